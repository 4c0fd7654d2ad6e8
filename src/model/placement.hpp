// Where the bodies sit before the analysis moves them: the reference placement.
// Without a well the string lies straight along global +x from the origin (bit end at x = 0), the
// string frame is the global frame. In a well the bodies form a chain of chords along the
// centreline from the bit upward: node 0 of each body on the end node of the one below, the end
// node on the centreline at the body's length from its start. Each body's frame has x along the
// chord (up-hole), z toward the high side and y to the right (looking down-hole): the string
// frame of case-format.md. The couplings stay stress-free in this placement except for the small
// kinks between chords; the bending a curved hole forces on the string comes out of the analysis.
#pragma once

#include <vector>

#include "model/body.hpp"
#include "well/trajectory.hpp"

namespace drillflex::model {

// The string frame (columns x up-hole, y right, z high side) for an up-hole axis `up` and the
// high-side frame of the hole there.
Mat3 StringFrame(const Vec3& up, const well::PathFrame& hole_frame);

// Places bodies (in order from the bit) along the well from `bit_md` upward. Throws InputError
// when the string would reach above the first survey station.
void PlaceAlongWell(std::vector<Body>& bodies, const well::Trajectory& trajectory, double bit_md);

}  // namespace drillflex::model
