// The trust-region energy minimizer (solvers/energy_trust_region.hpp) on toy energies with analytic
// minima: a saddle left from its exact stationary point, a compressed point in a circular hole (a
// string buckling onto the wall, in miniature), a hanging chain of stiff springs turned by 90°, and a
// convex chain where it must end as plain Newton does.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "solvers/energy_trust_region.hpp"
#include "solvers/newton.hpp"

namespace drillflex::solvers {
namespace energy_trust_region_test {

// A Euclidean problem from an energy, its gradient and Hessian (dense, small), unit masses.
class EnergyProblem final : public StaticProblem {
 public:
  using Energy = std::function<double(const VecX&)>;
  using Gradient = std::function<VecX(const VecX&)>;
  using Hessian = std::function<MatX(const VecX&)>;
  EnergyProblem(int n, Energy energy, Gradient gradient, Hessian hessian, double force_scale)
      : n_(n), energy_(std::move(energy)), gradient_(std::move(gradient)), hessian_(std::move(hessian)),
        force_scale_(force_scale) {}

  Index num_positions() const override { return n_; }
  Index num_velocities() const override { return n_; }
  VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }
  VecX Residual(double, const VecX& q, const VecX&, const VecX&) const override { return gradient_(q); }
  SparseMat IterationMatrix(double, const VecX& q, const VecX&, const VecX&, double cK, double,
                            double cM) const override {
    const MatX matrix = cK * hessian_(q) + cM * MatX::Identity(n_, n_);
    return matrix.sparseView(0.0, 0.0);
  }
  double ForceScale() const override { return force_scale_; }
  // One rounding unit of each coordinate (the residual's round-off floor, solvers/problem.hpp).
  VecX StateResolution(const VecX& q) const override {
    return std::numeric_limits<double>::epsilon() * q.cwiseAbs().cwiseMax(1.0);
  }
  double EnergyChange(const VecX& from, const VecX& to) const override { return energy_(to) - energy_(from); }

