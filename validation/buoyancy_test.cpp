// V5 of validation.md, buoyancy (validation/v5-buoyancy/): 3000 ft of 5 in x 4.276 in pipe without
// tool joints, built-in steel, hanging in a vertical 8-1/2 in hole in 10 ppg mud, WOB 0: the bit
// carries nothing axially, so the hook carries the whole buoyed weight.
// Reference (Archimedes with separate annulus and bore fluids; method.md §7): hook load
// = g L (ρ_s A − ρ_f A_o + ρ_i A_i); with one fluid (ρ_i = ρ_f) that is the weight in air × (1 − ρ_f/ρ_s).
// The built-in steel is 7850 kg/m³ = 65.511 ppg, so 10 ppg gives 0.847355 (validation.md: 0.8473 with
// 65.5 ppg steel). Tolerance 0.1 % on the top node's axial force and on the hook's reaction.
#include <cmath>
#include <cstdio>

#include "fe/material.hpp"
#include "field_units.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace buoyancy_test {

constexpr double kLength = 3000.0;  // ft
constexpr double kOd = 5.0, kId = 4.276;  // in
constexpr double kMudPpg = 10.0;

// Hook load (lbf) of the hanging string with ρ_i inside (ppg).
double HookLoadReference(double internal_ppg) {
  const double steel = fe::Steel().density;
  const double ppg = kKgPerCubicMetrePerPpg;
  const double area = CircleArea(kOd) - CircleArea(kId);
  return kLength * (PoundsPerFoot(area, steel) - PoundsPerFoot(CircleArea(kOd), kMudPpg * ppg) +
                    PoundsPerFoot(CircleArea(kId), internal_ppg * ppg));
}

TEST(V5Buoyancy, BuiltInSteelGivesTheHandbookBuoyancyFactor) {
  const double steel_ppg = fe::Steel().density / kKgPerCubicMetrePerPpg;
  EXPECT_NEAR(steel_ppg, 65.5, 0.05);  // 65.511 ppg
  const double factor = 1.0 - kMudPpg / steel_ppg;
  EXPECT_NEAR(factor, 0.8473, 1e-4);  // 0.847355
  std::printf("built-in steel %.1f kg/m3 = %.4f ppg; buoyancy factor in 10 ppg mud %.6f\n", fe::Steel().density,
              steel_ppg, factor);
}

struct BuoyancyCase {
  const char* file;
  double internal_ppg;
};

class V5HangingString : public ::testing::TestWithParam<BuoyancyCase> {};

TEST_P(V5HangingString, HookLoadIsTheBuoyedWeightWithinPointOnePercent) {
  const BuoyancyCase c = GetParam();
  const auto results = RunCase("static", std::string("v5-buoyancy/") + c.file);
  ASSERT_TRUE(results.contains("static"));
  const auto& statics = results["static"];
  EXPECT_TRUE(statics["converged"].get<bool>());
  const double reference = HookLoadReference(c.internal_ppg);
  if (c.internal_ppg == kMudPpg) {
    // One fluid: the same number written as weight in air × (1 − ρ_f/ρ_s).
    const double steel = fe::Steel().density;
    const double in_air = kLength * PoundsPerFoot(CircleArea(kOd) - CircleArea(kId), steel);
    EXPECT_NEAR(reference, in_air * (1.0 - kMudPpg * kKgPerCubicMetrePerPpg / steel), 1e-9 * in_air);
  }
  const double top_axial = statics["nodes"].back()["axial_force"].get<double>();
  EXPECT_LT(std::abs(RelativeError(top_axial, reference)), 0.001) << top_axial << " lbf against " << reference;
  // The hook: the support at the top of the string; its axial reaction holds the string up-hole.
  const double length = statics["nodes"].back()["s"].get<double>();
  double hook = 0.0;
  for (const auto& reaction : statics["reactions"]) {
    if (std::abs(reaction["s"].get<double>() - length) < 1.0) hook = reaction["force"][0].get<double>();
  }
  EXPECT_LT(std::abs(RelativeError(hook, reference)), 0.001) << hook << " lbf against " << reference;
  std::printf("%s: reference %.2f lbf, top axial force %.2f (%+.4f %%), hook reaction %.2f (%+.4f %%)\n", c.file,
              reference, top_axial, 100.0 * RelativeError(top_axial, reference), hook,
              100.0 * RelativeError(hook, reference));
}

// Tool joints are steel too: 6-5/8 in x 3-1/4 in joints, 18 in of every 30 ft, add their weight.
// Reference: hook load = g L (ρ_s − ρ_f) A_m, A_m = (28.5 A_body + 1.5 A_joint) / 30 = 6.319681 in².
TEST(V5Buoyancy, ToolJointsAddTheirWeightToTheHookLoad) {
  const auto results = RunCase("static", "v5-buoyancy/vertical-tool-joints.yaml");
  ASSERT_TRUE(results.contains("static"));
  const auto& statics = results["static"];
  EXPECT_TRUE(statics["converged"].get<bool>());
  const double body = CircleArea(kOd) - CircleArea(kId);
  const double joint = CircleArea(6.625) - CircleArea(3.25);
  const double area = (28.5 * body + 1.5 * joint) / 30.0;
  const double reference = kLength * PoundsPerFoot(area, fe::Steel().density - kMudPpg * kKgPerCubicMetrePerPpg);
  const double top_axial = statics["nodes"].back()["axial_force"].get<double>();
  EXPECT_LT(std::abs(RelativeError(top_axial, reference)), 0.001) << top_axial << " lbf against " << reference;
  std::printf("vertical-tool-joints.yaml: reference %.2f lbf, top axial force %.2f (%+.4f %%); without the joints' "
              "weight it would be %.2f\n",
              reference, top_axial, 100.0 * RelativeError(top_axial, reference), reference * body / area);
}

INSTANTIATE_TEST_SUITE_P(Validation, V5HangingString,
                         ::testing::Values(BuoyancyCase{"vertical-10-ppg.yaml", 10.0},
                                           BuoyancyCase{"vertical-internal-14-ppg.yaml", 14.0},
                                           BuoyancyCase{"vertical-internal-empty.yaml", 0.0}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.size() - 5);
                           for (char& ch : name) if (ch == '-') ch = '_';
                           return name;
                         });

}  // namespace buoyancy_test
}  // namespace drillflex::validation
