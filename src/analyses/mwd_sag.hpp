// The MWD's sag correction (issue 34, item 5): the MWD's inclination sensor reads the direction of
// its own axis; where the collar sags between stabilizers that axis differs from the hole's. From a
// static equilibrium in a well: the sensor's axis, the string's tangent at the sensor (the chord of its
// two neighbouring stations, second order in their spacing), against the hole's tangent at the
// sensor's MD, in the vertical plane: sag = I_axis − I_hole. The survey's inclination corrected for
// it is the measured one less the sag.
#pragma once

#include <optional>
#include <span>

#include "analyses/static_analysis.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// Where the sensor sits: `mwd_at` (m from the bit) when given, else the middle of the string's first
// MWD component; none without either.
std::optional<double> MwdSensorAt(const model::StringConfig& string, std::optional<double> mwd_at);

// The sag at `sensor_s` of an equilibrium's stations (from the bit upward, in a well: has_wall set)
// in `path`. None when the stations do not reach the sensor with a neighbour on each side.
std::optional<MwdSag> ComputeMwdSag(std::span<const StaticNodeResult> nodes, const well::Trajectory& path,
                                    double sensor_s);

}  // namespace drillflex::analyses
