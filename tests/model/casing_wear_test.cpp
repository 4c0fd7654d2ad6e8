// Casing wear (model/casing_wear.hpp) against hand computations: White & Dawson's worn volume by hand, the
// groove's area and depth against an independent computation of the crescent (Python: the joint's circle
// outside the bore summed in 400 000 slices, not the lens formula drillflex uses).
#include "model/casing_wear.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "field_units.hpp"

namespace drillflex::model::test {
namespace casing_wear_test {

// WF 5e-10 1/psi (in²/lbf), 1000 lbf/ft on 6-5/8 in tool joints at 120 rpm for 100 h. By hand: the
// sliding distance π 6.625 in · 120 /min · 6000 min, V/L = 5e-10 · (1000/12 lbf/in) · that
// = 0.624392 in² (in³ per in of casing).
TEST(CasingWear, WornVolumeIsWearFactorTimesWork) {
  const double worn = WornVolumePerLength(5e-10 / kPsi, 1000.0 * kPoundForce / 0.3048, 6.625 * kInch,
                                          120.0 * 2.0 * kPi / 60.0, 100.0 * 3600.0);
  EXPECT_NEAR(worn / (kInch * kInch), 0.6243915, 1e-6);
}

// A 6-5/8 in joint (r 3.3125 in) in 9-5/8 in 40 lb/ft casing (bore 8.835 in, R 4.4175 in). By slices:
// the groove 0.1 in deep is 0.2084224 in²; 0.6243915 in² is a groove 0.2137739 in deep.
TEST(CasingWear, GrooveOfAJointInTheCasingBySlices) {
  const double bore = 4.4175 * kInch, joint = 3.3125 * kInch;
  EXPECT_NEAR(GrooveArea(bore, joint, 0.1 * kInch) / (kInch * kInch), 0.2084224, 1e-6);
  EXPECT_NEAR(GrooveDepth(bore, joint, 0.6243915 * kInch * kInch) / kInch, 0.2137739, 1e-6);
  EXPECT_DOUBLE_EQ(GrooveArea(bore, joint, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(GrooveDepth(bore, joint, 0.0), 0.0);
}

}  // namespace casing_wear_test
}  // namespace drillflex::model::test
