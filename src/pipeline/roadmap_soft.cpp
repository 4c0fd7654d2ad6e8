// The soft-string roadmap (pipeline/roadmap.hpp RunSoftRoadmap): the four runs of a point by
// Johancsik's model (analyses/soft_string.hpp) on the string of CaseAtDepth.
#include "analyses/soft_string.hpp"
#include "core/error.hpp"
#include "core/profile.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::pipeline {
namespace {

// Elements of at most a joint (30 ft): the result no longer depends on the survey's spacing (a
// 500 m build surveyed at its ends read 1-2 % off in the mean inclination of one element).
constexpr double kElementLength = model::kDefaultJointSpacing;

analyses::SoftStringOperation Operation(analyses::SoftStringMotion motion, double friction, double wob, double tob) {
  return {motion, friction, friction, wob, tob, kElementLength};
}

double HookLoad(const model::ModelInput& input, analyses::SoftStringMotion motion, double friction) {
  return analyses::ComputeSoftString(input, Operation(motion, friction, 0.0, 0.0)).hook_load;
}

RoadmapPoint SoftPoint(const model::ModelInput& input, double bit_md, double friction) {
  using analyses::SoftStringMotion;
  RoadmapPoint point{bit_md, friction, 0.0, 0.0, 0.0, 0.0, 0.0, ""};
  point.pick_up = HookLoad(input, SoftStringMotion::PickUp, friction);
  point.slack_off = HookLoad(input, SoftStringMotion::SlackOff, friction);
  const analyses::SoftStringResult rotating =
      analyses::ComputeSoftString(input, Operation(SoftStringMotion::Rotating, friction, 0.0, 0.0));
  point.rotating = rotating.hook_load;
  point.off_bottom_torque = rotating.surface_torque;
  point.on_bottom_torque =
      analyses::ComputeSoftString(input, Operation(SoftStringMotion::Rotating, friction, input.operation.weight_on_bit,
                                                   input.operation.torque_on_bit))
          .surface_torque;
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
    for (const double friction : settings.friction) points.push_back(SoftPoint(at.input, md, friction));
  }
  return points;
}

}  // namespace drillflex::pipeline
