// Where the elements a transient adds at the string's ends start, so that each takes over from the
// start equilibrium at t = 0 without a jump (as the drives take over from the supports):
//  * the bottom contact (model/bit_bottom.hpp) under the bit at its start place, pressed in by as
//    much as carries the WOB of the start equilibrium;
//  * the block's line (model/drives.hpp BlockDrive::line_stiffness) stretched by as much as the
//    hold it replaces was, so that it carries the same force.
#pragma once

#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// `transient` (TransientModelInput's) with its bottom's level set from the start q0 of `start`
// (the case's model at rest, the same coordinates): level = t·(r_bit(q0) − p) + W/k, W the
// operation's WOB (what the start equilibrium applied), k the contact's stiffness. Unchanged
// without a bottom contact.
model::ModelInput PlaceBottomAtStart(model::ModelInput transient, const model::BuiltModel& start, const VecX& q0);

// `transient` with its block's start_top_displacement set to the top node's axial displacement
// t·(r_top(q0) − p) in q0 of `start`. Unchanged without a velocity block with its own line stiffness.
model::ModelInput PlaceBlockAtStart(model::ModelInput transient, const model::BuiltModel& start, const VecX& q0);

}  // namespace drillflex::analyses
