#include "analyses/coupling_regap.hpp"

#include <array>
#include <vector>

#include <Eigen/QR>
#include <fmt/format.h>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/spring_elements.hpp"

namespace drillflex::analyses {
namespace {

// What one end node of a body should do: a small translation and rotation in the body's frame, in
// the directions that are held (free directions are left to the fit).
struct EndTarget {
  Vec6 motion = Vec6::Zero();  // (δx, δθ), body frame
  Vec6 held = Vec6::Zero();    // 1 where the motion is prescribed
};

// The change of strain that makes a spring carry at stiffness k_to the force f it carries at k_from.
Vec6 StrainChange(const Vec6& force, const Vec6& k_from, const Vec6& k_to) {
  Vec6 change = Vec6::Zero();
  for (int d = 0; d < 6; ++d) {
    if (k_from[d] > 0.0 && k_to[d] > 0.0) change[d] = force[d] / k_to[d] - force[d] / k_from[d];
  }
  return change;
}

// A 6-vector (translation, rotation) from one frame to another: R·(t, θ).
Vec6 Rotate(const Mat3& rotation, const Vec6& v) {
  Vec6 out;
  out << rotation * v.head<3>(), rotation * v.tail<3>();
  return out;
}

// Moves the body's end nodes by their targets with the least strain energy: the frame motion
// (δr, δθ) and modal coordinates η with δr + δθ × ρ_k + Φ_k η = δx_k, δθ + Ψ_k η = δθ_k at the held
// components, solved for the least ½ Σ ω_j² η_j² (modal columns scaled by 1/ω_j) with the frame
// free (its columns scaled up): the static shape of the body under end loads, as in the resting
// start's BendAlongLine (resting_start.cpp). The motions are ~1e-5, so one linear pass is exact to
// round-off for the forces that matter.
void MoveEnds(const model::Body& body, const model::BodyPose& pose, const std::array<EndTarget, 2>& ends, VecX& q) {
  constexpr double kFrameWeight = 1e3;
  const int nf = body.flexible_count;
  const int last = body.node_count() - 1;
  const VecX compliance = body.reduced->modal_stiffness.diagonal().cwiseSqrt().cwiseInverse();
  MatX a = MatX::Zero(12, 6 + nf);
  VecX rhs = VecX::Zero(12);
  for (int end = 0; end < 2; ++end) {
    const int k = end == 0 ? 0 : last;
    MatX rows = MatX::Zero(6, 6 + nf);
    rows.block<3, 3>(0, 0) = kFrameWeight * Mat3::Identity();
    rows.block<3, 3>(0, 3) = -kFrameWeight * so3::Skew(pose.NodeOffset(body, k));
    rows.block(0, 6, 3, nf) = body.reduced->node_translation_modes[k] * compliance.asDiagonal();
    rows.block<3, 3>(3, 3) = kFrameWeight * Mat3::Identity();
    rows.block(3, 6, 3, nf) = body.reduced->node_rotation_modes[k] * compliance.asDiagonal();
    a.middleRows(6 * end, 6) = ends[end].held.asDiagonal() * rows;
    rhs.segment<6>(6 * end) = ends[end].held.cwiseProduct(ends[end].motion);
  }
  if (rhs.isZero(0.0)) return;
  const VecX x = Eigen::CompleteOrthogonalDecomposition<MatX>(a).solve(rhs);
  q.segment<3>(body.q_offset) += pose.A * (kFrameWeight * x.head<3>());
  const Quat turned = so3::Compose(pose.rotation, kFrameWeight * x.segment<3>(3));
  q.segment<4>(body.q_offset + 3) << turned.w(), turned.x(), turned.y(), turned.z();
  q.segment(body.q_offset + 7, nf) += compliance.asDiagonal() * x.tail(nf);
}

}  // namespace

void CarryCouplingForces(const model::BuiltModel& from, const model::BuiltModel& to, VecX& q) {
  const model::SystemModel& system = from.system;
  const auto& bodies = system.bodies();
  const auto& elements = system.elements();
  if (to.system.elements().size() != elements.size() || to.system.bodies().size() != bodies.size() ||
      to.support_elements.size() != from.support_elements.size()) {
    throw LogicError("CarryCouplingForces: the two models do not have the same bodies and elements");
  }
  const auto poses = system.Poses(q);
  const VecX rest = VecX::Zero(system.num_velocities());
  std::vector<std::array<EndTarget, 2>> targets(bodies.size());
  // Each coupling's change δe (lower body's frame) is shared: the upper body's first node moves by
  // +δe/2, the lower body's last node by −δe/2 (e = x_upper − x_lower, model/coupling_kinematics.hpp).
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto* old_coupling = dynamic_cast<const model::CouplingElement*>(elements[i].get());
    if (old_coupling == nullptr) continue;
    const auto* new_coupling = dynamic_cast<const model::CouplingElement*>(to.system.elements()[i].get());
    if (new_coupling == nullptr) throw LogicError(fmt::format("CarryCouplingForces: element {} differs", i));
    const int lower = system.IndexOf(old_coupling->bodies()[0]);
    const int upper = system.IndexOf(old_coupling->bodies()[1]);
    const Vec6 force = old_coupling->Force(system.StateOf(*old_coupling, poses, rest, 0.0, 1.0));
    const Vec6 change = StrainChange(force, old_coupling->stiffness(), new_coupling->stiffness());
    EndTarget& below = targets[lower][1];
    EndTarget& above = targets[upper][0];
    below.motion -= 0.5 * change;
    below.held.setOnes();
    above.motion += Rotate(poses[upper].A.transpose() * poses[lower].A, 0.5 * change);
    above.held.setOnes();
  }
  // A support's strain is its node's motion against the ground frame (the string frame there):
  // e = −reaction/k; the node takes the whole change in the directions it holds.
  for (std::size_t i = 0; i < from.support_elements.size(); ++i) {
    const auto* old_support = dynamic_cast<const model::SupportElement*>(elements[from.support_elements[i]].get());
    const auto* new_support =
        dynamic_cast<const model::SupportElement*>(to.system.elements()[to.support_elements[i]].get());
    if (old_support == nullptr || new_support == nullptr) continue;
    const model::Body& body = *old_support->bodies()[0];
    const int end = old_support->node() == 0 ? 0 : old_support->node() == body.node_count() - 1 ? 1 : -1;
    if (end < 0) continue;  // a support inside a body: left to Newton
    const int index = system.IndexOf(&body);
    const Vec6 strain_force = -old_support->Reaction(system.StateOf(*old_support, poses, rest, 0.0, 1.0));
    const Vec6 change = StrainChange(strain_force, old_support->stiffness(), new_support->stiffness());
    const Mat3 ground = body.reference_orientation.toRotationMatrix();
    EndTarget& target = targets[index][end];
    target.motion += Rotate(poses[index].A.transpose() * ground, change);
    for (int d = 0; d < 6; ++d) {
      if (old_support->stiffness()[d] > 0.0) target.held[d] = 1.0;
    }
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) MoveEnds(bodies[b], poses[b], targets[b], q);
}

}  // namespace drillflex::analyses
