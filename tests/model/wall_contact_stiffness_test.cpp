// The wall contacts' stiffness (model/build_defaults.hpp WallContactStiffness): the wall's stiffness
// per metre × the circle's length, and for a tight contact at least the stiffness under which its
// section's weight over 30 ft sinks it by the case's fraction of its radial clearance. Hand values.
#include <gtest/gtest.h>

#include "model/build_defaults.hpp"

namespace drillflex::model {
namespace wall_contact_stiffness_test {

constexpr double kInch = 0.0254;

ContactSettings Settings(double fraction) {
  ContactSettings contact;
  contact.stiffness = 1e8;  // N/m per m
  contact.penetration_fraction = fraction;
  return contact;
}

// A 5 in pipe's body in an 8-1/2 in hole (c = 1.75 in): the wall's stiffness per metre holds.
TEST(WallContactStiffness, LooseContactTakesTheWallsStiffnessPerMetre) {
  EXPECT_DOUBLE_EQ(WallContactStiffness(Settings(0.02), 0.3048, 280.0, 1.75 * kInch, kContactWeightSpan), 1e8 * 0.3048);
}

// A stabilizer's blades with 1/32 in of clearance on an 8 in collar (1500 N/m buoyed): 1500 N/m ×
// 9.144 m / (0.02 × 0.79375 mm) = 8.64e8 N/m, 19 times the wall's 1e8 N/m a metre × 1.5 ft; the
// weight over 30 ft then sinks it by 2 % of its clearance.
TEST(WallContactStiffness, TightContactSinksTheGivenFractionOfItsClearanceUnderItsSpansWeight) {
  const double clearance = kInch / 32.0;
  const double k = WallContactStiffness(Settings(0.02), 0.4572, 1500.0, clearance, kContactWeightSpan);
  EXPECT_NEAR(k, 8.64e8, 1e-6 * 8.64e8);
  EXPECT_NEAR(1500.0 * 9.144 / k, 0.02 * clearance, 1e-15);
  // Buoyancy's sign does not matter (a string lighter than its mud still presses the wall somewhere).
  EXPECT_DOUBLE_EQ(WallContactStiffness(Settings(0.02), 0.4572, -1500.0, clearance, kContactWeightSpan), k);
}

// A full-gauge blade (no clearance) takes 1/64 in; a fraction of 0 turns the floor off.
TEST(WallContactStiffness, FullGaugeTakesTheLeastClearanceAndZeroFractionTurnsTheFloorOff) {
  EXPECT_NEAR(WallContactStiffness(Settings(0.02), 0.4572, 1500.0, 0.0, kContactWeightSpan), 1500.0 * 9.144 / (0.02 * kInch / 64.0),
              1e-3 * 1e9);
  EXPECT_DOUBLE_EQ(WallContactStiffness(Settings(0.0), 0.4572, 1500.0, 0.0, kContactWeightSpan), 1e8 * 0.4572);
}

// A body's circle carries its own length's share: the Wu rod's brass (0.67 N/m, 5 cm circles, 2.55 mm of
// clearance) needs 0.67 × 0.05 / (0.02 × 2.55e-3) = 657 N/m, far below its case's 3e5 N/m² × 5 cm.
TEST(WallContactStiffness, BodyCircleCarriesItsOwnLength) {
  ContactSettings soft = Settings(0.02);
  soft.stiffness = 3e5;
  EXPECT_DOUBLE_EQ(WallContactStiffness(soft, 0.05, 0.67, 2.55e-3, 0.05), 3e5 * 0.05);
  // The same circle as a point contact carrying 30 ft: 0.67 × 9.144 / (0.02 × 2.55e-3) = 1.20127e5 N/m.
  EXPECT_NEAR(WallContactStiffness(soft, 0.05, 0.67, 2.55e-3, kContactWeightSpan), 1.20127e5, 1.0);
}

}  // namespace wall_contact_stiffness_test
}  // namespace drillflex::model
