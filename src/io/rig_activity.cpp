// The rig activities' names and the classification rule of io/rig_activity.hpp.
#include "io/rig_activity.hpp"

#include <cmath>

namespace drillflex::io {
namespace {

constexpr RigActivity kActivities[] = {RigActivity::kDrilling, RigActivity::kRotatingOffBottom, RigActivity::kPickUp,
                                       RigActivity::kSlackOff, RigActivity::kInSlips,           RigActivity::kOther};

}  // namespace

const char* RigActivityName(RigActivity activity) {
  switch (activity) {
    case RigActivity::kDrilling: return "drilling";
    case RigActivity::kRotatingOffBottom: return "rotating";
    case RigActivity::kPickUp: return "pick_up";
    case RigActivity::kSlackOff: return "slack_off";
    case RigActivity::kInSlips: return "in_slips";
    case RigActivity::kOther: return "other";
  }
  return "other";
}

std::optional<RigActivity> RigActivityOfName(std::string_view name) {
  for (const RigActivity activity : kActivities) {
    if (name == RigActivityName(activity)) return activity;
  }
  return std::nullopt;
}

bool IsModelledActivity(RigActivity activity) {
  return activity != RigActivity::kInSlips && activity != RigActivity::kOther;
}

double InSlipsHookLoad(double lowest, double median) { return lowest < 0.5 * median ? 1.2 * lowest : 0.0; }

RigActivity ClassifyRigActivity(const RigActivitySample& now, const RigActivitySample* previous,
                                const RigActivityThresholds& thresholds) {
  if (now.hook_load < thresholds.in_slips_hook_load) return RigActivity::kInSlips;
  const bool rotating = now.rotary_speed > thresholds.min_rotary_speed;
  const bool on_bottom =
      now.hole_md - now.bit_md < thresholds.on_bottom_distance && now.weight_on_bit > thresholds.min_weight_on_bit;
  if (on_bottom) return rotating ? RigActivity::kDrilling : RigActivity::kOther;
  // The bit's movement down since the previous row: the block's fall where both rows have it.
  double down = 0.0;
  if (previous) {
    down = now.block_position && previous->block_position ? *previous->block_position - *now.block_position
                                                          : now.bit_md - previous->bit_md;
  }
  const bool still = std::abs(down) <= thresholds.still_distance;
  if (rotating) return still ? RigActivity::kRotatingOffBottom : RigActivity::kOther;
  if (still) return RigActivity::kOther;
  return down < 0.0 ? RigActivity::kPickUp : RigActivity::kSlackOff;
}

}  // namespace drillflex::io
