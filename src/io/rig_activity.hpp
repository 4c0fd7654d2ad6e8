// What the rig was doing at a reading: drilling on bottom, rotating off bottom, picking up, slacking off,
// in slips or something else. A readings CSV says it on each row; a WITSML log's rows are classified
// here from bit and hole depth, block movement, rotary speed, WOB and hook load.
//
// The rule (ClassifyRigActivity), tried in this order:
//   1. in_slips   the hook load is below the in-slips hook load (RigActivityThresholds): the hook then
//                 carries only the travelling equipment, the string hangs in the slips.
//   2. on bottom  hole depth - bit depth < on_bottom_distance and WOB > min_weight_on_bit:
//                 rotating (RPM > min_rotary_speed) -> drilling; not rotating (sliding) -> other.
//   3. off bottom, the bit's movement since the previous row (from the block position when the log has
//                 it: the bit goes down as the block does; else from the bit depth; none for the first
//                 row) within +-still_distance, rotating -> rotating (off bottom); rotating and moving
//                 (reaming) -> other.
//   4. not rotating: the bit moving up by more than still_distance -> pick_up, down -> slack_off, still
//                 -> other.
// The roadmap's pick-up and slack-off hook loads are those of a string moving without rotation, and its
// rotating hook load and off-bottom torque those of a string turning in place (pipeline/roadmap.hpp):
// reaming and sliding match none of them and are "other".
#pragma once

#include <optional>
#include <string_view>

#include "core/types.hpp"

namespace drillflex::io {

enum class RigActivity {
  kDrilling,           // on bottom, rotating
  kRotatingOffBottom,  // off bottom, rotating, the block still
  kPickUp,             // moving up, not rotating
  kSlackOff,           // moving down, not rotating
  kInSlips,
  kOther,
};

// "drilling", "rotating", "pick_up", "slack_off", "in_slips", "other".
const char* RigActivityName(RigActivity activity);
// The activity of a name RigActivityName gives; none for any other text.
std::optional<RigActivity> RigActivityOfName(std::string_view name);
// The activities the roadmap models (drilling, rotating, pick_up, slack_off): the ones a calibration uses.
bool IsModelledActivity(RigActivity activity);

// One row of a log as the rule sees it, SI.
struct RigActivitySample {
  double bit_md = 0.0;   // m
  double hole_md = 0.0;  // m: the hole's depth at the row (its deepest bit depth so far when not logged)
  std::optional<double> block_position;  // m, up positive (BPOS); none where not logged
  double hook_load = 0.0;                // N
  double weight_on_bit = 0.0;            // N
  double rotary_speed = 0.0;             // rad/s
};

struct RigActivityThresholds {
  double on_bottom_distance = 0.3;  // m: the bit within this of the hole's bottom is on bottom
  // N: 1 klbf (1000 x 4.4482216152605 N, NIST SP 811), the usual resolution of a rig's WOB; less is
  // an off-bottom sensor offset.
  double min_weight_on_bit = 4448.2216152605;
  // rad/s: 5 rpm; a string turning slower is not rotating (the top drive held or creeping).
  double min_rotary_speed = 5.0 * 2.0 * kPi / 60.0;
  // m: the bit moving less than this between two rows is still (a 1-5 s log drilling at 30 m/h moves
  // 0.01-0.04 m a row; tripping at 0.2-0.5 m/s moves 0.2 m or more).
  double still_distance = 0.05;
  double in_slips_hook_load = 0.0;  // N: below this the string is in slips (InSlipsHookLoad)
};

// The in-slips hook load of a log whose lowest hook load is `lowest` and median `median` (N): 1.2 x
// the lowest when the lowest is under half the median, i.e. when the log holds periods in slips (the
// hook then carries only the travelling equipment, a small part of the string's weight); else 0 (no
// row in slips: a log all drilling has no such gap, and 1.2 x its lowest would take its lightest rows).
double InSlipsHookLoad(double lowest, double median);

// The activity at `now`; `previous` is the log's row before it (null for the first).
RigActivity ClassifyRigActivity(const RigActivitySample& now, const RigActivitySample* previous,
                                const RigActivityThresholds& thresholds);

}  // namespace drillflex::io
