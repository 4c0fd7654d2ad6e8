// An imbalance: a small mass m at an eccentricity e from the string axis, fixed to the string at
// node k (a bent or worn collar, an eccentric tool), given as the product m·e like the vibration
// analysis's `imbalance` excitation (case-format.md). In the limit of a mass small against the
// string's, its only effect is the d'Alembert force of its centripetal acceleration on the node:
//   F = −m e ω_k × (ω_k × ê),  ê = A ê₀,
// with ω_k the node's global angular velocity (model/node_force.hpp) and ê₀ the unit direction of
// the offset in the body frame (at the reference placement the body frame is the string frame: ê₀ =
// e_z, the high side). Spinning at Ω about the axis, F = m e Ω² ê: the rotating force of the
// vibration analysis, now turning with the string's actual rotation. Left out (stated, both small
// for m e ≪ the string's own m R): the tangential m e Ω̇ while the speed changes (the element sees
// no accelerations), the node's small elastic rotation in ê, and the mass m itself (inertia, weight).
//
// Exact tangent: with F_ω = ∂F/∂ω_k = −m e (ω êᵀ + (ω·ê) I − 2 ê ωᵀ) (ω × (ω × ê) = ω (ω·ê) − ê ω²)
// through node_force.hpp, plus the turn of ê with the body frame, δê = −A skew(ê₀) δθ:
//   δF = m e skew(ω_k)² A skew(ê₀) δθ, mapped by −L_kᵀ (L_k = [I, −A ũ_k, A Φ_k]).
// No potential (a velocity-dependent, non-conservative force).
#pragma once

#include "model/force_element.hpp"

namespace drillflex::model {

class ImbalanceElement : public ForceElement {
 public:
  // `imbalance` m·e (kg·m) at `node`, offset toward `direction` (body frame, ⟂ x; normalized here).
  ImbalanceElement(const Body* body, Index node, double imbalance, const Vec3& direction);
  std::string Describe() const override;
  // F above (global), N.
  Vec3 Force(const ElementState& state) const;

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState&) const override { return 0.0; }

 private:
  Index node_;
  double imbalance_;
  Vec3 direction_;
};

}  // namespace drillflex::model
