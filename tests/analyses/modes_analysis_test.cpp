// Modes analysis: the V1 cantilever frequencies (validation.md V1, the paper's 72-coordinate
// model), the energy classification of axial, torsional and lateral modes (V6), rigid-body modes
// of a free string, and mode-shape normalization.
#include <gtest/gtest.h>

#include <cmath>

#include "analyses/modes_analysis.hpp"
#include "analyses_test_support.hpp"

namespace drillflex::analyses {
namespace modes_analysis_test {

using testing::kRodLength;

constexpr double kE = 2.1e11, kRho = 7800.0, kNu = 0.3;

// Euler–Bernoulli cantilever f_n = (β_n L)² / (2π L²) sqrt(EI/(ρA)).
double CantileverHz(double beta_l) {
  return beta_l * beta_l / (2 * kPi * kRodLength * kRodLength) *
         std::sqrt(kE * testing::RodSecondMoment() / (kRho * testing::RodArea()));
}

model::BuiltModel Build(const model::ModelInput& input, cms::ReductionCache& cache) {
  return model::BuildSystemModel(input, cache);
}

model::ModelInput Cantilever() {
  model::ModelInput input = testing::V1Rod();
  input.supports = {testing::ClampAt(0.0)};
  return input;
}

TEST(ModesAnalysis, V1CantileverFrequencies) {
  cms::ReductionCache cache;
  const model::BuiltModel built = Build(Cantilever(), cache);
  ASSERT_EQ(built.system.num_velocities(), 72);
  ModesSettings settings;
  settings.count = 8;
  const ModesResult result = RunModes(built, built.system.ReferencePositions(), settings);
  ASSERT_EQ(result.modes.size(), 8u);
  EXPECT_EQ(result.rigid_body_modes, 0);
  const double beta[4] = {1.8751041, 4.6940911, 7.8547574, 10.995541};
  for (int n = 0; n < 4; ++n) {
    const double exact = CantileverHz(beta[n]);
    for (int copy = 0; copy < 2; ++copy) {  // the y and z bending pair
      const ModeResult& mode = result.modes[2 * n + copy];
      const double error = mode.frequency_hz / exact - 1.0;
      if (copy == 0) std::printf("V1 mode %d: %.5f Hz, exact %.5f Hz, error %.4f %%\n", n + 1, mode.frequency_hz, exact, 100 * error);
      EXPECT_LT(std::abs(error), 5e-4) << "mode " << n + 1;
      EXPECT_EQ(mode.kind, ModeKind::Lateral);
      EXPECT_GT(mode.lateral_fraction, 0.999);
    }
  }
  for (std::size_t i = 1; i < result.modes.size(); ++i) {
    EXPECT_LE(result.modes[i - 1].frequency_hz, result.modes[i].frequency_hz);
  }
}

// A cantilever's first bending mode: zero at the clamp, largest (= 1) at the tip, string frame.
TEST(ModesAnalysis, ShapesAreNormalizedToUnitMaximumDisplacement) {
  cms::ReductionCache cache;
  const model::BuiltModel built = Build(Cantilever(), cache);
  ModesSettings settings;
  settings.count = 1;
  const ModesResult result = RunModes(built, built.system.ReferencePositions(), settings);
  const ModeResult& mode = result.modes.front();
  ASSERT_EQ(mode.displacement.size(), result.s.size());
  EXPECT_NEAR(mode.displacement.back().norm(), 1.0, 1e-12);
  EXPECT_LT(mode.displacement.front().norm(), 1e-6);
  for (const Vec3& d : mode.displacement) EXPECT_LE(d.norm(), 1.0 + 1e-12);
  // Tip slope of the first cantilever mode: φ'(L)/φ(L) = 1.3765/L (β₁ L = 1.8751, exact shape).
  const double slope = mode.rotation.back().norm() * kRodLength;
  EXPECT_NEAR(slope, 1.3765, 2e-3);
}

// Fixed–free rod (validation.md V6): axial f₁ = sqrt(E/ρ)/(4L), torsional f₁ = sqrt(G/ρ)/(4L).
// Inside a body these modes are carried by the linear constraint modes only (the kept
// fixed-interface modes are bending), so the 4-body rod is 4 linear consistent-mass elements for
// them: +(kh)²/24 = +0.64 % (k = π/2L, h = L/4). Tolerance 1 %.
TEST(ModesAnalysis, AxialAndTorsionalFamiliesAreFoundAndClassified) {
  cms::ReductionCache cache;
  const model::BuiltModel built = Build(Cantilever(), cache);
  const VecX q = built.system.ReferencePositions();
  ModesSettings settings;
  settings.count = 1;
  settings.kind = ModeKind::Axial;
  const ModesResult axial = RunModes(built, q, settings);
  settings.kind = ModeKind::Torsional;
  const ModesResult torsional = RunModes(built, q, settings);
  ASSERT_EQ(axial.modes.size(), 1u);
  ASSERT_EQ(torsional.modes.size(), 1u);
  const double axial_exact = std::sqrt(kE / kRho) / (4 * kRodLength);
  const double torsional_exact = std::sqrt(kE / (2 * (1 + kNu)) / kRho) / (4 * kRodLength);
  std::printf("axial %.3f Hz (exact %.3f), torsional %.3f Hz (exact %.3f)\n", axial.modes[0].frequency_hz,
              axial_exact, torsional.modes[0].frequency_hz, torsional_exact);
  EXPECT_NEAR(axial.modes[0].frequency_hz / axial_exact, 1.0, 1e-2);
  EXPECT_NEAR(torsional.modes[0].frequency_hz / torsional_exact, 1.0, 1e-2);
  EXPECT_GT(axial.modes[0].axial_fraction, 0.99);
  EXPECT_GT(torsional.modes[0].torsional_fraction, 0.99);
  EXPECT_EQ(axial.modes[0].kind, ModeKind::Axial);
  EXPECT_EQ(torsional.modes[0].kind, ModeKind::Torsional);
  // A torsional mode is normalized by its largest rotation; its tip rotates about the axis.
  EXPECT_NEAR(std::abs(torsional.modes[0].rotation.back().x()), 1.0, 1e-9);
  // Both lie above eight lateral modes of the cantilever (73.7 Hz is the fourth pair).
  EXPECT_GT(axial.modes[0].frequency_hz, CantileverHz(10.995541));
}

// A free string: six rigid-body modes at 0 Hz, then the free–free bending pair
// (β L = 4.7300408).
TEST(ModesAnalysis, FreeStringReportsRigidBodyModesAtZero) {
  cms::ReductionCache cache;
  const model::BuiltModel built = Build(testing::V1Rod(), cache);
  ModesSettings settings;
  settings.count = 8;
  const ModesResult result = RunModes(built, built.system.ReferencePositions(), settings);
  EXPECT_EQ(result.rigid_body_modes, 6);
  for (int i = 0; i < 6; ++i) {
    EXPECT_TRUE(result.modes[i].rigid_body);
    EXPECT_EQ(result.modes[i].frequency_hz, 0.0);
  }
  const double exact = CantileverHz(4.7300408);
  EXPECT_NEAR(result.modes[6].frequency_hz / exact, 1.0, 5e-4);
  EXPECT_NEAR(result.modes[7].frequency_hz / exact, 1.0, 5e-4);
  // A family excludes rigid-body modes.
  settings.count = 2;
  settings.kind = ModeKind::Lateral;
  const ModesResult lateral = RunModes(built, built.system.ReferencePositions(), settings);
  EXPECT_EQ(lateral.rigid_body_modes, 0);
  EXPECT_NEAR(lateral.modes[0].frequency_hz / exact, 1.0, 5e-4);
}

}  // namespace modes_analysis_test
}  // namespace drillflex::analyses
