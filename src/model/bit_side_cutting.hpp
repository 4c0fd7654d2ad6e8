// The rock's lateral reaction on the bit (a transient's `bit_rock.side_cutting`,
// model/bit_rock.hpp): the bit cuts the side of its hole as it is pushed sideways, at a lateral
// depth per revolution proportional to the side force, which replaces the rigid hold of the bit at
// the hole centre (builder.hpp DefaultWellSupports) when the case asks for it.
//
// The law (the lateral part of the bit/rock interface laws of Perneder, Detournay & Downton,
// Int. J. Rock Mech. Min. Sci. 51, 2012, and of Ho's anisotropic rock–bit model, SPE 16658, 1987):
// the lateral penetration per revolution d_n = 2π V_n/Ω, V_n the bit's velocity across the hole
// axis, is proportional to the lateral force,
//   F_n = k_s d_n,
// k_s (N/m) the bit's lateral cutting resistance: the side force that cuts 1 m sideways per
// revolution. Against Detournay's axial cutting WOB = ζ ε a d it is k_s = η ζ ε a, η the bit's
// lateral steering resistance of Perneder et al. (the inverse of Ho's bit anisotropy index
// I_b = (d_n/d)/(F_n/W)); a bit that side-cuts poorly (η ≫ 1) holds the hole centre almost as the
// rigid hold does. Regularized as the axial law (model/bit_rock.hpp): Ω → Ω_r = sqrt(Ω² + Ω_ε²),
// so a bit that does not turn resists lateral motion as a stiff viscous law. On the bit node, with
// P = I − t tᵀ (t the string axis at the bit in its reference placement) and Ω = −t·ω_bit:
//   F = −(2π k_s/Ω_r) P ṙ_bit,
//   ∂F/∂ṙ = −(2π k_s/Ω_r) P,   ∂F/∂ω = −(2π k_s Ω/Ω_r³) (P ṙ_bit) tᵀ   (∂Ω/∂ω = −tᵀ).
// Dissipative: no potential energy.
#pragma once

#include <string>

#include "model/force_element.hpp"

namespace drillflex::model {

struct BitSideCuttingParameters {
  double resistance = 0.0;   // k_s, N/m (> 0)
  double stick_speed = 0.0;  // Ω_ε, rad/s (> 0): the bit-rock section's
};

class BitSideCuttingElement : public ForceElement {
 public:
  // On node 0 of the bit body (the string's first); t its reference axis.
  BitSideCuttingElement(const Body* bit, const BitSideCuttingParameters& parameters);
  std::string Describe() const override;
  const BitSideCuttingParameters& parameters() const { return parameters_; }

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState&) const override { return 0.0; }

 private:
  BitSideCuttingParameters parameters_;
  Vec3 axis_;
};

// Checks the parameters (throws LogicError naming the first out of range).
void CheckBitSideCuttingParameters(const BitSideCuttingParameters& parameters);

}  // namespace drillflex::model
