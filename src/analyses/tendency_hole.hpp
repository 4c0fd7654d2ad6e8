// The hole of a directional tendency (docs/method.md "Directional tendency"): the hole the bit has
// drilled when it keeps a constant curvature. It ends at the bit where the case's hole does, with the
// case's direction there; up the hole from the bit it is a circular arc of the curvature vector
// κ = κ_b h + κ_r r (h the high side and r the right of the hole at the bit: κ_b > 0 builds, κ_r > 0
// turns right), over `arc_length`, and straight along the arc's top tangent above it. The hole's
// diameter stays the case's at each MD.
//
// The string moved from one such hole into another (CarryIntoHole): each body's ends keep their places
// in the hole's cross-sections, so the contacts keep their side of the wall and their offsets, the bit
// stays where its support holds it, and a static from it starts a curvature step away from its
// equilibrium.
#pragma once

#include "core/types.hpp"
#include "model/system_model.hpp"
#include "well/trajectory.hpp"

namespace drillflex::analyses {

// A hole's curvature vector at the bit in the hole's frame there, 1/m.
struct HoleCurvature {
  double build = 0.0;  // κ_b: toward the high side (the inclination grows along the hole)
  double right = 0.0;  // κ_r: toward the right, looking down-hole (the azimuth grows)
};

// The case path's own curvature at the bit, in its frame there.
HoleCurvature CurvatureAtBit(const well::Trajectory& path, double bit_md);

// The hole above: from `top_md` (≥ 0, < bit_md) down to the bit at `bit_md`, ending at the position
// and tangent of `path` at `bit_md`, the arc over min(arc_length, bit_md − top_md). Its stations are
// at most 10 m apart along the arc (the minimum-curvature path through them is the arc itself).
// Throws LogicError for a non-positive arc length or a turn of the arc over π (no unique path).
well::Trajectory ConstantCurvatureHole(const well::Trajectory& path, double bit_md, double top_md,
                                       double arc_length, HoleCurvature curvature);

// The positions q of `from_model` (its bodies in the hole `from`, the bit at `bit_md`) carried into the
// hole `to`, as positions of `to_model` (the same bodies placed in `to`; q holds each frame's
// displacement from its model's placement). Each body's first and last node keep their places in the
// hole's cross-section at their MD (the point turned with the hole's tangent there), the body turned
// with its chord between them; modal coordinates are kept.
VecX CarryIntoHole(const model::SystemModel& from_model, const VecX& q, const model::SystemModel& to_model,
                   double bit_md, const well::Trajectory& from, const well::Trajectory& to);

}  // namespace drillflex::analyses
