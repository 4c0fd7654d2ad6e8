// operation.hook_load instead of a WOB: the WOB is what a surface hook load leaves of the string's
// buoyed weight along the hole (with the pipe above the model, to the surface), and the model's top
// then carries the hook load less the pipe above. References by hand: open-ended tubes,
// w = g (ρ_s A_s − ρ_m A_o + ρ_m A_i) = g (ρ_s − ρ_m) π/4 (OD² − ID²), along a straight hole of
// constant inclination θ (TVD = MD cos θ).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "pipeline/case_run.hpp"
#include "core/error.hpp"
#include "io/case.hpp"

namespace drillflex::io {
namespace hook_load_test {

constexpr double kSteelDensity = 7850.0;  // kg/m³ (fe/material.hpp built-in steel)
constexpr double kMudDensity = 1200.0;    // kg/m³
constexpr double kGravity = 9.81;         // m/s²

double TubeWeightPerLength(double od, double id) {
  return kGravity * (kSteelDensity - kMudDensity) * kPi / 4.0 * (od * od - id * id);
}

// Collars and plain pipe (no tool joints) below the surface in a straight hole at `inclination_deg`,
// the bit at 1000 m MD.
std::string CaseText(double inclination_deg, const std::string& operation) {
  return fmt::format(R"(name: hook load
units: SI
well:
  survey: [[0, {0}, 0], [1200, {0}, 0]]
  hole: [{{diameter: 0.2159}}]
  bit_md: 1000
fluid: {{density: 1200}}
string:
  - {{type: collar, od: 0.1715, id: 0.0714, length: 9, count: 6}}
  - {{type: pipe, od: 0.127, id: 0.1086, length: 9, count: 10}}
model: {{body_length: 9}}
operation: {1}
)",
                     inclination_deg, operation);
}

struct Expected {
  double string_weight;  // the modelled string's buoyed weight along the hole, N
  double above_weight;   // the pipe above it, to the surface, N
};

Expected ByHand(double inclination_deg) {
  const double cosine = std::cos(inclination_deg * kPi / 180.0);
  const double collars = 54.0, pipe = 90.0;
  const double top_md = 1000.0 - collars - pipe;
  return {(TubeWeightPerLength(0.1715, 0.0714) * collars + TubeWeightPerLength(0.127, 0.1086) * pipe) * cosine,
          TubeWeightPerLength(0.127, 0.1086) * top_md * cosine};
}

TEST(HookLoad, SetsTheWobToTheBuoyedWeightAlongTheHoleLessTheHookLoad) {
  for (const double inclination : {0.0, 30.0}) {
    const double hook_load = 200e3;
    const Case c = ParseCase(CaseText(inclination, "{hook_load: 200 kN}"), "hook.yaml");
    const model::ModelInput& input = c.input;
    const Expected expected = ByHand(inclination);
    EXPECT_NEAR(model::StringAboveWeight(input), expected.above_weight, 1e-9 * expected.above_weight) << inclination;
    const double wob = expected.string_weight + expected.above_weight - hook_load;
    EXPECT_NEAR(input.operation.weight_on_bit, wob, 1e-9 * wob) << inclination;
  }
}

// The static equilibrium then holds the model's top with the hook load less the pipe above: the
// axial balance of a frictionless string (at rest) is exact, so the top support's reaction equals
// it to the solver's tolerance.
TEST(HookLoad, TheTopCarriesTheHookLoadLessThePipeAbove) {
  const double inclination = 30.0, hook_load = 200e3;
  const Case c = ParseCase(CaseText(inclination, "{hook_load: 200 kN}"), "hook.yaml");
  const pipeline::CaseResults run = pipeline::RunCase(c, pipeline::AnalysisRequest::Only(pipeline::Analysis::Static));
  const analyses::StaticResult& result = *run.static_result;
  ASSERT_TRUE(result.converged);
  const Expected expected = ByHand(inclination);
  const double top_tension = hook_load - expected.above_weight;
  ASSERT_EQ(result.reactions.size(), 2u);
  const analyses::SupportReaction& top = result.reactions.back();
  EXPECT_NEAR(top.s, 144.0, 1e-9);
  // The reaction on the string along it, up-hole: the pull of the pipe above.
  EXPECT_NEAR(top.force.x(), top_tension, 1e-4 * top_tension);
}

TEST(HookLoad, WithAWobOrMoreThanTheStringWeighsIsBadInput) {
  try {
    ParseCase(CaseText(0.0, "{wob: 50 kN, hook_load: 200 kN}"), "both.yaml");
    FAIL() << "a WOB and a hook load together were taken";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key_path(), "operation.hook_load");
    EXPECT_NE(std::string(error.what()).find("not both"), std::string::npos) << error.what();
  }
  try {
    ParseCase(CaseText(0.0, "{hook_load: 900 kN}"), "heavy.yaml");
    FAIL() << "a hook load above the string's weight was taken";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key_path(), "operation.hook_load");
    EXPECT_NE(std::string(error.what()).find("off bottom"), std::string::npos) << error.what();
  }
}

}  // namespace hook_load_test
}  // namespace drillflex::io
