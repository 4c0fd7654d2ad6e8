// The trajectory table of `drillflex well`: every survey station and every `output_step` between
// them, in the output units.
#pragma once

#include <vector>

#include "io/case.hpp"
#include "io/result_files.hpp"

namespace drillflex::io {

struct TrajectoryRow {
  double md = 0.0;           // m
  double inclination = 0.0;  // rad
  double azimuth = 0.0;      // rad
  double north = 0.0, east = 0.0, tvd = 0.0;  // m
  double dogleg_severity = 0.0;  // rad/m
  double hole_diameter = 0.0;    // m
};

// Rows at every station and every `step` between consecutive stations (SI).
std::vector<TrajectoryRow> TrajectoryTable(const WellConfig& well);

// Adds trajectory.csv and the "well" entry of results.json, in `system` units.
void AddTrajectoryResults(const std::vector<TrajectoryRow>& rows, units::System system, ResultFiles& files);

}  // namespace drillflex::io
