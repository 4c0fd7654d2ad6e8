// Issue 4 acceptance: a long uniform pipe on the low side of a straight inclined hole
// (validation/v4-long-pipe/pipe-60-deg.yaml): 3000 ft of 5 in x 4.276 in drill pipe without tool joints,
// built-in steel, 8-1/2 in hole at I = 60°, 10.5 ppg mud, WOB 0, rpm 0.
// Reference (statics of a straight hole, no friction without motion): the hole axis is straight, so
// the lateral part of the weight, w_b L sin I, is carried by the wall contacts and the bit support
// alone (the hook holds only the axial direction): Σ N + bit side force = w_b L sin I; the weight
// pulls the pipe to the low side, every contact at a high-side angle of 180°; the axial part
// w_b L cos I is carried by the hook (the bit carries WOB = 0): top axial force = w_b L cos I.
// w_b = g A (ρ_s − ρ_f) (Archimedes; method.md §7), ρ_s of the built-in steel.
#include <cmath>

#include "fe/material.hpp"
#include "field_units.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace long_pipe_test {

constexpr double kLength = 3000.0;          // ft
constexpr double kInclination = 60.0;       // deg
constexpr double kMudPpg = 10.5;

double BuoyedWeightPerFoot() {
  const double area = CircleArea(5.0) - CircleArea(4.276);
  const double steel = fe::Steel().density;  // 7850 kg/m³
  return PoundsPerFoot(area, steel - kMudPpg * kKgPerCubicMetrePerPpg);  // 15.0734 lbf/ft
}

TEST(V4LongPipe, WallAndBitCarryTheLateralWeightOnTheLowSideAndTheHookTheAxialWeight) {
  const auto results = RunCase("static", "v4-long-pipe/pipe-60-deg.yaml");
  ASSERT_TRUE(results.contains("static"));
  const auto& statics = results["static"];
  EXPECT_TRUE(statics["converged"].get<bool>());
  const double w_b = BuoyedWeightPerFoot();
  const double inclination = kInclination * kPi / 180.0;

  const auto& contacts = statics["contacts"];
  ASSERT_FALSE(contacts.empty());
  double normal_sum = 0.0;
  for (const auto& contact : contacts) {
    normal_sum += contact["normal_force"].get<double>();
    EXPECT_NEAR(contact["high_side_angle"].get<double>(), 180.0, 1.0) << contact;
  }
  const double bit_side = statics["bit"]["side_force"].get<double>();
  const double lateral = normal_sum + bit_side;
  const double lateral_reference = w_b * kLength * std::sin(inclination);  // 39 162 lbf
  EXPECT_LT(std::abs(RelativeError(lateral, lateral_reference)), 0.005)
      << "sum N " << normal_sum << " + bit " << bit_side << " lbf against " << lateral_reference;

  const double top_axial = statics["nodes"].back()["axial_force"].get<double>();
  const double axial_reference = w_b * kLength * std::cos(inclination);  // 22 610 lbf
  EXPECT_LT(std::abs(RelativeError(top_axial, axial_reference)), 0.005)
      << "top axial force " << top_axial << " lbf against " << axial_reference;
  std::printf("V4 long pipe: %zu contacts, sum N %.2f + bit %.2f = %.2f lbf (reference %.2f, %+.4f %%); "
              "top axial %.2f lbf (reference %.2f, %+.4f %%)\n",
              contacts.size(), normal_sum, bit_side, lateral, lateral_reference,
              100.0 * RelativeError(lateral, lateral_reference), top_axial, axial_reference,
              100.0 * RelativeError(top_axial, axial_reference));
}

}  // namespace long_pipe_test
}  // namespace drillflex::validation
