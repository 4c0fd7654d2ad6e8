// The stations at which the analyses report results along the string: every FE node of every
// body, a joint (end node of body i = start node of body i + 1) reported once. A station's
// kinematics are model/node_kinematics.hpp's (ComputeNodeDisplacement, ComputeStringFrameNodeRates).
#pragma once

#include <vector>

#include "core/types.hpp"
#include "model/system_model.hpp"

namespace drillflex::analyses {

struct Station {
  double s = 0.0;  // distance from the bit end along the undeformed string, m
  Index body = 0;    // the body and node the station reads (at a joint: the upper body's node 0)
  Index node = 0;
  Index lower_body = -1;  // at a joint: the body below (its last node coincides); −1 elsewhere
};

// Ordered from the bit (s = 0) to the top; bodies must be listed from the bit upward.
std::vector<Station> StringStations(const model::SystemModel& model);

}  // namespace drillflex::analyses
