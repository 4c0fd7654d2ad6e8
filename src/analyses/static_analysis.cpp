#include "analyses/static_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "analyses/mwd_sag.hpp"
#include "analyses/static_solve.hpp"
#include "analyses/wall_offsets.hpp"
#include "core/error.hpp"
#include "core/profile.hpp"
#include "model/internal_forces.hpp"
#include "model/node_kinematics.hpp"
#include "model/spring_elements.hpp"
#include "model/static_problem.hpp"
#include "model/string_above.hpp"
#include "model/wall_contact.hpp"

namespace drillflex::analyses {
namespace {


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
Index SupportNode(const model::SystemModel& model, const model::SupportElement& support, const VecX& q) {
  const model::Body& body = *support.bodies()[0];
  VecX dv = VecX::Zero(model.num_velocities());
  for (Index j = 0; j < body.flexible_count; ++j) dv[body.v_offset + 6 + j] = 1e-4 * (1.0 + 0.37 * j);
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
  Index best = 0;
  double best_error = std::numeric_limits<double>::infinity();
  for (Index k = 0; k < body.node_count(); ++k) {
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

std::vector<StaticNodeResult> StaticNodeResults(const model::BuiltModel& built, const VecX& q,
                                                const model::LoadParameters& load) {
  std::vector<Index> all(StringStations(built.system).size());
  for (Index i = 0; i < std::ssize(all); ++i) all[i] = i;
  return StaticNodeResults(built, q, load, all);
}

std::vector<StaticNodeResult> StaticNodeResults(const model::BuiltModel& built, const VecX& q,
                                                const model::LoadParameters& load, std::span<const Index> station_indices) {
  const model::SystemModel& model = built.system;
  const std::vector<Station> stations = StringStations(model);
  // Only the bodies and joints the listed stations read.
  std::vector<Index> bodies, joints;
  for (const Index i : station_indices) {
    const Station& station = stations.at(i);
    if (station.lower_body >= 0) {
      joints.push_back(station.lower_body);
    } else {
      bodies.push_back(station.body);
    }
  }
  const auto poses = model.Poses(q);
  const auto forces = model::ComputeInternalForces(built, q, load, bodies);
  const auto joint_forces = model::JointInternalForces(built, q, VecX::Zero(model.num_velocities()), joints);
  std::vector<StaticNodeResult> nodes;
  nodes.reserve(station_indices.size());
  for (const Index i : station_indices) {
    const Station& station = stations[i];
    const model::Body& body = model.bodies()[station.body];
    const model::NodeDisplacement motion = model::ComputeNodeDisplacement(body, poses[station.body], station.node);
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

std::vector<SupportReaction> SupportReactions(const model::BuiltModel& built, const VecX& q,
                                             const model::LoadParameters& parameters) {
  const model::SystemModel& model = built.system;
  const auto poses = model.Poses(q);
  const VecX v = VecX::Zero(model.num_velocities());
  std::vector<SupportReaction> reactions;
  for (const auto handle : built.supports) {
    const model::SupportElement& support = model.Get(handle);
    const Vec6 reaction = support.Reaction(model.StateOf(support, poses, v, 0.0, parameters));
    const model::Body& body = *support.bodies()[0];
    SupportReaction result;
    result.s = body.NodeS(SupportNode(model, support, q));
    result.force = reaction.head<3>();
    result.moment = reaction.tail<3>();
    reactions.push_back(result);
  }
  return reactions;
}

namespace {

// The residual (a fraction of the model's force scale, its loads) above which a converged equilibrium
// is reported with a warning, and above which it is no equilibrium at all. A solver also stops where
// the state no longer changes (steps below the increment tolerance, 1e-10 m, or the residual's
// round-off floor): with couplings so stiff that such a step still moves more force than the loads
// (bodies of millimetres, or a modulus typed 1e9 times too large: c·EA/ℓ ~ 1e16 N/m), that state is
// not an equilibrium of the loads, and its reactions and stresses would be noise.
constexpr double kLooselyResolvedFraction = 1e-3;
constexpr double kUnresolvedFraction = 1e-2;

}  // namespace

StaticResult WithResults(const model::BuiltModel& built, StaticResult result, const model::LoadParameters& parameters) {
  const profile::Scope scope("static: results along the string");
  CheckForcesResolved(built, result);
  result.nodes = StaticNodeResults(built, result.q, parameters);
  AddWallOffsets(built, result.q, result.nodes);
  result.reactions = SupportReactions(built, result.q, parameters);
  if (built.string_above) {
    const model::SystemModel& model = built.system;
    const model::StringAboveElement& above = model.Get(*built.string_above);
    const auto poses = model.Poses(result.q);
    const VecX v = VecX::Zero(model.num_velocities());
    const Vec6 reaction = above.Reaction(model.StateOf(above, poses, v, 0.0, parameters));
    PipeAboveReaction pipe;
    pipe.s = model.length();
    pipe.force = reaction.head<3>();
    pipe.moment = reaction.tail<3>();
    pipe.tension = above.Tension(parameters);
    pipe.buckled = !(above.BucklingMargin(parameters) > 0.0);
    result.pipe_above = pipe;
  }
  result.contacts = ContactReports(built, result.q, parameters);
  result.bit = ComputeBitReport(built, result);
  return result;
}

StaticResult ToStaticResult(const model::BuiltModel& built, const StaticOutcome& outcome,
                            const model::LoadParameters& parameters) {
  if (!outcome.converged) throw SolverError("static: " + outcome.failure);
  StaticResult result;
  static_cast<StaticOutcome&>(result) = outcome;
  return WithResults(built, std::move(result), parameters);
}

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

StaticResult RunStatic(const model::BuiltModel& built, const StaticSettings& settings) {
  return ToStaticResult(built, SolveOnSupports(built, settings), 1.0);
}

StaticResult RunStaticInWell(const model::ModelInput& input, const model::BuiltModel& built,
                             const StaticSettings& settings, const model::LoadParameters& parameters,
                             const VecX* start) {
  StaticResult result =
      ToStaticResult(built, SolveStaticEquilibrium(input, built, settings, parameters, start), parameters);
  if (input.well) {
    if (const auto sensor = MwdSensorAt(input.string, settings.mwd_at)) {
      result.mwd = ComputeMwdSag(result.nodes, input.well->trajectory, *sensor);
    }
  }
  return result;
}

std::vector<ContactReport> ContactReports(const model::BuiltModel& built, const VecX& q,
                                          const model::LoadParameters& parameters) {
  std::vector<ContactReport> reports;
  if (built.contacts.empty()) return reports;
  const auto poses = built.system.Poses(q);
  const VecX rest = VecX::Zero(built.system.num_velocities());
  for (const auto handle : built.contacts) {
    const model::WallContactElement& contact = built.Get(handle);
    const model::WallContactResult state = contact.Result(built.system.StateOf(contact, poses, rest, 0.0, parameters));
    if (!state.in_contact) continue;
    const model::Body& body = *contact.bodies()[0];
    reports.push_back({body.NodeS(contact.node()), state.md, state.normal_force,
                       state.friction_force.norm(), state.high_side_angle, body.component, state.contact_point,
                       state.normal});
  }
  return reports;
}

std::optional<BitReport> ComputeBitReport(const model::BuiltModel& built, const StaticResult& result) {
  if (built.contacts.empty() || result.nodes.empty()) return std::nullopt;
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
  report.tilt_right = std::atan2(axis.y(), -axis.x());
  return report;
}

}  // namespace drillflex::analyses
