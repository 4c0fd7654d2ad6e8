// The transient analysis (analyses/transient_analysis.hpp) on the V1 cantilever with 2 bodies:
// the start from the equilibrium under initial loads, the samples and their times, the probe
// signals (lateral displacement, whirl angle, bending moment), the energy, a rest that stays rest, and the
// frames of the whole state kept at every k-th sample (state_frames) without changing the run.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analyses/static_analysis.hpp"
#include "analyses/transient_analysis.hpp"
#include "analyses_test_support.hpp"
#include "cms/reduction_cache.hpp"
#include "core/error.hpp"

namespace drillflex::analyses {
namespace transient_analysis_test {

using testing::ClampAt;
using testing::PointLoad;

model::ModelInput Cantilever() {
  model::ModelInput input = testing::RodInput(2, 2.1e11, 7800.0);
  input.settings.structural_damping = 0.0;
  input.supports = {ClampAt(0.0)};
  return input;
}

// The cantilever built, with its reductions; the initial loads a transient releases it from, if
// any, in its model as their load group (model::ModelInput::initial_loads).
model::ModelInput CantileverWith(std::vector<model::Load> initial_loads) {
  model::ModelInput input = Cantilever();
  input.initial_loads = std::move(initial_loads);
  return input;
}

struct BuiltCantilever {
  explicit BuiltCantilever(std::vector<model::Load> initial_loads = {})
      : input(CantileverWith(std::move(initial_loads))), built(model::BuildSystemModel(input, cache)) {}
  model::ModelInput input;
  cms::ReductionCache cache;
  model::BuiltModel built;
};

double TipDeflection(double force) {
  return force * std::pow(testing::kRodLength, 3) / (3.0 * 2.1e11 * testing::RodSecondMoment());
}

TEST(TransientAnalysis, ReleasedCantileverSwingsThroughZeroWithItsEnergy) {
  const std::vector<model::Load> initial = {PointLoad(testing::kRodLength, Vec3(0.0, 100.0, 0.0))};  // toward +y
  BuiltCantilever cantilever(initial);
  const model::BuiltModel& built = cantilever.built;
  TransientSettings settings;
  settings.duration = 0.25;  // about half a period of 1/2.1434 Hz
  settings.output_interval = 0.01;
  settings.time_step = 5e-4;
  settings.rho_infinity = 1.0;
  settings.tolerance = 1e-8;
  settings.probes = {testing::kRodLength, 0.0};
  settings.initial_loads = initial;  // toward +y, right
  const VecX start = TransientStartPositions(cantilever.input, built, settings, StaticSettings{});
  const TransientResult result = RunTransient(built, start, settings);
  ASSERT_EQ(result.samples.size(), 26u);
  EXPECT_NEAR(result.samples.back().time, 0.25, 1e-12);
  EXPECT_NEAR(result.samples[7].time, 0.07, 1e-12);
  EXPECT_NEAR(result.probe_s[0], testing::kRodLength, 1e-9);
  const ProbeSample& released = result.samples.front().probes[0];
  // Released from P L³/(3EI) to the right: whirl angle 90° (high side 0°, right 90°).
  EXPECT_NEAR(released.lateral_y, TipDeflection(100.0), 1e-3 * TipDeflection(100.0));
  EXPECT_NEAR(released.lateral_z, 0.0, 1e-9);
  EXPECT_NEAR(released.whirl_angle, kPi / 2.0, 1e-6);
  // At the root the moment is P L at the start, and the tip swings through zero to the left
  // (270°) by half a period (0.233 s).
  EXPECT_NEAR(result.samples.front().probes[1].bending_moment, 100.0 * testing::kRodLength, 5e-3 * 508.0);
  const ProbeSample& swung = result.samples.back().probes[0];
  EXPECT_LT(swung.lateral_y, -0.9 * TipDeflection(100.0));
  EXPECT_NEAR(swung.whirl_angle, 1.5 * kPi, 1e-3);
  // Energy: the strain energy ½ P δ at the start, all kinetic near the quarter period (0.117 s).
  const double swing = 0.5 * 100.0 * TipDeflection(100.0);
  EXPECT_NEAR(result.samples.front().potential_energy, swing, 2e-3 * swing);
  EXPECT_GT(result.samples[12].kinetic_energy, 0.95 * swing);
  EXPECT_LT(result.energy_drift, 1e-5);
  EXPECT_EQ(result.statistics.steps, 500);
  // No drive and no spin: the surface and bit speeds stay zero.
  EXPECT_NEAR(result.samples.back().surface_speed, 0.0, 1e-6);
}

TEST(TransientAnalysis, RestAtTheEquilibriumStaysAtRest) {
  BuiltCantilever cantilever;
  const model::BuiltModel& built = cantilever.built;
  TransientSettings settings;
  settings.duration = 0.05;
  settings.output_interval = 0.02;  // samples at 0, 0.02, 0.04 and the duration 0.05
  settings.start = TransientStart::Reference;
  settings.probes = {2.0};
  const VecX start = TransientStartPositions(cantilever.input, built, settings, StaticSettings{});
  const TransientResult result = RunTransient(built, start, settings);
  ASSERT_EQ(result.samples.size(), 4u);
  EXPECT_NEAR(result.samples.back().time, 0.05, 1e-15);
  for (const TransientSample& sample : result.samples) {
    EXPECT_LT(std::abs(sample.probes[0].lateral_y) + std::abs(sample.probes[0].lateral_z), 1e-12);
    EXPECT_LT(sample.kinetic_energy, 1e-20);
  }
  EXPECT_LT((result.final_q - built.system.ReferencePositions()).norm(), 1e-12);
}

// TransientSettings::state_frames: the whole state at every k-th output sample from t = 0 and at the
// end, at most that many; the run otherwise the same to the bit.
TEST(TransientAnalysis, StateFramesKeepEveryKthSampleFromTheStartAndTheEndWithoutChangingTheRun) {
  const std::vector<model::Load> initial = {PointLoad(testing::kRodLength, Vec3(0.0, 100.0, 0.0))};
  BuiltCantilever cantilever(initial);
  const model::BuiltModel& built = cantilever.built;
  TransientSettings settings;
  settings.duration = 0.1;
  settings.output_interval = 0.01;  // 11 samples
  settings.time_step = 5e-4;
  settings.probes = {testing::kRodLength};
  settings.initial_loads = initial;
  const VecX start = TransientStartPositions(cantilever.input, built, settings, StaticSettings{});
  const TransientResult plain = RunTransient(built, start, settings);
  EXPECT_TRUE(plain.frame_times.empty());  // state_frames = 0 by default: no frames kept
  EXPECT_TRUE(plain.frame_q.empty());

  settings.state_frames = 5;  // every 3rd sample (⌈10 / 4⌉) and the last
  const TransientResult framed = RunTransient(built, start, settings);
  ASSERT_EQ(framed.frame_times.size(), 5u);
  ASSERT_EQ(framed.frame_q.size(), 5u);
  const std::vector<int> kept = {0, 3, 6, 9, 10};
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const TransientSample& sample = framed.samples[kept[i]];
    EXPECT_EQ(framed.frame_times[i], sample.time) << "frame " << i;
    // The frame's tip is where the sample's probe read it.
    const StaticNodeResult tip = StaticNodeResults(built, framed.frame_q[i]).back();
    EXPECT_DOUBLE_EQ(tip.displacement.y(), sample.probes[0].lateral_y) << "frame " << i;
  }
  EXPECT_EQ(framed.frame_times.front(), 0.0);
  EXPECT_EQ(framed.frame_times.back(), 0.1);
  EXPECT_EQ(framed.frame_q.front(), start);
  EXPECT_EQ(framed.frame_q.back(), framed.final_q);
  EXPECT_GT(std::abs(framed.samples[3].probes[0].lateral_y - framed.samples[0].probes[0].lateral_y), 1e-4);  // moving

