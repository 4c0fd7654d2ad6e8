// A start for the static Newton solve of a string in a well: the string moved from the hole axis
// onto the wall it will rest on.
//
// From the centreline, Newton has to find which of hundreds of contacts close while the whole
// string falls through its clearance; capped steps and load stepping then take thousands of
// iterations. A soft-string estimate (the classic torque-and-drag model: Johancsik et al., SPE
// 11380, 1984, friction left out) says where each part of the string rests: its lateral load per
// length is
//   f⊥ = w_b (ĝ − (ĝ·t) t) + T κ,
// with w_b the buoyed weight per length, t the hole tangent, κ = dt/ds the curvature vector (toward
// the centre of the bend; tension pulls the string to the inside of a bend, compression pushes it
// out) and T the axial force (tension positive) from T(0) = −WOB and dT/ds = w_b cos I up the hole.
// Each station is moved along f⊥ by the radial clearance left at the largest contact diameter near
// it (the tool joints, blades or body within half a standard joint spacing), the offsets averaged
// along the string and ramped from zero at the bit, which its support holds at the hole centre:
// the resting line. The bodies are laid on it end to end with exact chord lengths, each stretched
// by T ℓ/EA, slid along the bit's axis until the top meets the hook, rolled from the body above
// (parallel transport from the top down), and bent into the line by the least strain energy, so
// the couplings start unstrained (resting_start.cpp says why each step is there). Newton then adds
// the sag between joints, the exact contact set and the balance of forces.
//
// The torque on bit twists the string by radians over a few hundred metres of drill pipe. A Newton
// step that turns a bent body about its axis also turns its bending (held in body coordinates),
// an error of second order that the stiff couplings amplify; so the twist is put in before the
// solve, with the shape kept (model::TwistKeepingShape): with the top held in torsion and the
// torque on bit a moment about the string axis, θ(s) = TOB ∫_s^top ds'/GJ (plus the friction torque of
// a rotating string).
#pragma once

#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// The positions q of the string resting on the wall, for `built` made from `input` (which must
// have a trajectory and a hole). Throws LogicError without them.
VecX RestingStart(const model::ModelInput& input, const model::BuiltModel& built);

// Turns each body about its axis by the twist θ at its middle, keeping the string's shape:
// θ(s) = ∫_s^top T ds'/GJ, T the torque on bit plus, when the string rotates
// (ModelInput::static_sliding), the wall friction torque μ_t N R_c of the contacts below s with
// their normal forces N at q (e.g. of an equilibrium without friction; the friction changes them
// little). `built` gives the contacts; its bodies are those of q. Under `parameters`: the friction
// coefficients and sliding of its block (model::WallContactElement::EffectiveParameters); the
// torque on bit is the input's.
void TwistUnderTorque(const model::ModelInput& input, const model::BuiltModel& built, VecX& q,
                      const model::LoadParameters& parameters = 1.0);

}  // namespace drillflex::analyses
