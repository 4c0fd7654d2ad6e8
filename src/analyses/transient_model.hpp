// The model a transient integrates, from the case's: with a bit-rock law (TransientSettings::
// bit_rock) the rock's reaction on the bit follows the bit's motion (model/bit_rock.hpp) and takes
// over from the case's constant bit loads: the torque on bit always, the WOB too under Detournay's
// law (which gives the WOB from the penetration); the friction law leaves the WOB an applied load
// (the classic torsional stick–slip model, its friction levels set by that WOB). The bit loads it
// takes over still act in the start equilibrium (TransientStartPositions solves it on the case's
// own model), so a run starts from the string resting on bottom under the case's WOB.
#pragma once

#include "analyses/analysis_settings.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

model::ModelInput TransientModelInput(const model::ModelInput& input, const TransientSettings& settings);

}  // namespace drillflex::analyses