  // The run itself is unchanged.
  ASSERT_EQ(framed.samples.size(), plain.samples.size());
  for (std::size_t k = 0; k < plain.samples.size(); ++k) {
    EXPECT_EQ(framed.samples[k].time, plain.samples[k].time);
    EXPECT_EQ(framed.samples[k].probes[0].lateral_y, plain.samples[k].probes[0].lateral_y);
    EXPECT_EQ(framed.samples[k].probes[0].bending_moment, plain.samples[k].probes[0].bending_moment);
    EXPECT_EQ(framed.samples[k].kinetic_energy, plain.samples[k].kinetic_energy);
  }
  EXPECT_EQ(framed.final_q, plain.final_q);
  EXPECT_EQ(framed.final_v, plain.final_v);
  EXPECT_EQ(framed.statistics.steps, plain.statistics.steps);

  // More frames than samples: every sample; one frame: the end only.
  settings.state_frames = 100;
  EXPECT_EQ(RunTransient(built, start, settings).frame_q.size(), 11u);
  settings.state_frames = 1;
  const TransientResult last = RunTransient(built, start, settings);
  ASSERT_EQ(last.frame_times.size(), 1u);
  EXPECT_EQ(last.frame_times[0], 0.1);
  settings.state_frames = -1;
  EXPECT_THROW(RunTransient(built, start, settings), LogicError);
}

TEST(TransientAnalysis, IntegratorOptionsFollowTheSettings) {
  TransientSettings settings;
  settings.tolerance = 1e-6;
  settings.output_interval = 0.5;
  const solvers::GeneralizedAlphaOptions adaptive = TransientIntegratorOptions(settings);
  EXPECT_TRUE(adaptive.adaptive);
  EXPECT_DOUBLE_EQ(adaptive.initial_step, 1e-4);
  EXPECT_DOUBLE_EQ(adaptive.relative_tolerance, 1e-6);
  EXPECT_DOUBLE_EQ(adaptive.absolute_tolerance, 1e-9);
  settings.time_step = 2e-3;
  settings.rho_infinity = 0.5;
  const solvers::GeneralizedAlphaOptions fixed = TransientIntegratorOptions(settings);
  EXPECT_FALSE(fixed.adaptive);
  EXPECT_DOUBLE_EQ(fixed.initial_step, 2e-3);
  EXPECT_DOUBLE_EQ(fixed.rho_infinity, 0.5);
}

}  // namespace transient_analysis_test
}  // namespace drillflex::analyses
