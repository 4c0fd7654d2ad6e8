#include "analyses/static_solve.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "analyses/dynamic_relaxation.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/static_minimum.hpp"
#include "core/error.hpp"
#include "core/profile.hpp"
#include "model/static_problem.hpp"

namespace drillflex::analyses {
namespace {

void Log(const StaticSettings& settings, const std::string& line) {
  if (settings.log) settings.log(line);
}

// Newton iterations per load step: the case's max_iterations, capped (a Newton step that has not
// converged in this many iterations is better cut than continued); in a hole at least
// kMaxIterationsInHole (contacts close one after another as the string settles).
constexpr int kMaxIterationsPerLoadStep = 50;
constexpr int kMaxIterationsInHole = 100;
// m: the Newton trust radius in a hole, the largest lateral move of a node in a step (a fraction of
// a typical clearance, so that contacts close gradually).
constexpr double kWallStepLimit = 0.01;
// Modified Newton from a neighbour (solvers::NewtonOptions::reuse_contraction): the factorization is
// kept while each step brings |R| to a quarter or less.
constexpr double kNeighbourContraction = 0.25;

StaticOutcome FromSolver(const solvers::NewtonResult& solved, const char* method) {
  StaticOutcome outcome;
  static_cast<solvers::StaticSolution&>(outcome) = solved;  // the solution; the solver's own account stays
  outcome.method = method;
  return outcome;
}

// Strategy 3: Newton with load stepping from the reference placement.
StaticOutcome SolveByLoadStepping(const model::BuiltModel& built, const StaticSettings& settings,
                                  const model::LoadParameters& parameters) {
  model::StaticModelProblem problem(built.system, parameters);
  solvers::NewtonOptions options = DefaultNewtonOptions();
  options.max_iterations = std::clamp(settings.max_iterations, 1, kMaxIterationsPerLoadStep);
  if (built.force_scale > 0.0) options.force_scale = built.force_scale;
  options.log = settings.log;
  if (!built.contacts.empty()) {
    options.max_increment = kWallStepLimit;
    options.max_iterations = std::max(options.max_iterations, kMaxIterationsInHole);
  }
  try {
    return FromSolver(solvers::SolveStatic(problem, built.system.ReferencePositions(), options), "newton");
  } catch (const SolverError& error) {  // the solver's own account of where and why it stopped
    StaticOutcome outcome;
    outcome.method = "newton";
    outcome.failure = error.what();
    return outcome;
  }
}

// Strategy 4: dynamic relaxation.
StaticOutcome SolveByRelaxation(const model::BuiltModel& built, const StaticSettings& settings,
                                const model::LoadParameters& parameters) {
  RelaxationOptions relaxation;
  relaxation.max_steps = 10 * std::max(settings.max_iterations, 1);
  StaticOutcome outcome;
  outcome.method = "dynamic-relaxation";
  try {
    const RelaxationResult relaxed = SolveByDynamicRelaxation(built.system, relaxation, parameters);
    outcome.converged = relaxed.converged;
    outcome.q = relaxed.q;
    outcome.iterations = relaxed.steps;
    outcome.load_steps = 1;
    outcome.residual_norm = relaxed.residual_norm;
  } catch (const SolverError& error) {
    outcome.failure = error.what();
  }
  return outcome;
}

// Strategy 2: the energy's minimum at rest, then the friction continued.
StaticOutcome SolveByEnergyMinimum(const model::ModelInput& input, const model::BuiltModel& built,
                                   const StaticSettings& settings, const model::LoadParameters& parameters) {
  const StaticMinimum minimum = SolveStaticMinimum(input, built, settings, parameters);
  StaticOutcome outcome;
  outcome.q = minimum.q;
  outcome.iterations = minimum.iterations;
  outcome.residual_norm = minimum.residual_norm;
  outcome.converged = minimum.converged;
  if (!minimum.converged) {
    outcome.failure = "the energy's minimum was not found: " + minimum.failure;
    return outcome;
  }
  outcome.stable = true;
  outcome.method = Slides(input, parameters) && !minimum.at_rest_only ? "energy-minimum+friction" : "energy-minimum";
  if (minimum.at_rest_only) {
    outcome.warnings.push_back("the equilibrium of the string at rest (no sliding friction): " + minimum.failure +
                               "; the transient analysis follows such a string in time");
  }
  return outcome;
}

bool InWell(const model::ModelInput& input) {
  return input.well && !input.well->hole.empty() && input.supports.empty();
}

}  // namespace

StaticOutcome SolveFromNeighbour(const model::BuiltModel& built, const StaticSettings& settings,
                                 const model::LoadParameters& parameters, const VecX& start, int max_iterations) {
  const profile::Scope scope("static: from a neighbour");
  model::StaticModelProblem problem(built.system, parameters);
  solvers::NewtonOptions options = DefaultNewtonOptions();
  if (built.force_scale > 0.0) options.force_scale = built.force_scale;
  options.load_stepping.enabled = false;
  options.max_iterations = max_iterations;
  options.max_increment = built.contacts.empty() ? 0.0 : kWallStepLimit;
  options.reuse_contraction = kNeighbourContraction;
  options.throw_on_failure = false;
  options.log = settings.log;
  StaticOutcome outcome;
  try {
    outcome = FromSolver(solvers::SolveStatic(problem, start, options), "continuation");
  } catch (const SolverError& error) {
    outcome.failure = error.what();
    return outcome;
  }
  if (!outcome.converged) {
    outcome.failure = fmt::format("Newton from the neighbouring equilibrium stopped after {} iterations at |R| = {:.4g} N",
                                  outcome.iterations, outcome.residual_norm);
  }
  return outcome;
}

StaticOutcome SolveOnSupports(const model::BuiltModel& built, const StaticSettings& settings,
                              const model::LoadParameters& parameters) {
  return settings.method == StaticMethod::DynamicRelaxation ? SolveByRelaxation(built, settings, parameters)
                                                            : SolveByLoadStepping(built, settings, parameters);
}

StaticOutcome SolveStaticEquilibrium(const model::ModelInput& input, const model::BuiltModel& built,
                                     const StaticSettings& settings, const model::LoadParameters& parameters,
                                     const VecX* start) {
  if (settings.method == StaticMethod::DynamicRelaxation) return SolveByRelaxation(built, settings, parameters);
  int spent = 0;
  std::string tried;
  if (start) {
    StaticOutcome neighbour = SolveFromNeighbour(built, settings, parameters, *start, kMaxIterationsPerLoadStep);
    if (neighbour.converged) return neighbour;
    Log(settings, "static: " + neighbour.failure);
    spent += neighbour.iterations;
    tried = neighbour.failure + "; ";
  }
  StaticOutcome outcome = InWell(input) ? SolveByEnergyMinimum(input, built, settings, parameters)
                                       : SolveByLoadStepping(built, settings, parameters);
  outcome.iterations += spent;
  if (!outcome.converged) outcome.failure = tried + outcome.failure;
  return outcome;
}

}  // namespace drillflex::analyses
