// The runs of a roadmap at one bit depth (pipeline/roadmap.hpp): the depth's model built once and each
// friction factor's pick-up, slack-off, rotating off bottom and on-bottom runs as a continuation from
// the runs before (pipeline/depth_runs.hpp). The factors are the open hole's; the cased hole takes the
// settings' cased_friction, else each cased section's own.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "io/case.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::pipeline {

// The points of one depth, one a friction factor in the settings' order (the runs go from the
// smallest factor up). A run that fails leaves its point NaN with its message.
// `log`, when set, takes the solvers' progress lines, each prefixed with the depth and the run.
std::vector<RoadmapPoint> RunRoadmapDepth(const io::Case& c, const analyses::RoadmapSettings& settings, double bit_md,
                                          const std::function<void(const std::string&)>& log = nullptr);

}  // namespace drillflex::pipeline
