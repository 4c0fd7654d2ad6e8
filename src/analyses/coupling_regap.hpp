// Carrying the couplings' forces over to stiffer couplings (the stages of the static solve from the
// resting start, analyses/static_analysis.cpp).
//
// The static solve stiffens the couplings in stages (c = 10, then the case's factor, by half decades
// or at once). An equilibrium at factor c₁ put into the model at c₂ leaves every coupling carrying
// c₂/c₁ times its force: the string's tension (1e6 N at the top of 3 km of pipe) and the torque,
// unbalanced at every joint, a residual of 1e8 N and more. Its geometric stiffness then bends the
// first Newton step of the stage (on the 3 km bench, half a metre across the hole) far from the
// small correction it needs. So, before the stage, each coupling's strain is changed to the one that
// carries at the new stiffness the force and moment it carried at the old, e′ = f/k₂ instead of
// f/k₁, and likewise each support's (the hook, the bit's lateral hold: as stiff as a coupling times
// kSupportStiffnessFactor). A coupling's change is shared by its two bodies (half each), a support's
// is its body's alone, and each body takes the motions of its end nodes with the least strain energy
// (its frame moves freely): no motion adds up along the string, so nothing pushes a body into the
// wall. What is left is the bodies' own stretch and bending under the changed end motions (3 km
// bench string, c 10 → 31.6: |R| 8.4e6 → 2.2e5 N; the stages after it converge in 3–5 Newton
// iterations where they took 40 and more).
#pragma once

#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// `from` and `to` are built from the same input but for the coupling factor (the same bodies and
// elements in the same order); q, an equilibrium of `from`, is changed in place. Throws LogicError
// when the two models do not match.
void CarryCouplingForces(const model::BuiltModel& from, const model::BuiltModel& to, VecX& q);

}  // namespace drillflex::analyses
