// V7 of validation.md: torque and drag, the soft-string limit of the static analysis
// (validation/v7-torque-drag/): 10,000 ft of 5 in drill pipe modelled as a uniform pipe of buoyed
// weight w_b = 16.523 lb/ft with 6-5/8 in tool joints every 30 ft, in a straight 8-1/2 in hole at
// I = 60°, μ = 0.25, WOB 0, off bottom. About 1000 bodies (3 km).
// References (Johancsik et al. 1984, straight section, no axial motion):
//  * hook load = w_b L cos I = 82,615 lbf, within 1 % (static and rotating);
//  * rotating (60 rpm): Johancsik's torque μ w_b L sin I r_joint = 0.25 × 16.523 × 10,000 × sin 60° ×
//    3.3125/12 = 9,875 ft·lbf takes the wall normal force N = w_b sin I per length. A rotating pipe
//    climbs the wall until the normal force and the friction μN together carry the weight: the contact
//    sits atan μ = 14.04° off the low side (toward the right for clockwise rotation seen from above:
//    high-side angle 180° − 14.04° = 165.96°), N = w_b sin I / sqrt(1 + μ²), so the torque is
//    9,875 / sqrt(1.0625) = 9,580 ft·lbf, which drillflex's 3-D contact must give, within 2 %
//    (Johancsik's figure is 3.1 % above it, outside the 2 %). Every contact at 165.96° ± 1.5°.
// The run time is printed (not asserted: no timed tests).
#include <cmath>
#include <cstdio>

#include "v7_rotating.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace torque_drag_test {

TEST(V7TorqueDrag, CaseBuoyedWeightIsTheReferenceOne) {
  EXPECT_NEAR(V7CaseBuoyedWeight(), kBuoyedWeight, 1e-4 * kBuoyedWeight);
  // And the references follow from it: w_b L cos I, μ w_b L sin I r_joint.
  EXPECT_NEAR(kBuoyedWeight * 10000.0 * std::cos(60.0 * kDegree), kHookLoad, 0.5);
  EXPECT_NEAR(kFriction * kBuoyedWeight * 10000.0 * std::sin(60.0 * kDegree) * 6.625 / 24.0, kJohancsikTorque, 0.5);
}

TEST(V7TorqueDrag, StaticHookLoadWithinOnePercent) {
  const auto results = RunCaseTimed("static", "v7-torque-drag/pipe-60-deg-static.yaml");
  ASSERT_TRUE(results.contains("static"));
  EXPECT_TRUE(results["static"]["converged"].get<bool>());
  const auto& top = results["static"]["nodes"].back();
  const double hook = top["axial_force"].get<double>();
  EXPECT_LT(std::abs(RelativeError(hook, kHookLoad)), 0.01) << hook << " lbf";
  std::printf("V7 static: hook load %.1f lbf (reference %.0f, %+.3f %%), top torque %.2f ft*lbf\n", hook, kHookLoad,
              100.0 * RelativeError(hook, kHookLoad), top["torque"].get<double>());
}

// The full 10,000 ft (1016 bodies, twisted by 21 rad between the hook and the bit: the static
// solver's twist-keeping increment, model::SystemModel::IncrementKeepingShape, converges it in
// 15 Newton iterations, ~1 s; before it, 479 iterations and ~40 s, or not at all). Measured
// 2026-12-03: top torque 9,573.0 ft·lbf against 9,580 (−0.073 %), hook load 82,611 lbf (−0.005 %).
TEST(V7TorqueDrag, RotatingOffBottomTorqueWithinTwoPercent) {
  CheckRotatingOffBottom("v7-torque-drag/pipe-60-deg-rotating.yaml", 10000.0);
}

// The same pipe over 1000 ft (102 bodies).
TEST(V7TorqueDrag, RotatingOffBottomTorqueOf1000FtWithinTwoPercent) {
  CheckRotatingOffBottom("v7-torque-drag/pipe-60-deg-rotating-1000-ft.yaml", 1000.0);
}

}  // namespace torque_drag_test
}  // namespace drillflex::validation
