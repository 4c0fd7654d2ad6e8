// Static analysis on the V1 cantilever (validation.md V1, the paper's 4 bodies × 10 elements ×
// (6 + 6) model, 72 coordinates): tip deflections against Euler–Bernoulli theory, support
// reactions against statics, dynamic relaxation against Newton.
#include <gtest/gtest.h>

#include <cmath>

#include "analyses/static_analysis.hpp"
#include "analyses_test_support.hpp"
#include "core/error.hpp"

namespace drillflex::analyses {
namespace static_analysis_test {

using testing::kRodLength;

constexpr double kE = 2.1e11;
const double kEI = kE * testing::RodSecondMoment();

StaticResult SolveCantilever(std::vector<model::Load> loads, StaticMethod method = StaticMethod::StrategyChain) {
  model::ModelInput input = testing::V1Rod();
  input.supports = {testing::ClampAt(0.0)};
  input.loads = std::move(loads);
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  EXPECT_EQ(built.system.num_velocities(), 72);
  StaticSettings settings;
  settings.method = method;
  return RunStatic(built, settings);
}

TEST(StaticAnalysis, StationsRunFromTheBitToTheTopWithJointsOnce) {
  const StaticResult result = SolveCantilever({testing::PointLoad(kRodLength, Vec3(0, 100, 0))});
  ASSERT_EQ(result.nodes.size(), 41u);  // 4 bodies × 10 elements, joints once
  EXPECT_DOUBLE_EQ(result.nodes.front().s, 0.0);
  EXPECT_NEAR(result.nodes.back().s, kRodLength, 1e-12);
  for (std::size_t i = 1; i < result.nodes.size(); ++i) EXPECT_GT(result.nodes[i].s, result.nodes[i - 1].s);
}

// Tip deflections within 0.05 % (validation.md V1); the loads are small enough to be linear
// (tip rotation ≤ 4e-3 rad, so the nonlinear correction is below 1e-5).
TEST(StaticAnalysis, V1TipForceDeflection) {
  const double force = 100.0;
  const StaticResult result = SolveCantilever({testing::PointLoad(kRodLength, Vec3(0, force, 0))});
  ASSERT_TRUE(result.converged);
  const double exact = force * std::pow(kRodLength, 3) / (3.0 * kEI);
  const double error = result.nodes.back().displacement.y() / exact - 1.0;
  std::printf("tip force: %.6e m, exact %.6e m, error %.4f %%\n", result.nodes.back().displacement.y(), exact,
              100 * error);
  EXPECT_LT(std::abs(error), 5e-4);
  EXPECT_NEAR(result.nodes.back().lateral_offset, std::abs(result.nodes.back().displacement.y()), 1e-12);
  // Tip rotation P L²/(2EI) about z.
  const double rotation = force * kRodLength * kRodLength / (2.0 * kEI);
  EXPECT_LT(std::abs(result.nodes.back().rotation.z() / rotation - 1.0), 5e-4);
}

TEST(StaticAnalysis, V1UniformLoadDeflection) {
  const double load = 20.0;  // N/m
  const StaticResult result = SolveCantilever({testing::DistributedLoad(0.0, kRodLength, Vec3(0, 0, load))});
  ASSERT_TRUE(result.converged);
  const double exact = load * std::pow(kRodLength, 4) / (8.0 * kEI);
  const double error = result.nodes.back().displacement.z() / exact - 1.0;
  std::printf("uniform load: error %.4f %%\n", 100 * error);
  EXPECT_LT(std::abs(error), 5e-4);
}

TEST(StaticAnalysis, V1TipMomentDeflection) {
  const double moment = 100.0;  // N·m about z: bends toward +y
  const StaticResult result =
      SolveCantilever({testing::PointLoad(kRodLength, Vec3::Zero(), Vec3(0, 0, moment))});
  ASSERT_TRUE(result.converged);
  const double exact = moment * kRodLength * kRodLength / (2.0 * kEI);
  const double error = result.nodes.back().displacement.y() / exact - 1.0;
  std::printf("tip moment: error %.4f %%\n", 100 * error);
  EXPECT_LT(std::abs(error), 5e-4);
}

// The clamp holds the tip force P (y) and its moment P L (about z): R = (0, −P, 0), M = (0, 0, −P L).
TEST(StaticAnalysis, SupportReactionBalancesTheLoad) {
  const double force = 100.0;
  const StaticResult result = SolveCantilever({testing::PointLoad(kRodLength, Vec3(0, force, 0))});
  ASSERT_EQ(result.reactions.size(), 1u);
  const SupportReaction& reaction = result.reactions[0];
  EXPECT_DOUBLE_EQ(reaction.s, 0.0);
  EXPECT_NEAR(reaction.force.y(), -force, 1e-6 * force);
  EXPECT_NEAR(reaction.force.x(), 0.0, 1e-3 * force);
  // Moment about the clamped node: the deflected tip adds only P·u_x (u_x ~ 1e-5 m).
  EXPECT_NEAR(reaction.moment.z(), -force * kRodLength, 1e-4 * force * kRodLength);
}

TEST(StaticAnalysis, SupportAtTheTopReportsItsStation) {
  model::ModelInput input = testing::V1Rod();
  input.supports = {testing::ClampAt(0.0), testing::SupportAt(kRodLength, {model::kY})};
  input.loads = {testing::PointLoad(0.5 * kRodLength, Vec3(0, 100, 0))};
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const StaticResult result = RunStatic(built, StaticSettings{});
  ASSERT_EQ(result.reactions.size(), 2u);
  EXPECT_NEAR(result.reactions[1].s, kRodLength, 1e-12);
  // Propped cantilever with a mid-span load P: prop reaction 5P/16 (Roark, Table 8.1 case 1c).
  EXPECT_NEAR(result.reactions[1].force.y(), -100.0 * 5.0 / 16.0, 0.01);
  // Equilibrium to the residual's round-off floor (~1e-3 N: stiff springs × position round-off).
  EXPECT_NEAR(result.reactions[0].force.y() + result.reactions[1].force.y(), -100.0, 1e-3);
}

// Dynamic relaxation converges to the same equilibrium as Newton.
TEST(StaticAnalysis, DynamicRelaxationAgreesWithNewton) {
  const std::vector<model::Load> loads = {testing::PointLoad(kRodLength, Vec3(-50, 100, 30), Vec3(20, 0, 0))};
  const StaticResult newton = SolveCantilever(loads);
  const StaticResult relaxed = SolveCantilever(loads, StaticMethod::DynamicRelaxation);
  ASSERT_TRUE(relaxed.converged);
  std::printf("dynamic relaxation: %d steps, Newton %d iterations\n", relaxed.iterations, newton.iterations);
  for (std::size_t i = 0; i < newton.nodes.size(); ++i) {
    EXPECT_NEAR((relaxed.nodes[i].displacement - newton.nodes[i].displacement).norm(), 0.0,
                1e-6 * newton.nodes.back().displacement.norm());
  }
}

// Von Mises stress at the clamp of a bar in tension, torsion and bending, by hand.
TEST(StaticAnalysis, CombinedStressAtTheOuterFibre) {
  const double tension = 1e4, torque = 200.0, force = 50.0;
  const StaticResult result =
      SolveCantilever({testing::PointLoad(kRodLength, Vec3(tension, force, 0), Vec3(torque, 0, 0))});
  const StaticNodeResult& root = result.nodes.front();
  const double c = 0.5 * testing::kRodDiameter, I = testing::RodSecondMoment(), J = 2.0 * I;
  const double bending = root.bending_moment * c / I;
  const double normal = tension / testing::RodArea() + bending;
  const double shear = torque * c / J;
  EXPECT_NEAR(root.bending_stress, bending, 1e-9 * bending);
  EXPECT_NEAR(root.von_mises_stress, std::sqrt(normal * normal + 3 * shear * shear), 1e-6 * normal);
  EXPECT_NEAR(root.torque, torque, 1e-6 * torque);
}

}  // namespace static_analysis_test
}  // namespace drillflex::analyses
