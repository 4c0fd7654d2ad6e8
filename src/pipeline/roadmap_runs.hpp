// The runs of a roadmap at one bit depth (pipeline/roadmap.hpp), as a continuation: the depth's
// model is built once (the string continued to the surface, the default well supports) and every
// run is the same model under another parameter block (model/load_parameters.hpp):
//
//   at rest, off bottom        the bit free, no WOB, no friction: the energy's minimum from the
//                              string resting on the wall (the one cold solve of a depth);
//   pick-up, slack-off         the axial friction of a prescribed trip, each from the same run at
//                              the friction factor before, the first from the string at rest;
//   rotating, off bottom       the friction around the string, from the same run at the friction
//                              factor before, the first continued in the friction from rest;
//   on bottom                  the bit held at the hole centre with the case's WOB and torque on
//                              bit, from the rotating run at the same friction factor.
//
// Each warm run is Newton from its neighbour with the factorization kept while it contracts
// (analyses/static_solve.hpp, strategy 1), falling back to the whole chain where that fails.
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
