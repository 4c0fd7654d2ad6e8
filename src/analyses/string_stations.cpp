#include "analyses/string_stations.hpp"

#include <algorithm>
#include <cmath>

namespace drillflex::analyses {

std::vector<Station> StringStations(const model::SystemModel& model) {
  std::vector<Station> stations;
  const auto& bodies = model.bodies();
  for (Index b = 0; b < std::ssize(bodies); ++b) {
    const model::Body& body = bodies[b];
    for (Index k = 0; k < body.node_count(); ++k) {
      Station station;
      station.s = body.NodeS(k);
      station.body = b;
      station.node = k;
      if (k == 0 && b > 0) {
        const model::Body& below = bodies[b - 1];
        const double below_end = below.s_start + below.length();
        // A joint: the lower body's end node is this station too (read from the upper body).
        if (std::abs(below_end - station.s) <= 1e-9 * std::max(1.0, std::abs(station.s))) {
          station.lower_body = b - 1;
          stations.back() = station;  // replaces the lower body's end node
          continue;
        }
      }
      stations.push_back(station);
    }
  }
  return stations;
}

}  // namespace drillflex::analyses
