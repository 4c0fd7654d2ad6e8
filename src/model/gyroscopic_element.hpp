// The gyroscopic moments of a body whose material spins steadily about its own axis while its
// frame does not: the stationary-frame ("non-rotating coordinates") description of a rotor with
// round sections used by rotordynamics (Lalanne & Ferraris, "Rotordynamics Prediction in
// Engineering", 2nd ed. 1998, ch. 1–2; Genta, "Dynamics of Rotating Systems", 2005, ch. 3–4).
//
// Node k carries the polar moment of inertia J_p,k = e_xᵀ J_k e_x of its lumped rotary inertia
// (cms/reduced_body.hpp). Its material spins at Ω about the node's axis pointing down-hole, −e_k,
// with e_k = e_x + θ_k × e_x the node's axis in the body frame to first order in its elastic
// rotation θ_k = Ψ_k η (e_x is the body's axis, up-hole; a positive Ω is clockwise looking down-hole,
// the drilling sense: model/drives.hpp). A round section's inertia does not change as it spins, so
// the spin adds one term to the angular momentum of the node, J_p Ω (−e_k), whose rate while the
// axis tilts at the node's angular velocity w_k = ω + Ψ_k η̇ (body frame) is J_p Ω (w_k × (−e_k)).
// The element adds that rate to the residual (as the inertia forces: R = M a + …):
//   m_k = J_p,k Ω (e_k × w_k),  mapped by [0; I; Ψ_kᵀ] onto (ω, η̇) of the body,
// linear in the velocities: ∂m_k/∂w_k = Ω J_p,k skew(e_k), i.e. the gyroscopic matrix ΩG of the
// linear analyses (M ẍ + (D + Ω G) ẋ + K x = 0), skew-symmetric, doing no work. Through e_k it also
// depends on η: δm_k = −J_p,k Ω skew(w_k) δe_k, δe_k = −skew(e_x) Ψ_k δη (the stiffness matrix;
// zero at rest). Translational inertia gives no gyroscopic term in these coordinates: the mass of a
// beam node lies on its axis, so spinning it moves nothing.
//
// This is not the floating frame's own velocity term Ω_k × J_k Ω_k (model/body_dynamics.hpp): that
// one belongs to frames that turn with the material (the body's ω); here the frames stay and only
// the material spins, which keeps a bent string's linearization time-invariant.
#pragma once

#include "core/types.hpp"
#include "model/force_element.hpp"
#include "model/system_model.hpp"

namespace drillflex::model {

class GyroscopicElement : public ForceElement {
 public:
  // `spin` Ω (rad/s, clockwise looking down-hole) of the material of `body`.
  GyroscopicElement(const Body* body, double spin);
  std::string Describe() const override;

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState&) const override { return 0.0; }

 private:
  double spin_;
};

// The gyroscopic matrix G of the whole model at q for a unit spin (1 rad/s, clockwise looking
// down-hole) of every body: the assembled ∂m/∂v of a GyroscopicElement on each body (N·m·s per rad/s
// of spin, per unit of each velocity coordinate); skew-symmetric, the pattern of the body blocks.
SparseMat ComputeGyroscopicMatrix(const SystemModel& model, const VecX& q);

}  // namespace drillflex::model
