// The string's limits at a roadmap point (pipeline/roadmap.hpp RoadmapPointLimits): the hook load at
// the top pipe's yield, the weakest make-up torque, the slack-off hook load at helical buckling, and
// the runs' screens (buckled zones, fatigue in the doglegs: ScreenRun).
#include <algorithm>
#include <cmath>

#include "analyses/soft_string.hpp"
#include "analyses/string_limits.hpp"
#include "model/string_limits.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::pipeline {
namespace {

// The largest compression / F_h over the soft string's stations slacking off with `weight_on_bit` set
// down (analyses::StringLimits's buckling screen on the soft string's axial force), and its hook load.
struct HelicalScreen {
  double ratio = 0.0;
  double hook_load = 0.0;
};
HelicalScreen ScreenHelical(const model::ModelInput& input, const analyses::SoftStringOperation& base,
                            double weight_on_bit) {
  analyses::SoftStringOperation operation = base;
  operation.weight_on_bit = weight_on_bit;
  const analyses::SoftStringResult soft = analyses::ComputeSoftString(input, operation);
  HelicalScreen screen{0.0, soft.hook_load};
  for (const analyses::SoftStringStation& station : soft.stations) {
    const double compression = -station.axial_force;
    if (compression <= 0.0) continue;
    const double helical = analyses::BucklingLoadsAt(input, station.s, station.md).helical;
    if (helical > 0.0) screen.ratio = std::max(screen.ratio, compression / helical);
  }
  return screen;
}

// The screens of the soft string under `operation`: its stations read as a static's (s, MD, axial force).
RunScreen SoftScreen(const model::ModelInput& input, const analyses::SoftStringOperation& operation) {
  std::vector<analyses::StaticNodeResult> nodes;
  for (const analyses::SoftStringStation& station : analyses::ComputeSoftString(input, operation).stations) {
    analyses::StaticNodeResult node;
    node.s = station.s;
    node.has_wall = true;
    node.md = station.md;
    node.axial_force = station.axial_force;
    node.torque = station.torque;
    nodes.push_back(node);
  }
  return ScreenRun(input, nodes, operation.motion == analyses::SoftStringMotion::Rotating);
}

}  // namespace

RunScreen ScreenRun(const model::ModelInput& input, const std::vector<analyses::StaticNodeResult>& stations,
                    bool rotating) {
  model::ModelInput screened = input;
  // The fatigue screen asks only whether the string turns (analyses::ComputeStringLimits).
  screened.operation.rotary_speed = rotating ? 1.0 : 0.0;
  const analyses::StringLimits limits = analyses::ComputeStringLimits(screened, stations, 1.0);
  RunScreen screen;
  screen.zones = limits.zones;
  if (rotating) {
    screen.doglegs = analyses::FatigueDoglegs(limits);
    screen.fatigue = limits.fatigue;
  }
  return screen;
}

RoadmapLimits RoadmapPointLimits(const io::Case& c, const analyses::RoadmapSettings& settings,
                                 const RoadmapPoint& point) {
  RoadmapLimits limits;
  const io::Case at = CaseAtDepth(c, point.bit_md);
  const model::ModelInput& input = at.input;
  // The top pipe at the surface (the case's top component continued up): its tension capacity under the
  // point's off-bottom torque, by von Mises on its rated section.
  const model::Component& top = input.string.components.back();
  const double yield = top.yield_strength.value_or(model::FindSteelGrade(model::kDefaultGrade)->yield);
  const double torque = std::isfinite(point.off_bottom_torque) ? point.off_bottom_torque : 0.0;
  limits.hook_load_limit = model::TensionCapacity(model::RatedSection(top), yield / c.limits.design_factor, torque);
  for (const model::Component& component : input.string.components) {
    if (component.makeup_torque) limits.torque_limit = std::isfinite(limits.torque_limit)
                                                           ? std::min(limits.torque_limit, *component.makeup_torque)
                                                           : *component.makeup_torque;
  }
  // Slacking off with weight set down: the WOB at which the soft string first reaches F_h anywhere
  // (bisection; the compression grows with the WOB), and the hook load there.
  analyses::SoftStringOperation operation;
  operation.motion = analyses::SoftStringMotion::SlackOff;
  operation.axial_friction = operation.tangential_friction = point.friction;
  if (settings.cased_friction) operation.cased_friction = model::WallFriction{*settings.cased_friction, *settings.cased_friction};
  operation.max_element_length = model::kDefaultJointSpacing;  // as the soft roadmap's runs
  if (point.screens) {
    limits.screens = *point.screens;
  } else {
    limits.screens.slack_off = SoftScreen(input, operation);
    analyses::SoftStringOperation pick_up = operation;
    pick_up.motion = analyses::SoftStringMotion::PickUp;
    limits.screens.pick_up = SoftScreen(input, pick_up);
    analyses::SoftStringOperation rotating = operation;  // off bottom: no WOB, no torque on bit
    rotating.motion = analyses::SoftStringMotion::Rotating;
    limits.screens.rotating = SoftScreen(input, rotating);
    analyses::SoftStringOperation drilling = rotating;
    drilling.weight_on_bit = input.operation.weight_on_bit;
    drilling.torque_on_bit = input.operation.torque_on_bit;
    limits.screens.on_bottom = SoftScreen(input, drilling);
  }
  const auto worst = [](const RunScreen& screen, double& utilisation, double& md) {
    if (screen.fatigue.limit.empty()) return;
    utilisation = screen.fatigue.utilisation;
    md = screen.fatigue.md;
  };
  worst(limits.screens.rotating, limits.fatigue_rotating, limits.fatigue_rotating_md);
  worst(limits.screens.on_bottom, limits.fatigue_on_bottom, limits.fatigue_on_bottom_md);
  const HelicalScreen off_bottom = ScreenHelical(input, operation, 0.0);
  if (off_bottom.ratio >= 1.0) {
    limits.helical_slack_off = off_bottom.hook_load;
    return limits;
  }
  double low = 0.0, high = model::WeightOnBitFromHookLoad(input, 0.0);  // all the string's weight on the bit
  if (!(high > 0.0) || ScreenHelical(input, operation, high).ratio < 1.0) return limits;
  for (int i = 0; i < 40 && high - low > 1e-6 * high; ++i) {
    const double middle = 0.5 * (low + high);
    (ScreenHelical(input, operation, middle).ratio >= 1.0 ? high : low) = middle;
  }
  limits.helical_slack_off = ScreenHelical(input, operation, high).hook_load;
  return limits;
}

}  // namespace drillflex::pipeline
