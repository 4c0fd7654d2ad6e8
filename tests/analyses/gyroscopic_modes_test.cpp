// Gyroscopic modes (analyses/gyroscopic_modes.hpp) of the V1 rod pinned at both ends, spun fast: the
// projected quadratic eigenproblem against the full state-space solve of the same {M, D + ΩG, K};
// at rest the undamped modes of modes_analysis; the pairs split into forward (higher) and backward
// whirl; the 1× crossings of a Campbell sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analyses/gyroscopic_modes.hpp"
#include "analyses_test_support.hpp"
#include "model/gyroscopic_element.hpp"
#include "solvers/eigen.hpp"

namespace drillflex::analyses {
namespace gyroscopic_modes_test {

model::ModelInput PinnedRod() {
  model::ModelInput input = testing::V1Rod();
  input.supports = {testing::SupportAt(0.0, {model::kX, model::kY, model::kZ, model::kRx}),
                    testing::SupportAt(testing::kRodLength, {model::kY, model::kZ})};
  return input;
}

constexpr double kSpin = 5000.0;  // rad/s: a 2 % split of the first pair of this slender rod

TEST(GyroscopicModes, ProjectionMatchesTheFullStateSpaceSolve) {
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(PinnedRod(), cache);
  const VecX q = built.system.ReferencePositions();
  ModesSettings settings;
  settings.count = 6;
  settings.gyroscopic = true;
  settings.rotary_speed = kSpin;
  const ModesResult projected = ComputeGyroscopicModes(built.system, q, settings, nullptr);
  ASSERT_EQ(projected.modes.size(), 6u);
  EXPECT_LT(projected.basis_size, built.system.num_velocities());
  const LinearizedSystem linear = Linearize(built.system, q, 1.0);
  const SparseMat velocity = linear.damping + kSpin * model::ComputeGyroscopicMatrix(built.system, q);
  const solvers::ComplexModes full = solvers::SolveDampedModes(MatX(linear.stiffness), MatX(velocity), MatX(linear.mass),
                                                               built.system.num_velocities(), false);
  std::vector<double> frequencies;
  for (Eigen::Index j = 0; j < full.eigenvalues.size(); ++j) {
    if (full.eigenvalues[j].imag() > 2.0 * kPi * kNearZeroFrequencyHz) frequencies.push_back(full.eigenvalues[j].imag() / (2.0 * kPi));
  }
  std::sort(frequencies.begin(), frequencies.end());
  ASSERT_GE(frequencies.size(), 6u);
  // The reference is the less accurate side: the dense state-space solve of a matrix whose stiff
  // supports and couplings (entries to 8e13 N/m against masses of ~45 kg) leave its frequencies
  // good to ~1e-5. Measured: a change of summation order in the assembly (K, D, M equal to the last
  // bit, 2.4e-4 N/m at 2e12 N/m) moved the full solve's modes 1–6 by up to 2.4e-5 and the projected
  // ones by 3e-10; the two agreed to 3.0e-6 before that change and 1.15e-5 after it.
  for (std::size_t m = 0; m < 6; ++m) {
    EXPECT_NEAR(projected.modes[m].frequency_hz / frequencies[m], 1.0, 5e-5) << "mode " << m + 1;
  }
}

TEST(GyroscopicModes, AtRestTheUndampedModesAndSpinningTheWhirlPairs) {
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(PinnedRod(), cache);
  const VecX q = built.system.ReferencePositions();
  ModesSettings settings;
  settings.count = 4;
  settings.kind = ModeKind::Lateral;
  const ModesResult undamped = RunModes(built, q, settings);
  settings.gyroscopic = true;
  const ModesResult rest = ComputeGyroscopicModes(built.system, q, settings, nullptr);
  ASSERT_EQ(rest.modes.size(), 4u);
  for (std::size_t m = 0; m < 4; ++m) {
    // The damped frequency of a mode with ζ ~ 2e-4 of viscous damping: ω sqrt(1 − ζ²).
    EXPECT_NEAR(rest.modes[m].frequency_hz / undamped.modes[m].frequency_hz, 1.0, 1e-6) << "mode " << m + 1;
    EXPECT_NEAR(rest.modes[m].damping_ratio, undamped.modes[m].damping_ratio, 1e-6);
  }
  settings.rotary_speed = kSpin;
  const ModesResult spinning = ComputeGyroscopicModes(built.system, q, settings, nullptr);
  ASSERT_EQ(spinning.modes.size(), 4u);
  for (std::size_t pair = 0; pair < 2; ++pair) {
    const ModeResult& backward = spinning.modes[2 * pair];
    const ModeResult& forward = spinning.modes[2 * pair + 1];
    EXPECT_EQ(backward.whirl, Whirl::Backward);
    EXPECT_EQ(forward.whirl, Whirl::Forward);
    EXPECT_LT(backward.whirl_index, -0.99);
    EXPECT_GT(forward.whirl_index, 0.99);
    EXPECT_LT(backward.frequency_hz, rest.modes[2 * pair].frequency_hz);
    EXPECT_GT(forward.frequency_hz, rest.modes[2 * pair].frequency_hz);
    EXPECT_EQ(forward.displacement.size(), spinning.s.size());
  }
}

TEST(GyroscopicModes, SynchronousCrossingsInterpolateTheBranches) {
  // Two flat branches over 0–180 rpm: 1× (f = Ω/2π) meets the 2 Hz one at 120 rpm (a sweep point:
  // counted once) and never the 50 Hz one.
  std::vector<CampbellPoint> points;
  for (int i = 0; i <= 6; ++i) {
    CampbellPoint point;
    point.rotary_speed = i * 10.0 * kPi / 30.0 * 3.0;  // 0, 30, …, 180 rpm
    ModeResult low, high;
    low.frequency_hz = 2.0;
    low.whirl = Whirl::Forward;
    high.frequency_hz = 50.0;
    point.modes = {low, high};
    points.push_back(point);
  }
  const std::vector<CampbellCrossing> crossings = FindSynchronousCrossings(points);
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_NEAR(crossings[0].rotary_speed * 30.0 / kPi, 120.0, 1e-9);
  EXPECT_EQ(crossings[0].branch, 0);
  EXPECT_EQ(crossings[0].whirl, Whirl::Forward);
}

}  // namespace gyroscopic_modes_test
}  // namespace drillflex::analyses