 private:
  int n_;
  Energy energy_;
  Gradient gradient_;
  Hessian hessian_;
  double force_scale_;
};

// Π = ½x² − ½y² + ¼y⁴: a saddle at 0, minima at (0, ±1).
EnergyProblem Saddle() {
  return EnergyProblem(
      2, [](const VecX& q) { return 0.5 * q[0] * q[0] - 0.5 * q[1] * q[1] + 0.25 * std::pow(q[1], 4); },
      [](const VecX& q) { return VecX((VecX(2) << q[0], -q[1] + std::pow(q[1], 3)).finished()); },
      [](const VecX& q) {
        MatX h = MatX::Zero(2, 2);
        h(0, 0) = 1.0;
        h(1, 1) = -1.0 + 3.0 * q[1] * q[1];
        return h;
      },
      1.0);
}

TEST(MinimizeEnergy, LeavesAnExactSaddleAlongItsNegativeCurvature) {
  EnergyProblem problem = Saddle();
  // The start is stationary: R = 0, only the curvature says it is not a minimum.
  const VecX start = VecX::Zero(2);
  ASSERT_EQ(problem.Residual(0.0, start, start, start).norm(), 0.0);
  const EnergyTrustRegionResult result = MinimizeEnergy(problem, start);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_TRUE(result.stable);
  EXPECT_GE(result.negative_curvature_steps, 1);
  EXPECT_NEAR(result.q[0], 0.0, 1e-8);
  EXPECT_NEAR(std::abs(result.q[1]), 1.0, 1e-8);
  EXPECT_NEAR(result.energy_released, 0.25, 1e-8);  // Π(0) − Π(0, ±1) = 1/4
  EXPECT_NEAR(result.lowest_curvature, -1.0, 1e-6);  // at the saddle, λ₁ = −1
}

TEST(MinimizeEnergy, WithoutTheCurvatureCheckTheSaddleIsAnAnswer) {
  EnergyProblem problem = Saddle();
  EnergyTrustRegionOptions options;
  options.require_stable = false;
  const EnergyTrustRegionResult result = MinimizeEnergy(problem, VecX::Zero(2), options);
  ASSERT_TRUE(result.converged);
  EXPECT_FALSE(result.stable);
  EXPECT_EQ(result.iterations, 0);
}

// A point held at the centre of a circular hole of clearance d by a spring k, pushed off it by a
// compression P/L > k (a compressed strut's lateral instability), against a stiff wall k_w:
//   Π = ½ (k − P/L) |x|² + ½ k_w ⟨|x| − d⟩².
// Equilibrium on the wall: (k − P/L)|x| + k_w (|x| − d) = 0, |x| = k_w d / (k_w + k − P/L).
TEST(MinimizeEnergy, ACompressedPointAtTheHoleCentreEndsOnTheWall) {
  constexpr double k = 1.0, softening = 3.0, wall = 1e6, d = 0.01;
  const double net = k - softening;  // −2 N/m: the centre is unstable
  auto gap = [&](const VecX& q) { return q.norm() - d; };
  EnergyProblem problem(
      2,
      [&](const VecX& q) {
        const double g = std::max(gap(q), 0.0);
        return 0.5 * net * q.squaredNorm() + 0.5 * wall * g * g;
      },
      [&](const VecX& q) {
        VecX r = net * q;
        if (gap(q) > 0.0) r += wall * gap(q) * q / q.norm();
        return r;
      },
      [&](const VecX& q) {
        MatX h = net * MatX::Identity(2, 2);
        if (gap(q) > 0.0) {
          const double rho = q.norm();
          const VecX n = q / rho;
          h += wall * (n * n.transpose() + gap(q) / rho * (MatX::Identity(2, 2) - n * n.transpose()));
        }
        return h;
      },
      wall * d);
  const EnergyTrustRegionResult result = MinimizeEnergy(problem, VecX::Zero(2));
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_TRUE(result.stable);
  EXPECT_GE(result.negative_curvature_steps, 1);
  const double expected = wall * d / (wall + net);
  EXPECT_NEAR(result.q.norm(), expected, 1e-12);
}

// Two unit masses on stiff springs (k = 1e12 N/m, rest length 1 m) from a pin at the origin, under
// gravity g along +y, started horizontal: the chain must swing through 90° with springs a million
// times stiffer than gravity's pull, where each linearized step's second-order stretch (½θ²L) costs
// more energy than the step releases. Equilibrium: straight down, the upper spring carrying 2g, the
// lower g: p₁ = (0, 1 + 2g/k), p₂ = (0, 2 + 3g/k).
TEST(MinimizeEnergy, SwingsAChainOfStiffSpringsDownThroughNinetyDegrees) {
  constexpr double stiffness = 1e12, g = 9.81;
  auto spring = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return (b - a).norm() - 1.0; };
  auto points = [](const VecX& q) {
    return std::pair<Eigen::Vector2d, Eigen::Vector2d>{q.head<2>(), q.tail<2>()};
  };
  EnergyProblem problem(
      4,
      [&](const VecX& q) {
        const auto [p1, p2] = points(q);
        const double e1 = spring(Eigen::Vector2d::Zero(), p1), e2 = spring(p1, p2);
        return 0.5 * stiffness * (e1 * e1 + e2 * e2) - g * (p1.y() + p2.y());
      },
      [&](const VecX& q) {
        const auto [p1, p2] = points(q);
        const Eigen::Vector2d n1 = p1.normalized(), n2 = (p2 - p1).normalized();
        const double f1 = stiffness * spring(Eigen::Vector2d::Zero(), p1), f2 = stiffness * spring(p1, p2);
        VecX r(4);
        r.head<2>() = f1 * n1 - f2 * n2 - Eigen::Vector2d(0.0, g);
        r.tail<2>() = f2 * n2 - Eigen::Vector2d(0.0, g);
        return r;
      },
      [&](const VecX& q) {
        const auto [p1, p2] = points(q);
        auto block = [&](const Eigen::Vector2d& d) {
          const double length = d.norm();
          const Eigen::Vector2d n = d / length;
          const Eigen::Matrix2d nn = n * n.transpose();
          return Eigen::Matrix2d(stiffness * (nn + (length - 1.0) / length * (Eigen::Matrix2d::Identity() - nn)));
        };
        const Eigen::Matrix2d k1 = block(p1), k2 = block(p2 - p1);
        MatX h = MatX::Zero(4, 4);
        h.topLeftCorner<2, 2>() = k1 + k2;
        h.topRightCorner<2, 2>() = -k2;
        h.bottomLeftCorner<2, 2>() = -k2;
        h.bottomRightCorner<2, 2>() = k2;
        return h;
      },
      2.0 * g);
  VecX start(4);
  start << 1.0, 0.0, 2.0, 0.0;
  const EnergyTrustRegionResult result = MinimizeEnergy(problem, start);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_TRUE(result.stable);
  // Along the springs within round-off of the stretch; across them the chain is held only by its
  // tension (g/L ≈ 10 N/m) against the residual's round-off floor (k·ε·2 m ≈ 4e-4 N): 1e-7 m.
  EXPECT_NEAR(result.q[0], 0.0, 1e-7);
  EXPECT_NEAR(result.q[1], 1.0 + 2.0 * g / stiffness, 1e-12);
  EXPECT_NEAR(result.q[2], 0.0, 1e-7);
  EXPECT_NEAR(result.q[3], 2.0 + 3.0 * g / stiffness, 1e-12);
  // Released: the weights' fall, 1·g + 2·g, less the springs' stored energy (negligible here).
  EXPECT_NEAR(result.energy_released, 3.0 * g, 1e-6);
  EXPECT_GT(result.second_order_corrections, 0);
  EXPECT_LT(result.iterations, 200);
}

