// A point-the-bit rotary steerable system in the tendency's statics (analyses.tendency.rss with
// `type: point`; docs/method.md "Directional tendency").
//
// The tool's drive shaft turns inside a housing held still in space; between the fulcrum bearing near
// the bit and an eccentric cam above it the shaft is deflected, so that below the fulcrum it, and the
// bit on it, point at `offset` to the tool's axis toward the toolface (Halliburton's Geo-Pilot,
// Schlumberger's PowerDrive Xceed). In the static that is a bent housing's bend at the fulcrum: the
// coupling of the bodies there holds the angle (model/string_geometry.cpp, BentHousingRotation), as an
// equivalent hinge-deflection angle at the steering unit does in the finite-element models of such
// tools. Unlike a rotating bent motor's, the bend does not sweep the toolfaces: the housing holds it at
// the toolface in space, so the bend is set against the string's twist at the fulcrum (TwistAt) until
// its toolface in the hole is the system's.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "analyses/analysis_settings.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/three_point_yield.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// The set toolface follows the twist until the bend's toolface in space is within this of the
// system's, in at most kPointTwistRounds statics (the twist hardly changes with the bend).
inline constexpr double kPointToolfaceTolerance = 0.01 * kDegree;  // rad
inline constexpr int kPointTwistRounds = 6;

// The reasons a point-the-bit system cannot go into `input`'s string, as (key, message) for an
// InputError: the fulcrum in the bit or beyond the string's top, or in a component with a bend of its own.
std::optional<std::pair<std::string, std::string>> PointTheBitProblem(const model::ModelInput& input,
                                                                      const RssSettings& rss);

// `input` with the system's shaft bent by rss.offset at its fulcrum rss.at toward `set_toolface` (rad,
// in the string's own frame: the toolface in space plus the string's twist there). A zero offset is no
// bend: the string is the case's.
model::ModelInput PointTheBit(model::ModelInput input, const RssSettings& rss, double set_toolface);

// The string's twist about its axis at `s` in a static (the rotation of the node nearest `s`, rad,
// positive about the up-hole axis): a bend the string carries there points toward its set toolface
// less the twist (a turn about the up-hole axis takes the high side toward the left, looking down-hole).
double TwistAt(const StaticResult& equilibrium, double s);

// The three-point geometric yield at full steer: the circle through the bit, the highest blade below the
// fulcrum (or the fulcrum itself) and the first blade above it, the offset the bend between them.
std::optional<ThreePointYield> PointTheBitThreePoint(const model::StringConfig& string, const RssSettings& rss);

}  // namespace drillflex::analyses
