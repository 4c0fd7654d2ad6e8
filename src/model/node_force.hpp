// A force F and a moment M (global) acting at node k of a flexible body, mapped to the body's
// generalized force with its exact derivatives, for forces that themselves depend on the node's
// position, velocity and angular velocity (wall contact, fluid forces, ...).
//
// Node kinematics (model/node_kinematics.hpp, method.md §4), body velocities v_b = (ṙ global, ω body frame, η̇):
//   r_k = r + A u_k,  u_k = ρ_k + Φ_k η                     (node position, global)
//   ṙ_k = ṙ + A (ω × u_k + Φ_k η̇)      = L_k v_b,  L_k = [I, −A ũ_k, A Φ_k]
//   ω_k = A (ω + Ψ_k η̇)                = G_k v_b,  G_k = [0, A, A Ψ_k]   (global angular velocity,
//                                                    small elastic node rotations)
// Generalized force Q = L_kᵀ F + G_kᵀ M = [F; u_k × AᵀF + AᵀM; Φ_kᵀ AᵀF + Ψ_kᵀ AᵀM]
// (model/nodal_loads.hpp). The residual R = M a + f_int − f_ext receives −Q.
//
// When F, M depend on (r_k, ṙ_k, ω_k) the tangent is
//   −∂Q/∂q = −H(F, M) − L_kᵀ ∂F/∂q − G_kᵀ ∂M/∂q,
//   ∂F/∂q = F_r L_k + F_v ∂ṙ_k/∂q + F_w ∂ω_k/∂q   (and the same for M),
//   ∂ṙ_k/∂q = [0, −A skew(ω × u_k + Φ_k η̇), A ω̃ Φ_k],  ∂ω_k/∂q = [0, −A skew(ω + Ψ_k η̇), 0]
// (δA = A skew(δθ), δu_k = Φ_k δη), H(F, M) the derivative of L_kᵀ F + G_kᵀ M at fixed F, M; the
// damping is −∂Q/∂v = −L_kᵀ (F_v L_k + F_w G_k) − G_kᵀ (M_v L_k + M_w G_k).
//
// A force applied at a point off the node, r_k + ℓ (a contact point: ℓ = R_c n), is the special
// case M = ℓ × F, Q = L_ℓᵀ F with L_ℓ = L_k − ℓ̃ G_k (the velocity Jacobian of that point); then
//   −∂Q/∂q = −H(F, ℓ × F) − L_ℓᵀ ∂F/∂q + G_kᵀ F̃ (∂ℓ/∂r_k) L_k,   −∂Q/∂v = −L_ℓᵀ ∂F/∂v,
// which AddPointForce assembles at about half the cost of the general form.
#pragma once

#include "model/force_element.hpp"
#include "model/node_kinematics.hpp"

namespace drillflex::model {

// Derivatives of the global force and moment on the node with respect to the node's global
// position r_k, velocity ṙ_k and angular velocity ω_k (3 × 3 each).
struct NodeForceJacobian {
  Mat3 force_position = Mat3::Zero();
  Mat3 force_velocity = Mat3::Zero();
  Mat3 force_angular_velocity = Mat3::Zero();
  Mat3 moment_position = Mat3::Zero();
  Mat3 moment_velocity = Mat3::Zero();
  Mat3 moment_angular_velocity = Mat3::Zero();
};

// Adds −Q of (force, moment) at `node` to out.force, rows [offset, offset + 6 + n_f): the body's
// block in the element's local vector. With `with_matrices`, also adds the tangent and damping
// above to out.stiffness and out.damping (which must be sized and zeroed by the caller, as
// ForceElement::Evaluate does); `jacobian` = nullptr means F and M do not depend on the node's
// motion (dead loads: only the geometric part H(F, M) remains).
void AddNodeForce(const Body& body, const BodyPose& pose, Index node, const NodeMotion& motion, const Vec3& force,
                  const Vec3& moment, const NodeForceJacobian* jacobian, bool with_matrices,
                  ElementContribution& out, Index offset = 0);

// Derivatives of the global force at the point r_k + ℓ, and of the lever ℓ (global), with
// respect to the node's position, velocity and angular velocity (the lever depends on r_k only).
struct PointForceJacobian {
  Mat3 force_position = Mat3::Zero();
  Mat3 force_velocity = Mat3::Zero();
  Mat3 force_angular_velocity = Mat3::Zero();
  Mat3 lever_position = Mat3::Zero();  // ∂ℓ/∂r_k
};

// AddNodeForce for the force `force` applied at r_k + `lever` (moment lever × force about the
// node), with the same conventions; `jacobian` = nullptr: force and lever do not depend on the
// motion.
void AddPointForce(const Body& body, const BodyPose& pose, Index node, const NodeMotion& motion, const Vec3& force,
                   const Vec3& lever, const PointForceJacobian* jacobian, bool with_matrices,
                   ElementContribution& out, Index offset = 0);

}  // namespace drillflex::model
