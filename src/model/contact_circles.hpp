// The wall-contact circles of a string: at which nodes, of which diameter, standing for how much
// string, so that the wall is as stiff per metre of string whatever the mesh.
//
// Short features that touch the wall, a tool joint and a stabilizer's blades, are point contacts
// (as in stiff-string torque-and-drag and BHA beam-column models, and the paper's contacts at body
// ends): one circle of the feature's diameter at the node nearest the feature's centre (the
// connection; the middle of the blades), standing for the feature's length. Every other node has a
// circle of the body OD standing for its own span (half-way to the neighbouring contact nodes)
// less the features' lengths inside it (never below 1/16 of the span). A feature resolved by
// several nodes would instead act as a patch that resists tilting, and its stiffness in bending
// would then grow as the mesh is refined; as one circle, refining the mesh leaves it alone.
// The circle's stiffness is k' × its length, with k' the wall's stiffness per metre of string.
#pragma once

#include <vector>

#include "model/string_config.hpp"

namespace drillflex::model {

struct ContactCircle {
  double diameter = 0.0;  // m
  double length = 0.0;    // m of string it stands for
};

// The circles at the contact nodes `s` (m from the bit, ascending; at least one).
std::vector<ContactCircle> ContactCircles(const StringConfig& string, const std::vector<double>& s);

}  // namespace drillflex::model
