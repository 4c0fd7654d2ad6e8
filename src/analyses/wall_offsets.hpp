// Where each station of the string sits in the hole (case-format.md "Results", issue 4 item 6):
// its distance from the hole axis, the direction of that offset and the clearance left to the wall,
// read from the wall contact at the node (model/wall_contact.hpp).
//
// The two offsets of a static result differ:
//  * StaticNodeResult::lateral_offset: the node's displacement across the string axis from its
//    undeformed placement (a chain of chords along the centreline: in a curved hole the chords'
//    interior nodes are off the axis by up to ℓ²κ/8 before anything moves).
//  * StaticNodeResult::hole_offset (this file): the distance ρ of the node from the hole axis,
//    measured in the hole's cross-section through the node (the contact's closest point s*).
// In a straight hole the two are equal; in a curved one they differ by the chord sag and because the
// string frame of a body is its chord's, not the hole's cross-section.
#pragma once

#include <span>
#include <vector>

#include "analyses/static_analysis.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// Fills in md, hole_offset, offset_high_side_angle, clearance, hole_diameter, has_wall and
// wall_contact of every node (StaticNodeResults(built, q) order: one per string station,
// from the bit upward) from the wall contact at that node, evaluated at q at rest.
// Nodes without a contact element of their own (the bit's: it cuts its hole and carries none) in a
// model with a well get the same geometry for a contact circle of their body's contact diameter
// (has_wall = true, wall_contact = false). Without wall contacts (no well) nothing changes
// (has_wall = false). Throws LogicError when `nodes` is not one per station.
void AddWallOffsets(const model::BuiltModel& built, const VecX& q, std::vector<StaticNodeResult>& nodes);
// The same for results at the listed stations only (nodes[i] at station station_indices[i], as
// StaticNodeResults(built, q, load_factor, station_indices) gives them).
void AddWallOffsets(const model::BuiltModel& built, const VecX& q, std::vector<StaticNodeResult>& nodes,
                    std::span<const Index> station_indices);

}  // namespace drillflex::analyses
