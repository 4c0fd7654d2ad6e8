#include "analyses/static_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "analyses/coupling_regap.hpp"
#include "analyses/dynamic_relaxation.hpp"
#include "analyses/resting_start.hpp"
#include "analyses/static_minimum.hpp"
#include "analyses/wall_offsets.hpp"
#include "core/error.hpp"
#include "model/internal_forces.hpp"
#include "model/spring_elements.hpp"
#include "model/static_problem.hpp"
#include "model/wall_contact.hpp"

namespace drillflex::analyses {
namespace {

void Log(const StaticSettings& settings, const std::string& line) {
  if (settings.log) settings.log(line);
}

// Newton iterations per load step: the case's max_iterations, capped (a Newton step that has not
// converged in this many iterations is better cut than continued).
constexpr int kMaxIterationsPerLoadStep = 50;

// Stresses at the outer fibre of a hollow round section (c = OD/2), the usual combined-stress
// check of drill-string design (e.g. API RP 7G §A.8; Timoshenko & Gere, Mechanics of Materials):
//   bending σ_b = M c / I, normal σ = |N|/A + σ_b (the worst fibre), torsional τ = T c / J,
//   von Mises σ_vm = sqrt(σ² + 3 τ²). Transverse shear stress is zero at the outer fibre.
void AddStresses(const model::Body& body, StaticNodeResult& node) {
  const fe::HollowSection& section = body.reduced->spec.section;
  const double c = 0.5 * section.outer_diameter;
  node.bending_stress = node.bending_moment * c / section.second_moment();
  const double normal = std::abs(node.axial_force) / section.area() + node.bending_stress;
  const double shear = std::abs(node.torque) * c / section.polar_moment();
  node.von_mises_stress = std::sqrt(normal * normal + 3.0 * shear * shear);
}

// The node of the support's body at which the support acts: the node whose mode rows map the
// support's reaction (R_t, R_r) to the modal part of its generalized force,
// g_η = −(Φ_kᵀ Aᵀ A_g R_t + Ψ_kᵀ R_r) (model/coupling_kinematics.hpp with the ground as side 1,
// A_g the body's reference frame). Evaluated at a state with a small modal perturbation so that
// the reaction is not zero.
int SupportNode(const model::SystemModel& model, const model::SupportElement& support, const VecX& q) {
  const model::Body& body = *support.bodies()[0];
  VecX dv = VecX::Zero(model.num_velocities());
  for (int j = 0; j < body.flexible_count; ++j) dv[body.v_offset + 6 + j] = 1e-4 * (1.0 + 0.37 * j);
  const VecX perturbed = model.Increment(q, dv);
  const auto poses = model.Poses(perturbed);
  const VecX v = VecX::Zero(model.num_velocities());
  const model::ElementState state = model.StateOf(support, poses, v, 0.0, 1.0);
  model::ElementContribution contribution;
  contribution.force = VecX::Zero(support.local_size());
  support.Evaluate(state, false, contribution);
  const Vec6 reaction = support.Reaction(state);
  const model::BodyPose& pose = *state.poses[0];
  const Mat3 ground = body.reference_orientation.toRotationMatrix();
  const VecX modal_force = contribution.force.tail(body.flexible_count);
  int best = 0;
  double best_error = std::numeric_limits<double>::infinity();
  for (int k = 0; k < body.node_count(); ++k) {
    const VecX predicted = -(body.reduced->node_translation_modes[k].transpose() * (pose.A.transpose() * ground *
                                                                                    reaction.head<3>()) +
                             body.reduced->node_rotation_modes[k].transpose() * reaction.tail<3>());
    const double error = (predicted - modal_force).norm();
    if (error < best_error) {
      best_error = error;
      best = k;
    }
  }
  return best;
}

}  // namespace

solvers::NewtonOptions DefaultNewtonOptions() {
  solvers::NewtonOptions options;
  options.increment_tolerance = 1e-10;
  options.line_search.enabled = false;
  return options;
}

std::vector<StaticNodeResult> StaticNodeResults(const model::SystemModel& model, const VecX& q, double load_factor) {
  std::vector<int> all(StringStations(model).size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return StaticNodeResults(model, q, load_factor, all);
}

std::vector<StaticNodeResult> StaticNodeResults(const model::SystemModel& model, const VecX& q, double load_factor,
                                                std::span<const int> station_indices) {
  const std::vector<Station> stations = StringStations(model);
  // Only the bodies and joints the listed stations read.
  std::vector<int> bodies, joints;
  for (const int i : station_indices) {
    const Station& station = stations.at(static_cast<std::size_t>(i));
    if (station.lower_body >= 0) {
      joints.push_back(station.lower_body);
    } else {
      bodies.push_back(station.body);
    }
  }
  const auto poses = model.Poses(q);
  const auto forces = model::ComputeInternalForces(model, q, load_factor, bodies);
  const auto joint_forces = model::JointInternalForces(model, q, VecX::Zero(model.num_velocities()), joints);
  std::vector<StaticNodeResult> nodes;
  nodes.reserve(station_indices.size());
  for (const int i : station_indices) {
    const Station& station = stations[i];
    const model::Body& body = model.bodies()[station.body];
    const NodeMotion motion = ComputeNodeMotion(body, poses[station.body], station.node);
    StaticNodeResult node;
    node.s = station.s;
    node.position = motion.position;
    node.displacement = motion.displacement;
    node.rotation = motion.rotation;
    node.lateral_offset = motion.displacement.tail<2>().norm();
    // Internal forces rotated from the body frame (at a joint: the lower body's) to the string frame.
    const Mat3 frame = body.reference_orientation.toRotationMatrix();
    const bool joint = station.lower_body >= 0;
    const model::SectionForces& section = joint ? joint_forces[station.lower_body] : forces[station.body][station.node];
    const Mat3 to_string = frame.transpose() * poses[joint ? station.lower_body : station.body].A;
    node.force = to_string * section.force;
    node.moment = to_string * section.moment;
    node.axial_force = node.force.x();
    node.torque = node.moment.x();
    node.shear_force = node.force.tail<2>().norm();
    node.bending_moment = node.moment.tail<2>().norm();
    AddStresses(body, node);
    nodes.push_back(node);
  }
  return nodes;
}

std::vector<SupportReaction> SupportReactions(const model::BuiltModel& built, const VecX& q) {
  const model::SystemModel& model = built.system;
  const auto poses = model.Poses(q);
  const VecX v = VecX::Zero(model.num_velocities());
  std::vector<SupportReaction> reactions;
  for (int index : built.support_elements) {
    const auto* support = dynamic_cast<const model::SupportElement*>(model.elements().at(index).get());
    if (support == nullptr) throw LogicError(fmt::format("SupportReactions: element {} is not a support", index));
    const Vec6 reaction = support->Reaction(model.StateOf(*support, poses, v, 0.0, 1.0));
    const model::Body& body = *support->bodies()[0];
    SupportReaction result;
    result.s = body.s_start + body.reduced->node_positions[SupportNode(model, *support, q)].x();
    result.force = reaction.head<3>();
    result.moment = reaction.tail<3>();
    reactions.push_back(result);
  }
  return reactions;
}

namespace {
constexpr double kWallStepLimit = 0.01;  // m: Newton trust radius in a hole (the largest node translation)
constexpr int kMaxIterationsInHole = 100;
// With the mass shift: contacts that open and close as the string settles make |R| zigzag down
// slowly (3 km of string: 1.7e6 N to 450 N in 100 iterations at c = 31.6).
constexpr int kMaxIterationsShifted = 300;
// The mass shift's end game (solvers::NewtonOptions::end_game_residual): plain Newton once |R| is
// within this fraction of the force scale.
constexpr double kEndGameFraction = 1e-2;
// The residual tolerance (relative to the force scale) of a coupling stage before the last: its
// equilibrium only starts the next stage, whose couplings change every force by c₂/c₁ anyway. On
// the 3 km bench string the rotating stages cycled for hundreds of iterations between 10 and 2000 N
// under the strict 1e-8, where 1e-4 (90 N on 9e5 N) ends them.
constexpr double kIntermediateStageTolerance = 1e-4;
}  // namespace

namespace {

// The equilibrium alone (no results along the string): see RunStatic.
// `mass_shift`: in a hole, a step longer than the trust radius is solved again with the mass shift
// (solvers::NewtonOptions::mass_shift) instead of cut, with kMaxIterationsShifted iterations.
// `relative_tolerance` > 0 replaces the Newton options' residual tolerance.
StaticResult SolveEquilibrium(const model::BuiltModel& built, const StaticSettings& settings, const VecX* start,
                              int iteration_budget = 0, bool mass_shift = false, double relative_tolerance = 0.0) {
  StaticResult result;
  if (settings.method == StaticMethod::DynamicRelaxation) {
    RelaxationOptions relaxation;
    relaxation.max_steps = 10 * std::max(settings.max_iterations, 1);
    const RelaxationResult relaxed = SolveByDynamicRelaxation(built.system, relaxation);
    result.converged = relaxed.converged;
    result.q = relaxed.q;
    result.iterations = relaxed.steps;
    result.load_steps = 1;
    result.residual_norm = relaxed.residual_norm;
    result.method = "dynamic-relaxation";
    return result;
  }
  model::StaticModelProblem problem(built.system);
  solvers::NewtonOptions options = DefaultNewtonOptions();
  options.max_iterations = std::clamp(settings.max_iterations, 1, kMaxIterationsPerLoadStep);
  if (built.force_scale > 0.0) options.force_scale = built.force_scale;
  options.max_total_iterations = iteration_budget;
  if (relative_tolerance > 0.0) options.residual_tolerance = relative_tolerance;
  options.log = settings.log;
  if (start) options.load_stepping.enabled = false;  // already near the equilibrium at full load
  // In a hole, let contacts close gradually: no node moves more than kWallStepLimit across the hole
  // in a step: a longer step is cut to it, or solved again with the mass shift, which damps the
  // directions the string barely resists instead of shortening the whole step.
  if (!built.contact_elements.empty()) {
    options.max_increment = kWallStepLimit;
    options.mass_shift = mass_shift;
    // Plain Newton tried once the shifted steps are within 1 % of the loads (solvers/newton.hpp):
    // on the 3 km bench string it converges in 2–6 steps where the shift cycled for hundreds.
    if (mass_shift) options.end_game_residual = kEndGameFraction * built.force_scale;
    options.max_iterations = std::max(options.max_iterations, mass_shift ? kMaxIterationsShifted : kMaxIterationsInHole);
  }
  // One solve at full load: the budget is its iteration limit.
  if (start && iteration_budget > 0) options.max_iterations = std::min(options.max_iterations, iteration_budget);
  const solvers::StaticResult solved =
      solvers::SolveStatic(problem, start ? *start : built.system.ReferencePositions(), options);
  result.converged = solved.converged;
  result.q = solved.q;
  result.iterations = solved.iterations;
  result.load_steps = solved.load_steps;
  result.residual_norm = solved.residual_norm;
  return result;
}

// The residual (a fraction of the model's force scale, its loads) above which a converged equilibrium
// is reported with a warning, and above which it is no equilibrium at all. A solver also stops where
// the state no longer changes (steps below the increment tolerance, 1e-10 m, or the residual's
// round-off floor): with couplings so stiff that such a step still moves more force than the loads
// (bodies of millimetres, or a modulus typed 1e9 times too large: c·EA/ℓ ~ 1e16 N/m), that state is
// not an equilibrium of the loads, and its reactions and stresses would be noise.
constexpr double kLooselyResolvedFraction = 1e-3;
constexpr double kUnresolvedFraction = 1e-2;

// Fills in the results along the string, the reactions, the contacts and the bit.
StaticResult WithResults(const model::BuiltModel& built, StaticResult result) {
  CheckForcesResolved(built, result);
  result.nodes = StaticNodeResults(built.system, result.q, 1.0);
  AddWallOffsets(built, result.q, result.nodes);
  result.reactions = SupportReactions(built, result.q);
  result.contacts = ContactReports(built, result.q);
  result.bit = ComputeBitReport(built, result);
  return result;
}

}  // namespace

void CheckForcesResolved(const model::BuiltModel& built, StaticResult& result) {
  const double scale = built.system.force_scale();
  if (!result.converged || !(scale > 0.0)) return;
  const double fraction = result.residual_norm / scale;
  if (fraction <= kLooselyResolvedFraction) return;
  if (fraction <= kUnresolvedFraction) {
    result.warnings.push_back(fmt::format("the equilibrium balances the loads to {:.2g} % (|R| = {:.4g} N of {:.4g} N): "
                                          "its reactions and forces are good to about that",
                                          100.0 * fraction, result.residual_norm, scale));
    return;
  }
  const auto& bodies = built.system.bodies();
  const model::Body& stiffest = *std::max_element(bodies.begin(), bodies.end(), [](const auto& a, const auto& b) {
    return a.axial_rigidity / a.length() < b.axial_rigidity / b.length();
  });
  throw SolverError(fmt::format(
      "the equilibrium's forces are not resolved: the solver stopped where the state no longer changes with "
      "|R| = {:.4g} N unbalanced, {:.3g} times the model's loads ({:.4g} N); its stiffest couplings are beyond "
      "double precision (the stiffest body, EA/l = {:.3g} N/m: {:.4g} m long at {:.6g} m from the bit, E = {:.4g} Pa): "
      "a component too short, or a modulus too large",
      result.residual_norm, fraction, scale, stiffest.axial_rigidity / stiffest.length(), stiffest.length(),
      stiffest.s_start, stiffest.reduced->spec.material.youngs_modulus));
}

StaticResult RunStatic(const model::BuiltModel& built, const StaticSettings& settings, const VecX* start) {
  StaticResult result = WithResults(built, SolveEquilibrium(built, settings, start));
  if (result.method.empty()) result.method = "newton";
  return result;
}

std::vector<ContactReport> ContactReports(const model::BuiltModel& built, const VecX& q) {
  std::vector<ContactReport> reports;
  if (built.contact_elements.empty()) return reports;
  const auto poses = built.system.Poses(q);
  const VecX rest = VecX::Zero(built.system.num_velocities());
  for (const int index : built.contact_elements) {
    const auto& contact = static_cast<const model::WallContactElement&>(*built.system.elements()[index]);
    const model::WallContactResult state = contact.Result(built.system.StateOf(contact, poses, rest, 0.0, 1.0));
    if (!state.in_contact) continue;
    const model::Body& body = *contact.bodies()[0];
    reports.push_back({body.s_start + body.reduced->node_positions[contact.node()].x(), state.md, state.normal_force,
                       state.friction_force.norm(), state.high_side_angle, body.component, state.contact_point,
                       state.normal});
  }
  return reports;
}

std::optional<BitReport> ComputeBitReport(const model::BuiltModel& built, const StaticResult& result) {
  if (built.contact_elements.empty() || result.nodes.empty()) return std::nullopt;
  const SupportReaction* bit = nullptr;
  for (const auto& reaction : result.reactions) {
    if (std::abs(reaction.s) < 1e-9) bit = &reaction;
  }
  if (!bit) return std::nullopt;
  BitReport report;
  // The formation pushes the bit with the reaction; the bit pushes the formation the other way.
  // String frame: y right, z high side.
  report.walk_force = -bit->force.y();
  report.build_force = -bit->force.z();
  report.side_force = std::hypot(report.walk_force, report.build_force);
  // The bit axis down-hole, −x of the bit node rotated by θ (string frame): (−1, −θz, θy) to first
  // order, so its high-side component is θy; the exact angle from the rotated axis.
  const Vec3 rotation = result.nodes.front().rotation;
  const Vec3 axis = -(Eigen::AngleAxisd(rotation.norm(), rotation.norm() > 0 ? rotation.normalized() : Vec3::UnitX()) *
                      Vec3::UnitX());
  report.tilt = std::atan2(axis.z(), -axis.x());
  return report;
}

namespace {

// The coupling factor of the first solve from the resting start: soft enough that the second-order
// error of a Newton step in the couplings (c·k·|δθ|² ℓ) stays small, stiff enough (10× the
// element) to hold the string together. Measured on the bundled example: from the resting start
// at c = 10 Newton converges in 8 iterations, at c = 1000 it does not converge in 100.
constexpr double kSoftCouplingFactor = 10.0;
// Half a decade: the step of the coupling factor when the couplings are stiffened gradually.
const double kHalfDecade = std::sqrt(10.0);

// From the string resting on the wall (analyses/resting_start.hpp): the equilibrium without the
// torque on bit, without rotating friction and with soft couplings (kSoftCouplingFactor); then,
// with all loads, the couplings stiffened to the case's factor: either in one solve or by half
// decades. Before each stage the couplings are closed to the gaps that carry their forces at the new
// stiffness (CarryCouplingForces), and before the first the string is twisted by the torque it
// carries (TwistUnderTorque, with the contact forces found). Which of the two converges was
// measured to depend on the case (the bundled example: in one solve without rotation, 0.16 s; by half decades when rotating at 120 rpm, 0.55 s;
// each fails on the other), so both are tried, the likelier first. Throws SolverError when
// neither converges.
// Newton iterations of a coupling stage with the trust radius before it is retried with the mass
// shift (the bundled example's stages take 6–10; V7's 10,000 ft rotating case 27 where it converges,
// 100 without converging where it does not), and of the whole solve from the resting start, failed
// attempts included, before the fallback takes over (V7's 10,000 ft rotating case: 662).
constexpr int kTrustStageIterations = 40;
constexpr int kRestingStartBudget = 1000;

StaticResult SolveFromRestingStart(const model::ModelInput& input, const model::BuiltModel& built,
                                   cms::ReductionCache& cache, const StaticSettings& settings) {
  model::ModelInput stage = input;
  stage.settings.coupling_factor = std::min(kSoftCouplingFactor, input.settings.coupling_factor);
  stage.operation.torque_on_bit = 0.0;
  stage.static_sliding.reset();
  const model::BuiltModel soft_model = model::BuildSystemModel(stage, cache);
  VecX q = RestingStart(input, soft_model);  // its couplings opened by the tension they carry
  Log(settings, fmt::format("static: from the string resting on the wall, couplings at c = {:g}, no torque",
                             stage.settings.coupling_factor));
  // The resting start is centimetres from the equilibrium where the soft-string estimate errs
  // (a compressed pipe above the collars, the free top of a long string): the mass shift.
  const StaticResult soft = SolveEquilibrium(soft_model, settings, &q, 0, true);
  q = soft.q;
  stage.operation = input.operation;
  stage.static_sliding = input.static_sliding;
  int iterations = soft.iterations, load_steps = soft.load_steps;
  const bool rotating = input.static_sliding.has_value();
  const std::vector<double> steps = rotating ? std::vector<double>{kHalfDecade, 0.0} : std::vector<double>{0.0, kHalfDecade};
  for (std::size_t attempt = 0; attempt < steps.size(); ++attempt) {
    VecX trial = q;
    try {
      StaticResult solved;
      // Each stage with the trust radius (kTrustStageIterations at most), and if that fails, again
      // with the mass shift (slower where the trust radius converges: the bundled example's stages
      // took 3 times the iterations), both within what is left of kRestingStartBudget.
      std::vector<std::unique_ptr<model::BuiltModel>> stages;  // alive while `previous` points to one
      const model::BuiltModel* previous = &soft_model;
      bool shift_first = false;
      auto solve = [&](const model::BuiltModel& model, double factor) {
        // A stage before the last only has to bring the next one near: a loose tolerance.
        const double tolerance = &model == &built ? 0.0 : kIntermediateStageTolerance;
        Log(settings, fmt::format("static: couplings at c = {:g}, all loads", factor));
        CarryCouplingForces(*previous, model, trial);
        // The soft stage had no torque: twist the string now, at the new stiffness.
        if (previous == &soft_model) TwistUnderTorque(input, soft_model, trial);
        previous = &model;
        const int left = kRestingStartBudget - iterations;
        if (left <= 0) {
          throw SolverError(fmt::format("the solve from the resting start spent its {} Newton iterations",
                                        kRestingStartBudget));
        }
        // Once a stage has needed the mass shift, the stiffer ones start with it (the 3 km bench
        // string: each of four trust-radius attempts spent its 40 iterations before the shift
        // converged in 4–6).
        bool shifted = false;
        if (!shift_first) {
          try {
            solved = SolveEquilibrium(model, settings, &trial, std::min(kTrustStageIterations, left), false, tolerance);
          } catch (const SolverError& error) {
            iterations += std::min(kTrustStageIterations, left);  // spent by the failed solve
            Log(settings, fmt::format("static: {}; again with the mass shift", error.what()));
            shifted = true;
          }
        }
        if (shift_first || shifted) {
          const int rest = kRestingStartBudget - iterations;
          if (rest <= 0) {
            throw SolverError(fmt::format("the solve from the resting start spent its {} Newton iterations",
                                          kRestingStartBudget));
          }
          solved = SolveEquilibrium(model, settings, &trial, rest, true, tolerance);
          shift_first = true;
        }
        trial = solved.q;
        iterations += solved.iterations;
        load_steps += solved.load_steps;
      };
      if (steps[attempt] > 0.0) {
        for (double factor = stage.settings.coupling_factor * steps[attempt]; factor < input.settings.coupling_factor;
             factor *= steps[attempt]) {
          model::ModelInput stiffer = stage;
          stiffer.settings.coupling_factor = factor;
          stages.push_back(std::make_unique<model::BuiltModel>(model::BuildSystemModel(stiffer, cache)));
          solve(*stages.back(), factor);
        }
      }
      solve(built, input.settings.coupling_factor);
      solved.iterations = iterations;
      solved.load_steps = load_steps;
      return solved;
    } catch (const SolverError& error) {
      Log(settings, fmt::format("static: {}", error.what()));
      if (attempt + 1 == steps.size()) throw;
    }
  }
  throw LogicError("SolveFromRestingStart: no attempt made");
}

// The older path, kept as the fallback: from the centreline with the top also held laterally at
// the hole centre, then the hold softened by decades until it carries nothing, each equilibrium
// the start of the next (a homotopy: every step a small change for Newton while contacts close as
// the top settles onto the wall); a step that fails is halved.
// The Newton iterations the fallback may spend in all, its stages together (its load stepping from
// the centreline took 6874 on the bundled example before the resting start; at ~5–15 ms an
// iteration on a 1000–3000-coordinate model, 2000 iterations are 10–30 s: a case that fails stops
// with its message well inside the robustness run's 120 s guard, where 4000 a stage ran into it).
constexpr int kFallbackBudget = 2000;

StaticResult SolveByReleasingTheTop(const model::ModelInput& input, const model::BuiltModel& built,
                                    cms::ReductionCache& cache, const StaticSettings& settings) {
  model::ModelInput held = input;
  held.supports = model::DefaultWellSupports(built.system.length());
  model::Support lateral;
  lateral.at = built.system.length();
  lateral.fixed[model::kY] = lateral.fixed[model::kZ] = true;
  held.supports.push_back(lateral);
  Log(settings, "static: fallback from the centreline, the top held at the hole centre");
  StaticResult stage = SolveEquilibrium(model::BuildSystemModel(held, cache), settings, nullptr, kFallbackBudget);
  int iterations = stage.iterations;
  auto spent = [&](double decade) {
    return SolverError(fmt::format("releasing the top of the string onto the wall took more than {} Newton "
                                   "iterations (stopped at a lateral hold of 1e-{:.3g} of a support's stiffness)",
                                   kFallbackBudget, decade));
  };
  constexpr double kLastDecade = 16.0, kSmallestStep = 1.0 / 64.0;
  double decade = 0.0, step = 1.0;
  while (decade < kLastDecade) {
    const double next = std::min(decade + step, kLastDecade);
    held.supports.back().stiffness_scale = std::pow(10.0, -next);
    const int left = kFallbackBudget - iterations;
    if (left <= 0) throw spent(decade);
    try {
      stage = SolveEquilibrium(model::BuildSystemModel(held, cache), settings, &stage.q, left);
      iterations += stage.iterations;
      decade = next;
      step = std::min(2.0 * step, 1.0);
    } catch (const SolverError& error) {
      // A failed solve spent at most its iteration limit (SolveEquilibrium; a pessimistic count).
      iterations += std::min(left, std::max(settings.max_iterations, kMaxIterationsInHole));
      if (iterations >= kFallbackBudget) throw spent(decade);
      step *= 0.5;
      if (step < kSmallestStep) {
        throw SolverError(fmt::format("releasing the top of the string onto the wall stopped at a lateral "
                                      "hold of 1e-{:.3g} of a support's stiffness: {}", decade, error.what()));
      }
    }
  }
  StaticResult last = SolveEquilibrium(built, settings, &stage.q);
  last.iterations += iterations;
  return last;
}

}  // namespace

StaticResult RunStaticInWell(const model::ModelInput& input, const model::BuiltModel& built,
                             cms::ReductionCache& cache, const StaticSettings& settings) {
  const bool case_supports = !input.supports.empty() && !settings.energy_minimum_on_case_supports;
  if (case_supports || !input.trajectory || settings.method == StaticMethod::DynamicRelaxation) {
    return RunStatic(built, settings);
  }
  const StaticMinimum minimum = SolveStaticMinimum(input, built, settings);
  if (minimum.converged) {
    StaticResult result;
    result.q = minimum.q;
    result.iterations = minimum.iterations;
    result.residual_norm = minimum.residual_norm;
    result.converged = true;
    result.stable = true;
    result.method = input.static_sliding && !minimum.at_rest_only ? "energy-minimum+friction" : "energy-minimum";
    if (minimum.at_rest_only) {
      result.warnings.push_back("the equilibrium of the string at rest (no rotating friction): " + minimum.failure +
                                "; the transient analysis follows such a string in time");
    }
    return WithResults(built, result);
  }
  Log(settings, fmt::format("static: the energy's minimum was not found ({}); the older paths follow", minimum.failure));
  try {
    StaticResult result = WithResults(built, SolveFromRestingStart(input, built, cache, settings));
    result.method = "coupling-stages";
    result.warnings.push_back("found by the fallback path (coupling stages from the resting start) after the energy "
                              "minimization stopped: " + minimum.failure + "; its stability is not checked");
    return result;
  } catch (const SolverError& error) {
    Log(settings, fmt::format("static: the solve from the resting start failed: {}", error.what()));
    // A start the soft-string estimate got wrong (e.g. a string buckled in a vertical hole):
    // the slower path below does not depend on it.
  }
  StaticResult result = WithResults(built, SolveByReleasingTheTop(input, built, cache, settings));
  result.method = "centreline-release";
  result.warnings.push_back("found by the fallback path (from the centreline, the top released onto the wall) after "
                            "the energy minimization stopped: " + minimum.failure + "; its stability is not checked");
  return result;
}

}  // namespace drillflex::analyses
