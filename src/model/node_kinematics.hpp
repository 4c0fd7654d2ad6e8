// A node's kinematics from the state, in one place (method.md §4): where node k of a body is, how it
// is turned, how fast it moves and turns (and how fast that changes), in the frame each caller
// reads: global for the force elements, the body frame for the inertia and the fluid, the string
// frame (the body's reference orientation) for the analyses' results. The pose's own queries
// (BodyPose::NodeOffset u_k = ρ_k + Φ_k η, NodePosition r + A u_k, NodeRotation Ψ_k η) stay with
// the pose (model/body.hpp); everything built on them is here.
//
// With body velocities v_b = (ṙ global, ω body frame, η̇):
//   r_k = r + A u_k                                          (position, global)
//   ṙ_k = ṙ + A (ω × u_k + Φ_k η̇)       = L_k v_b,  L_k = [I, −A ũ_k, A Φ_k]     (global)
//   ω_k = A (ω + Ψ_k η̇)                                       (angular velocity, global)
//   t_k = Aᵀṙ + ω × u_k + Φ_k η̇          = J_k v_b,  J_k = [Aᵀ, −ũ_k, Φ_k]       (body frame)
//   ṫ_k = J_k a + ω × Φ_k η̇ − ω × Aᵀṙ                        (its rate, body frame)
#pragma once

#include "core/types.hpp"
#include "model/body.hpp"

namespace drillflex::model {

// r_k of the undeformed placement (η = 0, the reference pose), global, m.
Vec3 NodeReferencePosition(const Body& body, Index node);

// The motion of one node of a body at a state, global (the force elements': model/node_force.hpp).
struct NodeMotion {
  Vec3 offset = Vec3::Zero();             // u_k = ρ_k + Φ_k η (body frame), m
  Vec3 position = Vec3::Zero();           // r_k (global), m
  Vec3 velocity = Vec3::Zero();           // ṙ_k (global), m/s
  Vec3 angular_velocity = Vec3::Zero();   // ω_k = A (ω + Ψ_k η̇) (global), rad/s
  Vec3 body_rate = Vec3::Zero();          // ω (body frame): the frame's own rate, rad/s
  Vec3 relative_velocity = Vec3::Zero();  // ω × u_k + Φ_k η̇ (body frame), m/s
  Vec3 node_rate = Vec3::Zero();          // ω + Ψ_k η̇ (body frame), rad/s
};

// The motion of `node` from the body's pose and its velocity block (ṙ, ω, η̇) (size 6 + n_f).
NodeMotion ComputeNodeMotion(const Body& body, const BodyPose& pose, Index node,
                             const Eigen::Ref<const VecX>& body_velocity);

// A velocity-level vector at a node: its translation (m/s, or m per unit of a mode) and rotation
// (rad/s, or rad per unit), in the frame the function names.
struct NodeRates {
  Vec3 translation = Vec3::Zero();
  Vec3 rotation = Vec3::Zero();
};

// Body frame, from the body's velocity block (ṙ, ω, η̇): t_k = Aᵀṙ + ω × u_k + Φ_k η̇ and
// w_k = ω + Ψ_k η̇.
NodeRates ComputeBodyFrameNodeRates(const Body& body, const BodyPose& pose, Index node, const VecX& body_velocity);

// String frame (the body's reference orientation), from a vector v of the system's velocity
// coordinates (a mode shape or an increment δv): A_refᵀ (ṙ + A (ω × u_k + Φ_k η̇)) and
// A_refᵀ A (ω + Ψ_k η̇).
NodeRates ComputeStringFrameNodeRates(const Body& body, const BodyPose& pose, const VecX& v, Index node);

// A node relative to its undeformed placement, in the string frame at the node (the body's
// reference orientation): u = A_refᵀ (r_k − r_k,ref), θ = Log(A_refᵀ A A_k,elastic) with
// A_k,elastic = Exp(Ψ_k η) (small elastic rotation).
struct NodeDisplacement {
  Vec3 position = Vec3::Zero();      // global, m
  Vec3 displacement = Vec3::Zero();  // string frame, m
  Vec3 rotation = Vec3::Zero();      // string frame, rad (rotation vector)
};
NodeDisplacement ComputeNodeDisplacement(const Body& body, const BodyPose& pose, Index node);

// The frame's motion in its own axes at (q, v, a): p = Aᵀṙ (m/s), Aᵀr̈ (m/s²), ω (rad/s), ω̇ (rad/s²).
struct FrameMotion {
  Vec3 velocity;
  Vec3 acceleration;
  Vec3 omega, omega_rate;
};
FrameMotion ComputeFrameMotion(const BodyPose& pose, const VecX& body_velocity, const VecX& body_acceleration);

// Node k's motion in the body frame with its rate (the fluid's lumps: model/fluid_inertia.hpp).
struct BodyFrameNodeMotion {
  Vec3 offset;          // u_k, m
  Vec3 velocity;        // t_k, m/s
  Vec3 rate;            // ṫ_k, m/s²
  Vec3 modal_velocity;  // Φ_k η̇, m/s
};
BodyFrameNodeMotion ComputeBodyFrameNodeMotion(const Body& body, const BodyPose& pose, const FrameMotion& frame,
                                               const VecX& body_velocity, const VecX& body_acceleration, Index node);

// J_k = [Aᵀ, −ũ_k, Φ_k] (3 × (6 + n_f)): node k's body-frame velocity t_k = J_k v_b, u_k its `offset`.
// The fluid's lumps' (model/fluid_inertia.hpp) and the linear analyses' J_lat (model/lateral_fluid.hpp: its
// last two rows).
void NodeVelocityJacobian(const Body& body, const BodyPose& pose, Index node, const Vec3& offset,
                          Eigen::Matrix<double, 3, Eigen::Dynamic>& jacobian);

// L_k = [I, −A ũ_k, A Φ_k] (3 × (6 + n_f)): node k's global velocity ṙ_k = L_k v_b.
MatX NodeTranslationJacobian(const Body& body, const BodyPose& pose, Index node);

}  // namespace drillflex::model
