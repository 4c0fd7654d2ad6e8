// The string's limits at every sample of a transient (analyses/limits_envelope.hpp) on the V1 rod
// (solid, D 3 in, L 200 in, 2 bodies), clamped at s = 0, against hand computations: held at its static
// equilibrium under a tip tension and torque, the von Mises and torque utilisations of every station at
// every sample; released from rest under a suddenly applied tip tension, the largest axial utilisation
// about twice the static one (the stress wave doubled by its reflection at the clamp), reached between the
// wave's arrival and its return (L/c to 3 L/c), and read at every sample with no VTK frames kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analyses/limits_envelope.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/transient_analysis.hpp"
#include "analyses_test_support.hpp"
#include "cms/reduction_cache.hpp"

namespace drillflex::analyses {
namespace limits_envelope_test {

using testing::ClampAt;
using testing::PointLoad;

constexpr double kYield = 500e6;          // Pa, given
constexpr double kMakeupTorque = 20e3;    // N·m, given
constexpr double kDesignFactor = 1.25;
constexpr double kTension = 200e3;        // N at the tip
constexpr double kTorque = 5e3;           // N·m at the tip

// The rod clamped at s = 0, without damping, rated (yield, make-up torque), under `loads`.
model::ModelInput RatedRod(std::vector<model::Load> loads, int bodies = 2) {
  model::ModelInput input = testing::RodInput(bodies, 2.1e11, 7800.0);
  input.settings.structural_damping = 0.0;
  input.supports = {ClampAt(0.0)};
  input.loads = std::move(loads);
  input.string.components[0].yield_strength = kYield;
  input.string.components[0].makeup_torque = kMakeupTorque;
  return input;
}

struct LimitsRun {
  LimitsEnvelope envelope;
  TransientResult result;
};

LimitsRun RunWithLimits(const model::ModelInput& input, const TransientSettings& settings) {
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const VecX start = TransientStartPositions(input, built, settings, StaticSettings{});
  LimitsRecorder recorder(input, built, kDesignFactor);
  LimitsRun run;
  run.result = RunTransient(built, start, settings, {},
                            [&recorder](double time, const VecX& q, const VecX&) { recorder.Read(time, q); });
  run.envelope = recorder.envelope();
  return run;
}

// Held at its equilibrium: N = 200 kN and T = 5 kN·m all along. By hand: A = π/4 · 0.0762² = 4.560367e-3 m²,
// J = π/32 · 0.0762⁴ = 3.309937e-6 m⁴, σ = N/A = 43.85612 MPa, τ = T (D/2)/J = 57.55396 MPa,
// σ_vm = √(σ² + 3τ²) = 108.9070 MPa against 500/1.25 = 400 MPa: 0.2722675; the torque 5/20 = 0.25.
TEST(LimitsEnvelope, HeldUnderTensionAndTorqueByHand) {
  const model::ModelInput input = RatedRod({PointLoad(testing::kRodLength, Vec3(kTension, 0.0, 0.0),
                                                      Vec3(kTorque, 0.0, 0.0))});
  TransientSettings settings;
  settings.duration = 0.01;
  settings.output_interval = 0.002;
  settings.state_frames = 0;
  const LimitsRun run = RunWithLimits(input, settings);
  const double area = kPi / 4.0 * std::pow(testing::kRodDiameter, 2);
  const double polar = kPi / 32.0 * std::pow(testing::kRodDiameter, 4);
  const double sigma = kTension / area, tau = kTorque * 0.5 * testing::kRodDiameter / polar;
  const double stress = std::sqrt(sigma * sigma + 3.0 * tau * tau) / (kYield / kDesignFactor);
  EXPECT_NEAR(stress, 0.2722675, 1e-6);  // the hand figures above
  ASSERT_EQ(run.envelope.times.size(), run.result.samples.size());
  ASSERT_EQ(run.envelope.times.size(), 6u);
  EXPECT_TRUE(run.result.frame_q.empty());
  ASSERT_FALSE(run.envelope.stations.empty());
  // Every station but the tip's (its section forces are the last element's, half an element in). The
  // model's section torque (analyses::StaticNodeResults, the static's too) reads between the load's and
  // 1/cos φ of it, φ the relative twist of the two bodies' frames: the couplings measure a relative rotation
  // by sin φ, and carry T/cos φ for T (tests/analyses/internal_forces_test.cpp: φ = (T/cos φ) L_b/(G J) =
  // 0.047559 rad, 1/cos φ − 1 = 1.1320e-3; the tension plays no part). So the torque's utilisation lies in
  // [0.25, 0.25/cos φ] and the von Mises one in [σ_vm(T), σ_vm(T/cos φ)], each bound with 1e-6 for round-off.
  const double polar_moment = kPi / 32.0 * std::pow(testing::kRodDiameter, 4);
  double phi = kTorque * 0.5 * testing::kRodLength / (2.1e11 / 2.6 * polar_moment);
  for (int i = 0; i < 50; ++i) phi = kTorque * 0.5 * testing::kRodLength / (2.1e11 / 2.6 * polar_moment) / std::cos(phi);
  EXPECT_NEAR(1.0 / std::cos(phi) - 1.0, 1.1320e-3, 1e-7);
  const double tau_high = tau / std::cos(phi);
  const double stress_high = std::sqrt(sigma * sigma + 3.0 * tau_high * tau_high) / (kYield / kDesignFactor);
  const double torque_high = 0.25 / std::cos(phi);
  for (std::size_t i = 0; i + 1 < run.envelope.stations.size(); ++i) {
    EXPECT_GE(run.envelope.largest[i][0], stress * (1.0 - 1e-6)) << "station " << i;
    EXPECT_LE(run.envelope.largest[i][0], stress_high * (1.0 + 1e-6)) << "station " << i;
    EXPECT_GE(run.envelope.largest[i][1], 0.25 * (1.0 - 1e-6)) << "station " << i;
    EXPECT_LE(run.envelope.largest[i][1], torque_high * (1.0 + 1e-6)) << "station " << i;
    EXPECT_FALSE(std::isfinite(run.envelope.largest[i][2]));  // no well: no buckling screen
    EXPECT_FALSE(std::isfinite(run.envelope.largest[i][3]));  // not rotating: no fatigue screen
  }
  for (const LimitValues& sample : run.envelope.history) {
    EXPECT_GE(sample[0], stress * (1.0 - 1e-6));
    EXPECT_LE(sample[0], stress_high * (1.0 + 1e-6));
    EXPECT_GE(sample[1], 0.25 * (1.0 - 1e-6));
    EXPECT_LE(sample[1], torque_high * (1.0 + 1e-6));
  }
  EXPECT_EQ(run.envelope.closest(), 0u);
  EXPECT_EQ(run.envelope.summary[0].limit, "yield");
}

// Released from the undeformed rod (8 bodies) with the tension on: a suddenly applied load. In an undamped
// bar the stress wave from the tip, reflected at the clamp, doubles the force behind its front: every section
// reaches twice the load, the clamp from the wave's arrival at L/c to its return at 3 L/c, c = √(E/ρ) =
// 5188.75 m/s: 0.979 ms to 2.937 ms, the middle from 1.5 L/c to 2.5 L/c. The few modes a body keeps round the
// front off and overshoot it (a truncated series overshoots a jump: Gibbs's 9 % of it for a Fourier series):
// 15 % here, within 20 %. Statically N/A against 400 MPa: 0.1096403; twice that 0.2192806. A frame at rest
// would show the static one only.
TEST(LimitsEnvelope, ASuddenTensionDoublesBetweenTheWavesArrivalAndReturn) {
  const model::ModelInput input = RatedRod({PointLoad(testing::kRodLength, Vec3(kTension, 0.0, 0.0))}, 8);
  TransientSettings settings;
  settings.start = TransientStart::Reference;
  settings.duration = 4e-3;
  settings.output_interval = 2e-5;
  settings.time_step = 2e-6;
  settings.rho_infinity = 1.0;
  settings.state_frames = 0;
  const LimitsRun run = RunWithLimits(input, settings);
  const double area = kPi / 4.0 * std::pow(testing::kRodDiameter, 2);
  const double statically = kTension / area / (kYield / kDesignFactor);
  EXPECT_NEAR(statically, 0.1096403, 1e-6);
  ASSERT_EQ(run.envelope.times.size(), 201u);
  const LimitUtilisation& yield = run.envelope.summary[0];
  EXPECT_GE(yield.utilisation, 0.95 * 2.0 * statically);
  EXPECT_LE(yield.utilisation, 1.2 * 2.0 * statically);
  const double wave = testing::kRodLength / std::sqrt(2.1e11 / 7800.0);
  EXPECT_GE(run.envelope.summary_time[0], wave);
  EXPECT_LE(run.envelope.summary_time[0], 3.0 * wave);
  // That station's envelope and the history agree with the summary; at t = 0 nothing is loaded yet.
  std::size_t at = 0;
  while (at + 1 < run.envelope.stations.size() && run.envelope.stations[at].s != yield.s) ++at;
  EXPECT_DOUBLE_EQ(run.envelope.largest[at][0], yield.utilisation);
  EXPECT_DOUBLE_EQ(run.envelope.when[at][0], run.envelope.summary_time[0]);
  EXPECT_NEAR(run.envelope.history.front()[0], 0.0, 1e-6);
  double largest = 0.0;
  for (const LimitValues& sample : run.envelope.history) largest = std::max(largest, sample[0]);
  EXPECT_DOUBLE_EQ(largest, yield.utilisation);
}

}  // namespace limits_envelope_test
}  // namespace drillflex::analyses
