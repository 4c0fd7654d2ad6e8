#include "analyses/static_minimum.hpp"

#include <fmt/format.h>

#include "analyses/resting_start.hpp"
#include "analyses/static_analysis.hpp"
#include "core/profile.hpp"
#include "model/hole_friction.hpp"
#include "model/static_problem.hpp"
#include "solvers/energy_trust_region.hpp"

namespace drillflex::analyses {
namespace {

// The trust-region iterations of one solve (the bundled example takes ~30).
constexpr int kMaxTrustRegionIterations = 1000;
// The first trust radius, m (a mass-weighted RMS move of the string): a tenth of a typical
// clearance's few centimetres, over the part of the string that moves.
constexpr double kInitialRadius = 1e-3;
// The friction continuation of a rotating string: the largest lateral move of a node in a Newton
// step (m), the iterations of a step and of the whole continuation, its first and smallest step.
constexpr double kWallStepLimit = 0.01;
constexpr int kContinuationStepIterations = 30;
constexpr int kContinuationIterations = 600;
constexpr double kFirstFrictionStep = 0.25;
constexpr double kSmallestFrictionStep = 1e-3;

}  // namespace

model::ModelInput EffectiveInput(const model::ModelInput& input, const model::LoadParameters& parameters) {
  model::ModelInput effective = input;
  const double load = parameters.load_factor;
  effective.gravity *= load * parameters.weight_factor;
  effective.operation.weight_on_bit = load * parameters.weight_on_bit.value_or(input.operation.weight_on_bit);
  effective.operation.torque_on_bit = load * parameters.torque_on_bit.value_or(input.operation.torque_on_bit);
  if (parameters.OverridesFriction()) {
    // Every hole section its coefficients under the block, the case's own where it gives none.
    // (A well of its own: the input's is shared, read only.)
    std::vector<well::HoleSection> hole = input.well ? input.well->hole.sections() : std::vector<well::HoleSection>{};
    model::LoadParameters unscaled = parameters;
    unscaled.friction_factor = 1.0;
    for (Index i = 0; i < std::ssize(hole); ++i) {
      const model::WallFriction friction =
          model::EffectiveFriction(model::SectionFriction(hole[i], input.settings.contact), unscaled);
      hole[i].friction = friction.tangential;
      hole[i].axial_friction = friction.axial;
    }
    if (!hole.empty()) effective.well = model::MakeWellbore(input.well->trajectory, hole);
    if (hole.empty() && parameters.open_hole_friction) {
      effective.settings.contact.friction = parameters.open_hole_friction->tangential;
      effective.settings.contact.axial_friction = parameters.open_hole_friction->axial;
    }
  }
  if (parameters.sliding_mode == model::SlidingMode::kVelocities) effective.static_sliding.reset();
  if (parameters.sliding_mode == model::SlidingMode::kPrescribed) effective.static_sliding = parameters.sliding;
  return effective;
}

bool Slides(const model::ModelInput& input, const model::LoadParameters& parameters) {
  return parameters.sliding_mode == model::SlidingMode::kPrescribed ||
         (parameters.sliding_mode == model::SlidingMode::kAsBuilt && input.static_sliding.has_value());
}

StaticMinimum SolveStaticMinimum(const model::ModelInput& input, const model::BuiltModel& built,
                                 const StaticSettings& settings, const model::LoadParameters& parameters,
                                 const VecX* start) {
  // The string at rest: a moving one's friction is switched off (friction factor 0) until the
  // continuation below. The start knows the loads (the soft-string estimate of the string under the
  // block's weights, WOB and torque).
  model::ModelInput still = EffectiveInput(input, parameters);
  still.static_sliding.reset();
  VecX q;
  if (start) {
    q = *start;
  } else {
    q = RestingStart(still, built);
    TwistUnderTorque(still, built, q);
  }
  if (settings.log) {
    settings.log(fmt::format("static: the energy's minimum from {} (c = {:g}{})",
                             start ? "the given state" : "the string resting on the wall",
                             input.settings.coupling_factor,
                             parameters.load_factor == 1.0 ? std::string()
                                                           : fmt::format(", loads × {:g}", parameters.load_factor)));
  }
  model::StaticModelProblem problem(built.system, parameters, model::StaticModelProblem::Ramp::kFriction);
  problem.SetLoadFactor(0.0);
  const solvers::NewtonOptions newton = DefaultNewtonOptions();
  solvers::EnergyTrustRegionOptions options;
  options.residual_tolerance = newton.residual_tolerance;
  options.increment_tolerance = newton.increment_tolerance;
  options.force_scale = built.force_scale;
  options.max_iterations = kMaxTrustRegionIterations;
  options.initial_radius = kInitialRadius;
  options.log = settings.log;
  const solvers::EnergyTrustRegionResult solved = solvers::MinimizeEnergy(problem, q, options);
  StaticMinimum result;
  result.q = solved.q;
  result.converged = solved.converged;
  result.iterations = solved.iterations;
  result.factorizations = solved.factorizations;
  result.negative_curvature_steps = solved.negative_curvature_steps;
  result.residual_norm = solved.residual_norm;
  result.failure = solved.failure;
  if (settings.log) {
    settings.log(fmt::format("static: energy trust region {} after {} iterations ({} factorizations, {} steps along "
                             "negative curvature, {} second-order corrections), |R| {:.4g} N{}",
                             solved.converged ? "converged" : "stopped", solved.iterations, solved.factorizations,
                             solved.negative_curvature_steps, solved.second_order_corrections, solved.residual_norm,
                             solved.converged ? "" : ": " + solved.failure));
  }
  if (!result.converged || !Slides(input, parameters)) return result;
  const FrictionContinuation moving = ContinueInFriction(built, settings, parameters, result.q);
  result.iterations += moving.iterations;
  if (moving.converged) {
    result.q = moving.q;
    result.residual_norm = moving.residual_norm;
  } else {
    // The equilibrium at rest stands (result.q); the friction's own balance was not found.
    result.at_rest_only = true;
    result.failure = moving.failure;
  }
  return result;
}

FrictionContinuation ContinueInFriction(const model::BuiltModel& built, const StaticSettings& settings,
                                        const model::LoadParameters& parameters, const VecX& at_rest) {
  // The friction acts around (or along) the string and has no potential. From the equilibrium at
  // rest, a continuation in the friction factor 0 → 1 by Newton (static-solver.md §6), its steps
  // cut to kWallStepLimit across the hole.
  const profile::Scope scope("static: friction continuation");
  model::StaticModelProblem problem(built.system, parameters, model::StaticModelProblem::Ramp::kFriction);
  solvers::NewtonOptions continuation = DefaultNewtonOptions();
  continuation.force_scale = built.force_scale;
  continuation.max_increment = kWallStepLimit;
  continuation.max_iterations = kContinuationStepIterations;
  continuation.max_total_iterations = kContinuationIterations;
  continuation.load_stepping.initial_step = kFirstFrictionStep;
  continuation.load_stepping.min_step = kSmallestFrictionStep;
  continuation.throw_on_failure = false;
  continuation.log = settings.log;
  if (settings.log) settings.log("static: sliding, the friction from 0 to its value");
  const solvers::NewtonResult moving = solvers::SolveStatic(problem, at_rest, continuation);
  if (settings.log) {
    settings.log(fmt::format("static: friction continuation {} after {} Newton iterations in {} steps",
                             moving.converged ? "converged" : "stopped", moving.iterations, moving.load_steps));
  }
  FrictionContinuation result;
  result.converged = moving.converged;
  result.q = moving.q;
  result.iterations = moving.iterations;
  result.residual_norm = moving.residual_norm;
  if (!moving.converged) {
    result.failure = fmt::format("with the friction of the sliding string acting no static balance was found beyond "
                                 "{:.3g} of its value (|R| {:.4g} N): the contacts walk around the hole, as a string "
                                 "that whirls",
                                 moving.load_factor, moving.residual_norm);
  }
  return result;
}

}  // namespace drillflex::analyses
