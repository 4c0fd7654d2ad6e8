// Where a transient's block line (model/drives.hpp BlockDrive::line_stiffness) starts: stretched
// by as much as the hold it replaces was at the start equilibrium, so that the line takes the top's
// axial force over at t = 0 without a jump (as the bottom contact does: bit_bottom_start.hpp).
#pragma once

#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// `transient` (TransientModelInput's) with its block's start_top_displacement set to the top node's
// axial displacement t·(r_top(q0) − p) in q0 of `start` (the case's model at rest, the same
// coordinates). Unchanged without a velocity block with its own line stiffness.
model::ModelInput PlaceBlockAtStart(model::ModelInput transient, const model::BuiltModel& start, const VecX& q0);

}  // namespace drillflex::analyses
