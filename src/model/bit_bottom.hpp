// The hole bottom as a unilateral axial contact of the bit node (a transient's
// `bit_rock.bottom`, model/bit_rock.hpp): a stiff penalty spring with a damper that pushes the bit
// up-hole only while the bit presses into the bottom, and lets go when it lifts off, so that the
// bit can bounce. The WOB is then what the contact carries, set by what holds the top (the hook
// support, the block's hook load or velocity), not an applied force.
//
// With t the string axis at the bit in its reference placement (up-hole; the hole axis at the bit
// MD) and p the bit node's reference place, the bit's axial place is x = t·(r_bit − p) and the
// bottom's x_b(t) = level + A(t) sin(2π f t), a harmonic motion of the bottom (a lobed formation
// under a turning bit: f = lobes × rpm / 60) whose amplitude A(t) = a · ½(1 − cos(π t/T_r)) rises
// smoothly over the ramp T_r (then a; T_r = 0: a from t = 0). The penetration δ = x_b − x and
//   N = k δ + c δ̇   while δ > 0 and N > 0, else 0        (δ̇ = ẋ_b − t·ṙ_bit)
// (a Kelvin–Voigt contact whose damper never pulls: Hunt & Crossley, J. Appl. Mech. 42, 1975,
// discuss the tension the plain damper would give at separation), the force N t on the bit node.
// Derivatives where active: ∂F/∂r = −k t tᵀ, ∂F/∂ṙ = −c t tᵀ; none where open. The potential
// ½ k ⟨δ⟩² is also given as a unilateral penalty for the energy minimum of a static solve.
#pragma once

#include <string>

#include "model/force_element.hpp"

namespace drillflex::model {

struct BitBottomParameters {
  // k, N/m; 0: the builder's default, as stiff as the model's supports (kSupportStiffnessFactor ×
  // c·EA/ℓ of the bit body's section: the bottom is the string's axial support at the bit).
  double stiffness = 0.0;
  double damping_ratio = 0.05;  // ζ: c = 2ζ sqrt(k m), m the mass of one FE element of the bit body
  // The bottom's place along t from the bit node's reference place, m (> 0: up-hole of it). A
  // transient that starts at rest on bottom sets it so that the contact carries the start's WOB
  // (analyses/transient_start_places.hpp).
  double level = 0.0;
  // The bottom's harmonic axial motion (none when the amplitude is 0).
  double amplitude = 0.0;  // a, m (up-hole first)
  double frequency = 0.0;  // f, Hz
  double ramp_time = 0.0;  // T_r, s
};

class BitBottomElement : public ForceElement {
 public:
  // `position`, `axis`: the bit node's reference place and t (global); k (N/m), c (N·s/m).
  BitBottomElement(const Body* bit, Index node, const Vec3& position, const Vec3& axis,
                   const BitBottomParameters& parameters, double stiffness, double damping);
  std::string Describe() const override;
  double stiffness() const { return stiffness_; }
  double damping() const { return damping_; }
  const BitBottomParameters& parameters() const { return parameters_; }
  // The bottom's place x_b(t) and its rate, m and m/s.
  double BottomPlace(double time) const;
  double BottomRate(double time) const;
  // The bit's penetration δ into the bottom (m, > 0 pressing) and the contact force N (N, ≥ 0).
  double Penetration(const ElementState& state) const;
  double ContactForce(const ElementState& state) const;

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState& state) const override;
  bool DoPenalty(const ElementState& state, double& value, double& stiffness, VecX& gradient) const override;

 private:
  Index node_;
  Vec3 position_, axis_;
  BitBottomParameters parameters_;
  double stiffness_, damping_;
};

// Checks the parameters (throws LogicError naming the first out of range); a stiffness of 0 is the
// builder's default.
void CheckBitBottomParameters(const BitBottomParameters& parameters);

}  // namespace drillflex::model
