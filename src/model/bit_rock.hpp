// The rock's reaction on the bit in a transient (analyses.transient.bit_rock of the case): an axial
// force (WOB, pushing the bit up-hole) and a torque (TOB, against the bit's spin) on the bit node,
// functions of the bit's penetration rate V and spin rate Ω:
//   V = −t·ṙ_bit  (m/s, > 0 drilling ahead),  Ω = −t·ω_bit  (rad/s, > 0 clockwise looking down-hole),
// t the string axis at the bit in its reference placement (up-hole, the direction the case's WOB
// acts in; the bit drills along the hole, so t stays fixed).
//
// Two laws:
//  * Detournay (Detournay & Defourny, Int. J. Rock Mech. 29, 1992; Richard, Germay & Detournay,
//    J. Sound Vib. 305, 2007, eqs. 1–4): cutting plus frictional contact of the wear flats, with the
//    depth of cut per revolution d = 2πV/Ω,
//      WOB = ζ ε a d + W_f,   TOB = ½ ε a² d + ½ μ γ a W_f,
//    ε the intrinsic specific energy, ζ the ratio of the normal to the tangential cutting force, a the
//    bit radius, μ the friction coefficient and γ the bit's geometry factor of the contact, W_f the
//    contact force of the wear flats (their contact stress times their area, σ a ℓ). Regularized:
//      d = 2π max(V, 0)/sqrt(Ω² + Ω_ε²)   (finite at Ω = 0: a bit that does not turn does not cut
//                                          ahead, it resists penetration as a stiff viscous law),
//      W_f → W_f clamp(V/V_ε, 0, 1)        (the contact is mobilized while the bit presses ahead,
//                                          none once it lifts off: V ≤ 0 gives no force at all),
//      TOB → TOB clamp(Ω/Ω_ε, −1, 1)       (against the spin either way; viscous below Ω_ε, so the
//                                          bit can stick).
//  * Friction: a torque against the spin with a static T_s and a kinetic T_d level (T_s > T_d), the
//    classic torsional stick–slip law (Brett, SPE Drill. Eng. 7, 1992; the pendulum of validation.md
//    V8); no axial force (the case's WOB stays an applied load):
//      |Ω| ≤ Ω_ε:  TOB = T_s Ω/Ω_ε                                   (stick: a stiff viscous law)
//      |Ω| > Ω_ε:  TOB = sign(Ω) [T_d + (T_s − T_d) exp(−(|Ω| − Ω_ε)/Ω_d)]   (slip, the drop from the
//                                                                    static to the kinetic level
//                                                                    over the speed Ω_d)
// The force element has the exact derivatives of both (piecewise: at the kinks the one-sided ones).
//
// Beside the law, at the bit (each optional, none by default, so that a case without them is as
// before):
//  * the hole bottom as a unilateral axial contact (model/bit_bottom.hpp): the WOB is then what it
//    carries, not the case's applied WOB, and the bit can bounce. With the friction law (or no law:
//    the case's TOB stays applied) only; not with Detournay's, whose WOB already is the rock's axial
//    reaction as a law of the penetration rate: a bit pressing ahead cuts its way down, so a bottom
//    fixed in place under it would stop the drilling, and a bottom that moves down with the cut
//    needs the depth-of-cut history (the delay equation of Richard, Germay & Detournay 2007), which
//    is not modelled;
//  * side cutting (model/bit_side_cutting.hpp): the rock's lateral reaction, in place of the rigid
//    hold of the bit at the hole centre.
#pragma once

#include <optional>
#include <string>

#include "model/bit_bottom.hpp"
#include "model/bit_side_cutting.hpp"
#include "model/force_element.hpp"

namespace drillflex::model {

// None: no torque law (the case's TOB stays applied), for a section with a bottom contact or side
// cutting only.
enum class BitRockLaw { Detournay, Friction, None };

struct BitRockParameters {
  BitRockLaw law = BitRockLaw::Detournay;
  // Detournay.
  double radius = 0.0;           // a, m; 0: half the OD of the string's first (bit) component
  double specific_energy = 0.0;  // ε, Pa (> 0)
  double cutting_ratio = 0.0;    // ζ (> 0)
  double contact_force = 0.0;    // W_f, N (≥ 0)
  double friction = 0.0;         // μ (≥ 0)
  double geometry = 1.0;         // γ (> 0)
  double contact_speed = 0.0;    // V_ε, m/s (> 0)
  // Friction.
  double static_torque = 0.0;    // T_s, N·m (> T_d)
  double kinetic_torque = 0.0;   // T_d, N·m (≥ 0)
  double stribeck_speed = 0.0;   // Ω_d, rad/s (> 0)
  // Both (and side cutting).
  double stick_speed = 0.0;      // Ω_ε, rad/s (> 0)
  // The bottom contact and the side cutting (see above).
  std::optional<BitBottomParameters> bottom;
  std::optional<double> side_cutting;  // k_s, N/m (model/bit_side_cutting.hpp)
};

// Defaults of the regularization: small against drilling speeds (1 rpm ≈ 0.1 rad/s, 1 m/h).
inline constexpr double kDefaultStickSpeed = 0.01;       // rad/s (0.1 rpm)
inline constexpr double kDefaultContactSpeed = 1.0e-5;   // m/s (0.036 m/h)

// The law at (V, Ω): the forces and their derivatives.
struct BitRockForces {
  double wob = 0.0;  // N, on the bit up-hole (≥ 0)
  double tob = 0.0;  // N·m, against positive Ω (the moment on the bit is −tob about the spin axis −t)
  double wob_by_penetration = 0.0, wob_by_spin = 0.0;  // ∂WOB/∂V (N·s/m), ∂WOB/∂Ω (N·s)
  double tob_by_penetration = 0.0, tob_by_spin = 0.0;  // ∂TOB/∂V (N·s), ∂TOB/∂Ω (N·m·s)
};

// Throws LogicError when a parameter is out of its range (the case reader checks them first).
BitRockForces EvaluateBitRock(const BitRockParameters& parameters, double penetration_rate, double spin_rate);

// The law on node 0 of the bit body (the string's first).
class BitRockElement : public ForceElement {
 public:
  BitRockElement(const Body* bit, const BitRockParameters& parameters);
  std::string Describe() const override;
  const BitRockParameters& parameters() const { return parameters_; }
  // V and Ω of the bit at a state.
  double PenetrationRate(const ElementState& state) const;
  double SpinRate(const ElementState& state) const;

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState&) const override { return 0.0; }  // dissipative

 private:
  BitRockParameters parameters_;
  Vec3 axis_;  // t, global
};

// Checks the parameters of `law`, the bottom's and the side cutting's (throws LogicError naming the
// first out of range, or a bottom contact under Detournay's law).
void CheckBitRockParameters(const BitRockParameters& parameters);

}  // namespace drillflex::model
