// The pipe above the modelled string's top (model/string_above.hpp): its end stiffness against
// Hetényi's semi-infinite beam on an elastic foundation and against an independent finite-difference
// minimization of the beam's energy with tension and foundation; the element's tangent against
// central differences of its own residual; what the builder gives it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include <Eigen/SparseCholesky>

#include "element_problem.hpp"
#include "model/string_above.hpp"
#include "model_test_support.hpp"
#include "well/trajectory.hpp"

namespace drillflex::model {
namespace string_above_test {

using testing::ElementProblem;
using testing::JacobianErrors;

// Without tension, Hetényi (1946): the end of a semi-infinite beam on a foundation k, β = (k/4EI)^¼,
// deflects by 2 F β / k under an end force with its tilt free and by F β / k with its tilt held.
TEST(SemiInfiniteBeamEndStiffness, HetenyisBeamWithoutTension) {
  const double ei = 2.0e6, k = 1.2e4;
  const double beta = std::pow(k / (4.0 * ei), 0.25);
  const EndStiffness end = SemiInfiniteBeamEndStiffness(ei, k, 0.0);
  EXPECT_NEAR(end.uu - end.u_theta * end.u_theta / end.theta_theta, k / (2.0 * beta), 1e-12 * k / beta);
  EXPECT_NEAR(end.uu, k / beta, 1e-12 * k / beta);
}

// A tensioned pipe without a foundation (a vertical hole): no lateral stiffness (the whole pipe
// shifts freely), a tilt stiffness √(T EI) (the end's moment over its tilt for y = θ e^{−x√(T/EI)}/…);
// nothing in compression, nor beyond Dawson–Paslay's F_sin = 2 √(k EI) with a foundation.
TEST(SemiInfiniteBeamEndStiffness, TensionAloneAndTheLimitsWhereItHoldsNothing) {
  const double ei = 2.0e6, k = 1.2e4, tension = 3.0e5;
  const EndStiffness tensioned = SemiInfiniteBeamEndStiffness(ei, 0.0, tension);
  EXPECT_EQ(tensioned.uu, 0.0);
  EXPECT_EQ(tensioned.u_theta, 0.0);
  EXPECT_NEAR(tensioned.theta_theta, std::sqrt(tension * ei), 1e-12 * std::sqrt(tension * ei));
  const EndStiffness compressed = SemiInfiniteBeamEndStiffness(ei, 0.0, -1.0);
  EXPECT_EQ(compressed.theta_theta, 0.0);
  const double sinusoidal = 2.0 * std::sqrt(k * ei);
  EXPECT_GT(SemiInfiniteBeamEndStiffness(ei, k, -0.999 * sinusoidal).theta_theta, 0.0);
  const EndStiffness buckled = SemiInfiniteBeamEndStiffness(ei, k, -1.001 * sinusoidal);
  EXPECT_EQ(buckled.uu, 0.0);
  EXPECT_EQ(buckled.theta_theta, 0.0);
}

// The energy ½ ∫ (EI y''² + T y'² + k y²) dx of a long beam minimized by finite differences (over
// 60 m, its far end clamped), its end held at y(0) = u, y'(0) = θ, for three (u, θ): the quadratic
// form's coefficients are K_uu, K_uθ, K_θθ. The end's one-sided tilt makes the error O(h): steps of
// 2 and 1 cm, Richardson-extrapolated. In tension, at no axial force, and in compression below
// F_sin, each within 0.05 %.
double FiniteDifferenceEnergy(double ei, double k, double tension, double u, double theta, double h) {
  const double length = 60.0;
  const int n = static_cast<int>(length / h);
  // Unknowns y_2 … y_{n−2}; y_0 = u, y_1 = u + h θ (the end's tilt), y_{n−1} = y_n = 0.
  const int first = 2, last = n - 2, size = last - first + 1;
  std::vector<Eigen::Triplet<double>> entries;
  VecX rhs = VecX::Zero(size);
  VecX fixed = VecX::Zero(n + 1);
  fixed[0] = u;
  fixed[1] = u + h * theta;
  // Energy terms, each c (Σ_j a_j y_{i+j})²: curvature at interior points, slope on segments, foundation at points.
  auto add_term = [&](double c, std::vector<std::pair<int, double>> stencil) {
    for (const auto& [i, a] : stencil) {
      if (i < first || i > last) continue;
      for (const auto& [j, b] : stencil) {
        if (j >= first && j <= last) entries.emplace_back(i - first, j - first, 2.0 * c * a * b);
        else rhs[i - first] -= 2.0 * c * a * b * fixed[j];
      }
    }
  };
  for (int i = 1; i < n; ++i) add_term(0.5 * ei / (h * h * h), {{i - 1, 1.0}, {i, -2.0}, {i + 1, 1.0}});
  for (int i = 0; i < n; ++i) add_term(0.5 * tension / h, {{i, -1.0}, {i + 1, 1.0}});
  for (int i = 0; i <= n; ++i) add_term(0.5 * k * h * (i == 0 || i == n ? 0.5 : 1.0), {{i, 1.0}});
  SparseMat hessian(size, size);
  hessian.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<SparseMat> solver(hessian);
  const VecX interior = solver.solve(rhs);
  VecX y = fixed;
  y.segment(first, size) = interior;
  double energy = 0.0;
  for (int i = 1; i < n; ++i) energy += 0.5 * ei / (h * h * h) * std::pow(y[i - 1] - 2.0 * y[i] + y[i + 1], 2);
  for (int i = 0; i < n; ++i) energy += 0.5 * tension / h * std::pow(y[i + 1] - y[i], 2);
  for (int i = 0; i <= n; ++i) energy += 0.5 * k * h * (i == 0 || i == n ? 0.5 : 1.0) * y[i] * y[i];
  return energy;
}

TEST(SemiInfiniteBeamEndStiffness, MatchesAFiniteDifferenceBeamInTensionAndCompression) {
  const double ei = 2.0e6, k = 1.2e4;
  const double sinusoidal = 2.0 * std::sqrt(k * ei);
  for (const double tension : {2.0 * sinusoidal, 0.0, -0.4 * sinusoidal}) {
    const EndStiffness end = SemiInfiniteBeamEndStiffness(ei, k, tension);
    auto energy = [&](double u, double theta) {
      return 2.0 * (2.0 * FiniteDifferenceEnergy(ei, k, tension, u, theta, 0.01) -
                    FiniteDifferenceEnergy(ei, k, tension, u, theta, 0.02));
    };
    const double uu = energy(1.0, 0.0), tt = energy(0.0, 1.0), both = energy(1.0, 1.0);
    const double ut = 0.5 * (both - uu - tt);
    std::printf("[ measure  ] T = %+.2f F_sin: K_uu %.5g (%.5g), K_ut %.5g (%.5g), K_tt %.5g (%.5g)\n",
                tension / sinusoidal, end.uu, uu, end.u_theta, ut, end.theta_theta, tt);
    EXPECT_NEAR(end.uu, uu, 5e-4 * end.uu) << tension;
    EXPECT_NEAR(end.u_theta, ut, 5e-4 * end.u_theta) << tension;
    EXPECT_NEAR(end.theta_theta, tt, 5e-4 * end.theta_theta) << tension;
  }
}

// 20 m of 6-3/4 in collars at the foot of a 2000 m hole at 60°, 8-1/2 in, under 20 kN WOB.
ModelInput CollarsInAWell(TopCondition top) {
  ModelInput input = testing::RodInput(4, 4, 4);
  Component& collar = input.string.components.front();
  collar.outer_diameter = 0.1715;
  collar.inner_diameter = 0.0714;
  collar.length = 20.0;
  input.settings.body_length = 5.0;
  input.settings.top = top;
  input.gravity = 9.81;
  input.well =
      model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{
                              {0.0, 0.0, 0.0}, {500.0, 0.0, 0.0}, {1500.0, kPi / 3.0, 0.0}, {2500.0, kPi / 3.0, 0.0}}),
                          std::vector<well::HoleSection>{well::HoleSection{{}, 0.2159, {}}});
  input.bit_md = 2000.0;
  input.operation.weight_on_bit = 2.0e4;
  return input;
}

