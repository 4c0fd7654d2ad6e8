// The string's limits over a transient run (issue 37): analyses::ComputeStringLimits at each frame of
// the whole string the run keeps (TransientResult::frame_q: the frames transient.pvd draws), its internal
// forces from the frame's state (analyses::StaticNodeResults), and at each station the largest
// utilisation of each limit over the frames, with when.
#pragma once

#include "analyses/transient_analysis.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"
#include "model/builder.hpp"

namespace drillflex::pipeline {

// results.json `transient.limits` from `result`'s frames of the `moving` model (pipeline::TransientSetup):
// `frames`, `design_factor`, `nodes` (per station: s, md, and the largest stress, torque, buckling and
// fatigue utilisations over the frames, 0 where a limit does not apply), `summary` (per limit and the
// closest: the largest over every station and frame, where and at which `time`). Nothing without frames.
void AddTransientLimits(const io::Case& c, const model::BuiltModel& moving, const analyses::TransientResult& result,
                        io::ResultFiles& files);

}  // namespace drillflex::pipeline
