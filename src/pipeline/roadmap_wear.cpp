// The casing worn drilling a roadmap's section (pipeline/roadmap.hpp RoadmapCasingWear): the static's
// wear run (pipeline/casing_wear_run.hpp) depth by depth down the roadmap, one friction factor at a time.
#include <cmath>

#include "pipeline/casing_wear_run.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::pipeline {
namespace {

// The deepest groove of `stations` (worn, their grooves finished) and the time drilled.
RoadmapWear Deepest(const std::vector<CasingWearStation>& stations, double rotating_time) {
  RoadmapWear wear;
  wear.rotating_time = rotating_time;
  const CasingWearStation* deepest = nullptr;
  for (const CasingWearStation& station : stations) {
    if (station.groove_depth > 0.0 && (!deepest || station.groove_depth > deepest->groove_depth)) deepest = &station;
  }
  if (!deepest) return wear;
  wear.md = deepest->md;
  wear.side_force_per_length = deepest->side_force_per_length;
  wear.worn_area = deepest->worn_area;
  wear.groove_depth = deepest->groove_depth;
  if (deepest->wall > 0.0) {
    wear.remaining_wall = deepest->remaining_wall;
    wear.utilisation = deepest->wear_utilisation;
  }
  return wear;
}

}  // namespace

std::vector<RoadmapWear> RoadmapCasingWear(const io::Case& c, const analyses::RoadmapSettings& settings,
                                           const std::vector<RoadmapPoint>& points) {
  std::vector<RoadmapWear> wear(points.size());
  if (!c.well || !c.limits.wear || !c.limits.wear->rate_of_penetration) return wear;
  const std::vector<CasingWearStation> casing = CasingWearStations(c);
  const std::size_t frictions = settings.friction.size();
  if (casing.empty() || frictions == 0) return wear;
  const double rop = *c.limits.wear->rate_of_penetration;  // m/s
  for (std::size_t k = 0; k < frictions; ++k) {
    std::vector<CasingWearStation> stations = casing;
    analyses::SoftStringOperation friction;
    friction.axial_friction = friction.tangential_friction = settings.friction[k];
    if (settings.cased_friction) {
      friction.cased_friction = model::WallFriction{*settings.cased_friction, *settings.cased_friction};
    }
    double time = 0.0;  // s drilled since the first depth
    for (std::size_t i = k; i < points.size(); i += frictions) {
      // From the depth above to this one the string rotates at this one (the first: nothing drilled).
      const double drilled = i >= frictions ? points[i].bit_md - points[i - frictions].bit_md : 0.0;
      if (drilled > 0.0) {
        AddRotatingWear(c, CaseAtDepth(c, points[i].bit_md).input, friction, drilled / rop, stations);
        time += drilled / rop;
      }
      std::vector<CasingWearStation> grooves = stations;
      FinishCasingWear(grooves);
      wear[i] = Deepest(grooves, time);
    }
  }
  return wear;
}

}  // namespace drillflex::pipeline
