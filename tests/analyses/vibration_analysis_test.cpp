// The forced response (analyses/vibration_analysis.hpp) on the V1 rod, pinned-pinned: linearity
// and superposition, the decoupling of axial and lateral motion in a straight rod, the static
// limit far below resonance, and the motor's speed from the flow.
#include "analyses/vibration_analysis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analyses_test_support.hpp"
#include "core/error.hpp"

namespace drillflex::analyses {
namespace vibration_analysis_test {

using testing::SupportAt;

struct PinnedRod {
  model::ModelInput input = testing::V1Rod();
  cms::ReductionCache cache;
  model::BuiltModel built;
  model::LateralFluid fluid;

  PinnedRod() : built(Build()) {}
  model::BuiltModel Build() {
    input.supports = {SupportAt(0.0, {model::kX, model::kY, model::kZ, model::kRx}),
                      SupportAt(testing::kRodLength, {model::kY, model::kZ})};
    return model::BuildSystemModel(input, cache);
  }
  VibrationResult Run(const VibrationSettings& settings) {
    return RunVibration(built, input, fluid, built.system.ReferencePositions(), settings);
  }
};

Excitation Imbalance(double at, double me) {
  Excitation e;
  e.type = ExcitationType::Imbalance;
  e.at = at;
  e.imbalance = me;
  return e;
}

VibrationSettings Sweep(std::vector<Excitation> excitations, double from_rpm, double to_rpm, double step_rpm) {
  VibrationSettings settings;
  settings.speed_from = from_rpm * kPi / 30.0;
  settings.speed_to = to_rpm * kPi / 30.0;
  settings.speed_step = step_rpm * kPi / 30.0;
  settings.excitations = std::move(excitations);
  return settings;
}

TEST(VibrationAnalysis, ResponsesAreLinearAndExcitationsAtOneFrequencySuperpose) {
  PinnedRod rod;
  const double mid = 0.5 * testing::kRodLength;
  const VibrationResult one = rod.Run(Sweep({Imbalance(mid, 0.01)}, 100, 3000, 100));
  const VibrationResult doubled = rod.Run(Sweep({Imbalance(mid, 0.02)}, 100, 3000, 100));
  const VibrationResult pair = rod.Run(Sweep({Imbalance(mid, 0.01), Imbalance(mid, 0.01)}, 100, 3000, 100));
  ASSERT_EQ(one.rotary_speeds.size(), 30u);
  for (std::size_t i = 0; i < one.rotary_speeds.size(); ++i) {
    const double x = one.max_lateral_displacement[i];
    EXPECT_NEAR(doubled.max_lateral_displacement[i], 2.0 * x, 1e-10 * x);
    EXPECT_NEAR(pair.max_lateral_displacement[i], 2.0 * x, 1e-8 * x);  // two solves added: round-off
    EXPECT_NEAR(doubled.max_bending_stress[i], 2.0 * one.max_bending_stress[i], 1e-10 * one.max_bending_stress[i]);
  }
  EXPECT_TRUE(one.max_clearance_ratio.empty());  // no well
  EXPECT_EQ(one.closed_contacts, 0);
}

// One curve per excitation: alone, an excitation's curve is the sweep's largest displacement; with a
// bit excitation at 3× beside the imbalance (other frequencies: two responses added station by
// station), each curve is its own response's and none exceeds the sum's largest.
TEST(VibrationAnalysis, EachExcitationHasItsOwnCurve) {
  PinnedRod rod;
  const double mid = 0.5 * testing::kRodLength;
  // Solved directly (a sparse LU per frequency), so that the three sweeps solve the same equations
  // (a reduced basis is built from the sweep's own excitations).
  const auto direct = [](VibrationSettings settings) {
    settings.method = VibrationMethod::Direct;
    return settings;
  };
  const VibrationResult one = rod.Run(direct(Sweep({Imbalance(mid, 0.01)}, 100, 3000, 100)));
  ASSERT_EQ(one.excitation_displacement.size(), 1u);
  ASSERT_EQ(one.excitation_displacement[0].size(), one.rotary_speeds.size());
  for (std::size_t i = 0; i < one.rotary_speeds.size(); ++i) {
    EXPECT_NEAR(one.excitation_displacement[0][i], one.max_lateral_displacement[i], 1e-12 * one.max_lateral_displacement[i]);
  }
  Excitation bit;
  bit.type = ExcitationType::Bit;
  bit.harmonic = 3;
  bit.lateral = 50.0;
  const VibrationResult both = rod.Run(direct(Sweep({Imbalance(mid, 0.01), bit}, 100, 3000, 100)));
  ASSERT_EQ(both.excitation_displacement.size(), 2u);
  const VibrationResult bit_alone = rod.Run(direct(Sweep({bit}, 100, 3000, 100)));
  // The same responses to round-off (the bit's lateral force acts at the pinned end: its response is
  // small, compared against the sweep's largest).
  const double scale = *std::max_element(one.max_lateral_displacement.begin(), one.max_lateral_displacement.end());
  for (std::size_t i = 0; i < both.rotary_speeds.size(); ++i) {
    const double imbalance = one.max_lateral_displacement[i], alone = bit_alone.max_lateral_displacement[i];
    EXPECT_NEAR(both.excitation_displacement[0][i], imbalance, 1e-9 * scale) << i;
    EXPECT_NEAR(both.excitation_displacement[1][i], alone, 1e-9 * scale) << i;
    EXPECT_LE(std::max(both.excitation_displacement[0][i], both.excitation_displacement[1][i]),
              both.max_lateral_displacement[i] * (1.0 + 1e-12)) << i;
  }
}

TEST(VibrationAnalysis, FarBelowResonanceTheWhirlIsTheStaticDeflection) {
  // At Ω ≪ ω₁ the rotating force m e Ω² deflects the rod as a static load: the mid-span deflection of
  // a pinned-pinned beam under a central force P is P L³/(48 EI) (any strength-of-materials text).
  PinnedRod rod;
  const double mid = 0.5 * testing::kRodLength, me = 0.01;
  const VibrationResult result = rod.Run(Sweep({Imbalance(mid, me)}, 10, 10, 1));
  const double omega = 10.0 * kPi / 30.0;
  const double ei = 2.1e11 * testing::RodSecondMoment();
  const double reference = me * omega * omega * std::pow(testing::kRodLength, 3) / (48.0 * ei);
  // ω₁ of the rod ≈ 2π × 51 Hz: (Ω/ω₁)² ≈ 4e-6, the dynamic amplification is negligible.
  EXPECT_NEAR(result.max_lateral_displacement[0], reference, 1e-3 * reference);
  EXPECT_NEAR(result.s_max_displacement[0], mid, 1e-9);
  // Bending stress there: M c / I = (P L/4)(D/2)/I.
  const double stress = me * omega * omega * testing::kRodLength / 4.0 * (0.5 * testing::kRodDiameter) /
                        testing::RodSecondMoment();
  EXPECT_NEAR(result.max_bending_stress[0], stress, 0.03 * stress);  // element-mean curvature near the load
}

TEST(VibrationAnalysis, AnAxialBitForceMovesAStraightRodOnlyAlongItsAxis) {
  PinnedRod rod;
  Excitation bit;
  bit.type = ExcitationType::Bit;
  bit.harmonic = 3;
  bit.axial = 1000.0;
  const VibrationResult axial = rod.Run(Sweep({bit}, 100, 500, 200));
  ASSERT_EQ(axial.rotary_speeds.size(), 3u);
  for (std::size_t i = 0; i < axial.rotary_speeds.size(); ++i) {
    EXPECT_LT(axial.max_lateral_displacement[i], 1e-12);
    EXPECT_LT(axial.max_bending_stress[i], 1e-3);  // Pa
  }
}

// A case without excitations gets an imbalance at 1× at the middle of its first MWD or LWD, else of its
// BHA (below the first drill pipe or HWDP; the whole string without one), and the bit at 3×.
TEST(VibrationAnalysis, DefaultExcitationsSitAtTheMwdOrTheMiddleOfTheBha) {
  auto component = [](model::ComponentType type, double length, int count = 1) {
    model::Component c;
    c.type = type;
    c.length = length;
    c.count = count;
    return c;
  };
  using model::ComponentType;
  model::StringConfig string;
  string.components = {component(ComponentType::Bit, 0.3), component(ComponentType::Collar, 9.0, 2),
                       component(ComponentType::Mwd, 10.0), component(ComponentType::Pipe, 9.0, 30)};
  std::vector<Excitation> defaults = DefaultExcitations(string);
  ASSERT_EQ(defaults.size(), 2u);
  EXPECT_EQ(defaults[0].type, ExcitationType::Imbalance);
  EXPECT_DOUBLE_EQ(defaults[0].at, 0.3 + 18.0 + 5.0);  // the MWD's middle
  EXPECT_DOUBLE_EQ(defaults[0].imbalance, kDefaultImbalance);
  EXPECT_EQ(defaults[1].type, ExcitationType::Bit);
  EXPECT_EQ(defaults[1].harmonic, 3);
  EXPECT_NEAR(defaults[1].lateral, 500.0 * 4.4482216152605, 1e-3);
  EXPECT_NEAR(defaults[1].axial, 1000.0 * 4.4482216152605, 1e-3);
  EXPECT_NEAR(defaults[1].torsional, 200.0 * 1.3558179483314004, 1e-3);
  string.components[2].type = ComponentType::Collar;  // no MWD: the BHA's middle, (0.3 + 18 + 10) / 2
  EXPECT_DOUBLE_EQ(DefaultExcitations(string)[0].at, 0.5 * 28.3);
  string.components.pop_back();  // no pipe: the whole string's middle
  EXPECT_DOUBLE_EQ(DefaultExcitations(string)[0].at, 0.5 * 28.3);
  string.components.push_back(component(ComponentType::Hwdp, 9.0, 3));
  string.components.push_back(component(ComponentType::Lwd, 9.0));  // above the HWDP: not the BHA's
  EXPECT_DOUBLE_EQ(DefaultExcitations(string)[0].at, 0.5 * 28.3);
}

TEST(VibrationAnalysis, MotorSpeedComesFromTheFlowOrIsGiven) {
  model::ModelInput input = testing::V1Rod();
  model::Component motor = input.string.components[0];
  motor.type = model::ComponentType::Motor;
  motor.speed_per_flow = 2.0 * kPi * 0.1 / 3.785411784e-3;  // 0.1 rev/gal
  motor.lobes = 5;
  input.string.components[0] = motor;
  input.operation.flow_rate = 500.0 * 3.785411784e-3 / 60.0;  // 500 gpm
  Excitation e;
  e.type = ExcitationType::Motor;
  e.lateral = 100.0;
  // 500 gpm × 0.1 rev/gal = 50 rev/min.
  EXPECT_NEAR(MotorSpeed(e, input, 0), 50.0 * kPi / 30.0, 1e-12);
  e.lobes = 4;
  EXPECT_NEAR(ExcitationFrequency(e, 7.0, 2.0), 8.0, 1e-12);  // lobes × rotor speed, not the RPM
  e.motor_speed = 3.0;
  EXPECT_NEAR(MotorSpeed(e, input, 0), 3.0, 1e-15);
  e.motor_speed.reset();
  input.operation.flow_rate.reset();
  EXPECT_THROW(MotorSpeed(e, input, 0), InputError);
}

}  // namespace vibration_analysis_test
}  // namespace drillflex::analyses
