// The rig activity rule (io/rig_activity.hpp), branch by branch, on hand-made rows: a hole 1000 m
// deep, a string of 150 klbf hanging off bottom, the defaults' thresholds (0.3 m on bottom, 1 klbf WOB,
// 5 rpm, 0.05 m still) and an in-slips hook load of 50 klbf.
#include "io/rig_activity.hpp"

#include <gtest/gtest.h>

namespace drillflex::io {
namespace rig_activity_test {

constexpr double kKlbf = 4448.2216152605;  // N
constexpr double kRpm = 2.0 * kPi / 60.0;  // rad/s

RigActivityThresholds Thresholds() {
  RigActivityThresholds thresholds;
  thresholds.in_slips_hook_load = 50 * kKlbf;
  return thresholds;
}

// A row at `bit_md` with the string's weight on the hook less the WOB.
RigActivitySample Row(double bit_md, double wob_klbf, double rpm, std::optional<double> block = std::nullopt) {
  return {bit_md, 1000.0, block, (150 - wob_klbf) * kKlbf, wob_klbf * kKlbf, rpm * kRpm};
}

RigActivity Classify(const RigActivitySample& now, const RigActivitySample* previous = nullptr) {
  return ClassifyRigActivity(now, previous, Thresholds());
}

TEST(RigActivity, NamesReadBack) {
  for (const RigActivity activity : {RigActivity::kDrilling, RigActivity::kRotatingOffBottom, RigActivity::kPickUp,
                                     RigActivity::kSlackOff, RigActivity::kInSlips, RigActivity::kOther}) {
    EXPECT_EQ(RigActivityOfName(RigActivityName(activity)), activity);
  }
  EXPECT_STREQ(RigActivityName(RigActivity::kRotatingOffBottom), "rotating");
  EXPECT_FALSE(RigActivityOfName("tripping"));
  EXPECT_TRUE(IsModelledActivity(RigActivity::kSlackOff));
  EXPECT_FALSE(IsModelledActivity(RigActivity::kInSlips));
  EXPECT_FALSE(IsModelledActivity(RigActivity::kOther));
}

TEST(RigActivity, OnBottomWithWeightAndRotationIsDrilling) {
  const RigActivitySample before = Row(999.85, 20, 120), now = Row(999.9, 20, 120);
  EXPECT_EQ(Classify(now, &before), RigActivity::kDrilling);
  EXPECT_EQ(Classify(now), RigActivity::kDrilling);  // the first row needs no movement
}

TEST(RigActivity, OnBottomWithoutRotationIsSlidingAndOther) {
  EXPECT_EQ(Classify(Row(999.9, 20, 0)), RigActivity::kOther);
  EXPECT_EQ(Classify(Row(999.9, 20, 4)), RigActivity::kOther);  // below 5 rpm: not rotating
}

TEST(RigActivity, NearBottomWithoutWeightIsOffBottom) {
  // 0.1 m above bottom but under 1 klbf WOB: the bit hangs off bottom, turning in place.
  const RigActivitySample before = Row(999.9, 0.5, 80), now = Row(999.9, 0.5, 80);
  EXPECT_EQ(Classify(now, &before), RigActivity::kRotatingOffBottom);
  // 0.4 m off bottom with weight on the sensor: not on bottom either (a WOB offset).
  const RigActivitySample high = Row(999.6, 5, 80);
  EXPECT_EQ(Classify(high, &high), RigActivity::kRotatingOffBottom);
}

TEST(RigActivity, RotatingInPlaceIsRotatingMovingIsReaming) {
  const RigActivitySample before = Row(990.0, 0, 100);
  EXPECT_EQ(Classify(Row(990.04, 0, 100), &before), RigActivity::kRotatingOffBottom);  // within 0.05 m
  EXPECT_EQ(Classify(Row(989.5, 0, 100), &before), RigActivity::kOther);               // back-reaming
  EXPECT_EQ(Classify(Row(990.5, 0, 100), &before), RigActivity::kOther);               // reaming down
}

TEST(RigActivity, MovingUpIsPickUpDownIsSlackOff) {
  const RigActivitySample before = Row(990.0, 0, 0);
  EXPECT_EQ(Classify(Row(989.0, 0, 0), &before), RigActivity::kPickUp);
  EXPECT_EQ(Classify(Row(991.0, 0, 0), &before), RigActivity::kSlackOff);
  EXPECT_EQ(Classify(Row(990.02, 0, 0), &before), RigActivity::kOther);  // still, not rotating
  EXPECT_EQ(Classify(Row(990.0, 0, 0)), RigActivity::kOther);            // the first row: no movement known
}

TEST(RigActivity, TheBlockPositionGivesTheMovementWhereLogged) {
  // The bit depth frozen (as some rigs log it) while the block rises 2 m: the bit goes up.
  const RigActivitySample before = Row(990.0, 0, 0, 20.0);
  EXPECT_EQ(Classify(Row(990.0, 0, 0, 22.0), &before), RigActivity::kPickUp);
  EXPECT_EQ(Classify(Row(990.0, 0, 0, 18.0), &before), RigActivity::kSlackOff);
  // Without the block on the previous row the bit depth decides.
  const RigActivitySample no_block = Row(990.0, 0, 0);
  EXPECT_EQ(Classify(Row(989.0, 0, 0, 22.0), &no_block), RigActivity::kPickUp);
}

TEST(RigActivity, ALightHookIsInSlipsWhateverElse) {
  RigActivitySample row = Row(999.9, 20, 120);
  row.hook_load = 45 * kKlbf;  // below 50 klbf: only the block on the hook
  EXPECT_EQ(Classify(row), RigActivity::kInSlips);
  const RigActivitySample before = Row(990.0, 0, 0, 20.0);
  RigActivitySample moving = Row(990.0, 0, 0, 25.0);  // the block moving up in slips: not a pick-up
  moving.hook_load = 40 * kKlbf;
  EXPECT_EQ(Classify(moving, &before), RigActivity::kInSlips);
}

TEST(RigActivity, TheInSlipsHookLoadNeedsAGapInTheHookLoads) {
  // A tripping log: the lowest hook load 40 klbf (the block), the median 180 klbf: 1.2 x 40.
  EXPECT_DOUBLE_EQ(InSlipsHookLoad(40 * kKlbf, 180 * kKlbf), 48 * kKlbf);
  // A log all drilling (Volve F-5: 1250-1430 kN): no row in slips.
  EXPECT_EQ(InSlipsHookLoad(1250e3, 1330e3), 0.0);
}

TEST(RigActivity, ThresholdsAreTheirs) {
  RigActivityThresholds wide = Thresholds();
  wide.on_bottom_distance = 1.0;
  EXPECT_EQ(ClassifyRigActivity(Row(999.5, 20, 120), nullptr, wide), RigActivity::kDrilling);
  EXPECT_EQ(Classify(Row(999.5, 20, 120)), RigActivity::kRotatingOffBottom);
  wide.still_distance = 2.0;
  const RigActivitySample before = Row(990.0, 0, 0);
  EXPECT_EQ(ClassifyRigActivity(Row(989.0, 0, 0), &before, wide), RigActivity::kOther);
}

}  // namespace rig_activity_test
}  // namespace drillflex::io
