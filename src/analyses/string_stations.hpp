// The stations at which the analyses report results along the string: every FE node of every
// body, a joint (end node of body i = start node of body i + 1) reported once, and the
// kinematics of a node relative to its undeformed placement in the string frame.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "model/system_model.hpp"

namespace drillflex::analyses {

struct Station {
  double s = 0.0;  // distance from the bit end along the undeformed string, m
  int body = 0;    // the body and node the station reads (at a joint: the upper body's node 0)
  int node = 0;
  int lower_body = -1;  // at a joint: the body below (its last node coincides); −1 elsewhere
};

// Ordered from the bit (s = 0) to the top; bodies must be listed from the bit upward.
std::vector<Station> StringStations(const model::SystemModel& model);

// Node displacement and rotation relative to the undeformed placement, both in the string frame
// at the node (the body's reference orientation): u = A_refᵀ (r_k − r_k,ref),
// θ = Log(A_refᵀ A A_k,elastic) with A_k,elastic = Exp(Ψ_k η) (small elastic rotation).
struct NodeMotion {
  Vec3 position = Vec3::Zero();      // global, m
  Vec3 displacement = Vec3::Zero();  // string frame, m
  Vec3 rotation = Vec3::Zero();      // string frame, rad (rotation vector)
};
NodeMotion ComputeNodeMotion(const model::Body& body, const model::BodyPose& pose, int node);

// A velocity-level vector v (a mode shape or an increment δv) mapped to node k: translation
// ṙ + A(ω × u_k + Φ_k η̇) and rotation ω + Ψ_k η̇, both rotated into the string frame
// (A_refᵀ A · and A_refᵀ A · respectively). method.md §4.
struct NodeVelocity {
  Vec3 translation = Vec3::Zero();  // string frame
  Vec3 rotation = Vec3::Zero();     // string frame
};
NodeVelocity MapToNode(const model::Body& body, const model::BodyPose& pose, const VecX& v, int node);

}  // namespace drillflex::analyses