TEST(StringAboveElement, TheBuilderGivesItTheTopsSectionWeightAndClearance) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(CollarsInAWell(TopCondition::StringAbove), cache);
  ASSERT_TRUE(built.string_above.has_value());
  const auto& element = built.Get(*built.string_above);
  const StringAboveParameters& p = element.parameters();
  const double area = kPi / 4.0 * (0.1715 * 0.1715 - 0.0714 * 0.0714);
  const double weight = 7800.0 * 9.81 * area;  // no fluid
  EXPECT_NEAR(p.weight_per_length, weight, 1e-9 * weight);
  // Gravity across the hole toward the low side (−z of the string frame), sin α long; a straight hole.
  EXPECT_NEAR(p.gravity_across.x(), 0.0, 1e-9);  // (y, z)
  EXPECT_NEAR(p.gravity_across.y(), -std::sin(kPi / 3.0), 1e-9);
  EXPECT_NEAR(p.curvature.norm(), 0.0, 1e-12);
  const StringAboveElement::Lying lying = element.LyingOf(LoadParameters(1.0));
  EXPECT_NEAR(lying.direction.y(), -1.0, 1e-9);
  EXPECT_NEAR(lying.foundation, weight * std::sin(kPi / 3.0) / p.clearance, 1e-9 * lying.foundation);
  EXPECT_NEAR(p.clearance, 0.5 * (0.2159 - 0.1715), 1e-12);
  EXPECT_NEAR(p.axial_weight, weight * 20.0 * 0.5, 1e-6 * weight);  // 20 m at 60°
  EXPECT_NEAR(p.bending_rigidity, 2.1e11 * kPi / 64.0 * (std::pow(0.1715, 4) - std::pow(0.0714, 4)), 1.0);
  // The top's tension at rest: the collars' weight along the hole less the WOB; the WOB × 2 of the
  // parameter block and the load factor move it.
  EXPECT_NEAR(element.Tension(LoadParameters(1.0)), weight * 10.0 - 2.0e4, 1e-6);
  LoadParameters doubled(0.5);
  doubled.weight_on_bit = 4.0e4;
  EXPECT_NEAR(element.Tension(doubled), 0.5 * (weight * 10.0 - 4.0e4), 1e-6);
  // The free top, or supports the case gives: none.
  EXPECT_EQ(BuildSystemModel(CollarsInAWell(TopCondition::Free), cache).string_above.has_value(), false);
  ModelInput supported = CollarsInAWell(TopCondition::StringAbove);
  supported.supports = DefaultWellSupports(20.0);
  EXPECT_EQ(BuildSystemModel(supported, cache).string_above.has_value(), false);
}

// The tangent against central differences of the residual at a bent, turned state, in tension (the
// foundation and the tension both acting) and in compression below F_sin.
TEST(StringAboveElement, JacobianMatchesCentralDifferences) {
  cms::ReductionCache cache;
  for (const double wob : {5.0e3, 2.0e5}) {
    ModelInput input = CollarsInAWell(TopCondition::StringAbove);
    input.operation.weight_on_bit = wob;
    const BuiltModel built = BuildSystemModel(input, cache);
    const auto& element = built.Get(*built.string_above);
    ASSERT_FALSE(element.Stiffness(LoadParameters(1.0)).isZero(0.0));
    const ElementProblem problem(built.system, *built.string_above);
    std::mt19937 rng(5);
    const VecX q = testing::PerturbedPositions(built.system, rng, 0.05);
    const VecX v = VecX::Zero(built.system.num_velocities());
    const testing::Errors errors = JacobianErrors(problem, 0.0, q, v);
    std::printf("[ measure  ] top tension %.0f N: stiffness error %.2e\n", element.Tension(LoadParameters(1.0)),
                errors.stiffness);
    EXPECT_LT(errors.stiffness, 1e-6) << wob;
  }
}

}  // namespace string_above_test
}  // namespace drillflex::model
