// Where a transient's bottom contact (model/bit_bottom.hpp) sits: under the bit at its start
// place, pressed in by as much as carries the WOB of the start equilibrium, so that the contact
// takes the case's WOB over at t = 0 without a jump (as the drives take over from the supports).
#pragma once

#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// `transient` (TransientModelInput's) with its bottom's level set from the start q0 of `start`
// (the case's model at rest, the same coordinates): level = t·(r_bit(q0) − p) + W/k, W the
// operation's WOB (what the start equilibrium applied), k the contact's stiffness. Unchanged
// without a bottom contact.
model::ModelInput PlaceBottomAtStart(model::ModelInput transient, const model::BuiltModel& start, const VecX& q0);

}  // namespace drillflex::analyses
