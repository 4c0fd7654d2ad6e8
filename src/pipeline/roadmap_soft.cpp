// The soft-string roadmap (pipeline/roadmap.hpp RunSoftRoadmap): the four runs of a point by
// Johancsik's model (analyses/soft_string.hpp) on the string of CaseAtDepth.
#include "analyses/soft_string.hpp"
#include "core/error.hpp"
#include "core/profile.hpp"
#include "pipeline/depth_runs.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::pipeline {
namespace {

RoadmapPoint SoftPoint(const model::ModelInput& input, const analyses::RoadmapSettings& settings, double bit_md,
                       double friction) {
  RoadmapPoint point;
  point.bit_md = bit_md;
  point.friction = friction;
  const HoleFrictionFactors factors{friction, settings.cased_friction};
  TdRunLoads loads;  // the case's WOB and torque on bit on bottom
  point.pick_up = SoftSurfaceReading(input, TdRun::kPickUp, factors, loads).hook_load;
  point.slack_off = SoftSurfaceReading(input, TdRun::kSlackOff, factors, loads).hook_load;
  const SurfaceReading rotating = SoftSurfaceReading(input, TdRun::kRotatingOffBottom, factors, loads);
  point.rotating = rotating.hook_load;
  point.off_bottom_torque = rotating.surface_torque;
  point.on_bottom_torque = SoftSurfaceReading(input, TdRun::kOnBottom, factors, loads).surface_torque;
  return point;
}

}  // namespace

const char* RoadmapModelName(analyses::RoadmapModel model) {
  switch (model) {
    case analyses::RoadmapModel::Stiff: return "stiff";
    case analyses::RoadmapModel::Soft: return "soft";
    case analyses::RoadmapModel::Both: return "both";
  }
  return "stiff";
}

std::vector<RoadmapPoint> RunSoftRoadmap(const io::Case& c, const analyses::RoadmapSettings& settings) {
  const profile::Scope scope("roadmap: soft string");
  std::vector<RoadmapPoint> points;
  for (const double md : RoadmapDepths(c, settings)) {
    const io::Case at = CaseAtDepth(c, md);
    for (const double friction : settings.friction) points.push_back(SoftPoint(at.input, settings, md, friction));
  }
  return points;
}

}  // namespace drillflex::pipeline
