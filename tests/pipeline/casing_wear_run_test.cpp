// Casing wear over a run (pipeline/casing_wear_run.hpp) against a hand computation: pipe rotating in a
// straight cased hole at 30°, where the soft string's side force per length is the buoyed weight across
// the hole, w sin 30°, at every MD.
#include "pipeline/casing_wear_run.hpp"

#include <gtest/gtest.h>

namespace drillflex::pipeline {
namespace casing_wear_run_test {

// 5 in pipe (0.127 × 0.1086 m) with 6-5/8 in joints (0.1683 × 0.0826 m, 0.5 m every 9 m) in 0.2159 m casing
// (wall 10 mm) at 30°, 1200 kg/m³ mud, g 9.81, steel 7850 kg/m³: by hand (Python) w = 270.978595 N/m,
// F/L = w/2 = 135.489297 N/m; WF 5e-10 1/psi = 7.2519e-14 1/Pa, 120 rpm for 100 h: V/L = WF (F/L) π 0.1683 m
// · 2 /s · 360 000 s = 3.7404383e-6 m²; the groove of a 0.08415 m joint in a 0.10795 m bore wearing that
// area, by 400 000 slices: 2.1825318e-4 m.
TEST(CasingWearRun, StraightInclinedCasingByHand) {
  const io::Case c = io::ParseCase(R"(name: wear
units: SI
gravity: 9.81
well:
  survey: [[0, 30, 0], [400, 30, 0]]
  hole: [{diameter: 0.2159, cased: true, wall: 0.01}]
  bit_md: 297
fluid: {density: 1200}
string:
  - {type: pipe, od: 0.127, id: 0.1086, length: 9, count: 30, joint_od: 0.1683, joint_id: 0.0826, joint_length: 0.5}
operation: {rpm: 120}
limits: {wear: {factor: 5e-10 1/psi, rotating_time: 100 h}}
)",
                                   "wear.yaml");
  const CasingWear wear = ComputeCasingWear(c);
  EXPECT_EQ(wear.depths, 1);
  EXPECT_DOUBLE_EQ(wear.rotating_time, 360000.0);
  ASSERT_EQ(wear.stations.size(), 98u);  // every 10 ft from 0 to 297 m
  for (const CasingWearStation& station : wear.stations) {
    EXPECT_NEAR(station.side_force_per_length, 135.489297, 1e-5) << "MD " << station.md;
    EXPECT_NEAR(station.worn_area, 3.7404383e-6, 1e-12) << "MD " << station.md;
    EXPECT_NEAR(station.groove_depth, 2.1825318e-4, 1e-10) << "MD " << station.md;
    EXPECT_NEAR(station.remaining_wall, 0.01 - 2.1825318e-4, 1e-10);
    EXPECT_NEAR(station.wear_utilisation, 2.1825318e-2, 1e-8);
  }
}

}  // namespace casing_wear_run_test
}  // namespace drillflex::pipeline