// The convex chain of solvers/newton_test.cpp's springs, k e + k₃ e³, tip load P: every spring carries
// P, q_i = i e* with k e* + k₃ e*³ = P. Ends with plain Newton's quadratic convergence.
TEST(MinimizeEnergy, EndsLikeNewtonOnAConvexProblem) {
  constexpr int n = 20;
  constexpr double k = 100.0, k3 = 1e4, tip = 500.0;
  auto elongation = [](const VecX& q, int i) { return q[i] - (i > 0 ? q[i - 1] : 0.0); };
  EnergyProblem problem(
      n,
      [&](const VecX& q) {
        double energy = -tip * q[n - 1];
        for (int i = 0; i < n; ++i) {
          const double e = elongation(q, i);
          energy += 0.5 * k * e * e + 0.25 * k3 * std::pow(e, 4);
        }
        return energy;
      },
      [&](const VecX& q) {
        VecX r = VecX::Zero(n);
        for (int i = 0; i < n; ++i) {
          const double e = elongation(q, i), f = k * e + k3 * e * e * e;
          r[i] += f;
          if (i > 0) r[i - 1] -= f;
        }
        r[n - 1] -= tip;
        return r;
      },
      [&](const VecX& q) {
        MatX h = MatX::Zero(n, n);
        for (int i = 0; i < n; ++i) {
          const double e = elongation(q, i), s = k + 3.0 * k3 * e * e;
          h(i, i) += s;
          if (i > 0) {
            h(i - 1, i - 1) += s;
            h(i - 1, i) -= s;
            h(i, i - 1) -= s;
          }
        }
        return h;
      },
      tip);
  EnergyTrustRegionOptions options;
  options.initial_radius = 1.0;
  const EnergyTrustRegionResult result = MinimizeEnergy(problem, VecX::Zero(n), options);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_TRUE(result.stable);
  // e*: the real root of k3 e³ + k e − P (Newton on the scalar cubic).
  double e = 0.1;
  for (int i = 0; i < 50; ++i) e -= (k3 * e * e * e + k * e - tip) / (3.0 * k3 * e * e + k);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(result.q[i], (i + 1) * e, 1e-10) << i;
  EXPECT_LE(result.residual_norm, 1e-8 * tip);
  EXPECT_LT(result.iterations, 30);
}

TEST(MinimizeEnergy, AProblemWithoutAnEnergyIsRefused) {
  class NoEnergy final : public StaticProblem {
   public:
    Index num_positions() const override { return 1; }
    Index num_velocities() const override { return 1; }
    VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }
    VecX Residual(double, const VecX& q, const VecX&, const VecX&) const override { return q; }
    SparseMat IterationMatrix(double, const VecX&, const VecX&, const VecX&, double cK, double, double cM) const override {
      return (MatX::Constant(1, 1, cK + cM)).sparseView();
    }
  } problem;
  EXPECT_THROW(MinimizeEnergy(problem, VecX::Ones(1)), LogicError);
}

}  // namespace energy_trust_region_test
}  // namespace drillflex::solvers
