// Linearized buckling (K + λ K_G) x = 0 on problems with closed-form critical loads.
#include "solvers/buckling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "toy_problems.hpp"

namespace drillflex::solvers {
namespace buckling_test {

using testing::BlockDiagonal;
using testing::ChainStiffness;
using testing::ScaledIdentity;

// ‖(K + λ K_G) x‖ / ‖K x‖ for every returned pair, and xᵀ K x = 1.
void ExpectBucklingPairs(const SparseMat& K, const SparseMat& K_G, const BucklingResult& result,
                         double tolerance) {
  for (Eigen::Index j = 0; j < result.multipliers.size(); ++j) {
    const VecX x = result.modes.col(j);
    const VecX kx = K * x;
    EXPECT_LT((kx + result.multipliers[j] * (K_G * x)).norm() / kx.norm(), tolerance);
    EXPECT_NEAR(x.dot(kx), 1.0, tolerance);
  }
}

TEST(SolveBuckling, TwoDofToy) {
  // K = k[[2, −1], [−1, 2]], K_G = −g I: λ = eig(K)/g = k/g and 3k/g, modes (1, 1) and (1, −1).
  const double k = 5.0e3, g = 2.0;
  SparseMat K(2, 2);
  K.insert(0, 0) = 2 * k;
  K.insert(1, 1) = 2 * k;
  K.insert(0, 1) = -k;
  K.insert(1, 0) = -k;
  const SparseMat K_G = ScaledIdentity(2, -g);
  const BucklingResult result = SolveBuckling(K, K_G, 2);
  ASSERT_EQ(result.multipliers.size(), 2);
  EXPECT_NEAR(result.multipliers[0], k / g, 1e-9 * k / g);
  EXPECT_NEAR(result.multipliers[1], 3 * k / g, 1e-9 * k / g);
  EXPECT_NEAR(result.modes(0, 0), result.modes(1, 0), 1e-12);
  ExpectBucklingPairs(K, K_G, result, 1e-12);
}

TEST(SolveBuckling, SkipsDirectionsWithoutOrWithStabilisingGeometricStiffness) {
  // K = diag(k1, k2, k3), K_G = diag(−g, 0, +g): only the first DOF can buckle (λ = k1/g); the
  // second has no geometric stiffness (λ = ∞), the third is stiffened (λ < 0).
  SparseMat K(3, 3), K_G(3, 3);
  K.insert(0, 0) = 10.0;
  K.insert(1, 1) = 20.0;
  K.insert(2, 2) = 30.0;
  K_G.insert(0, 0) = -4.0;
  K_G.insert(2, 2) = 4.0;
  const BucklingResult result = SolveBuckling(K, K_G, 3);
  ASSERT_EQ(result.multipliers.size(), 1);
  EXPECT_NEAR(result.multipliers[0], 2.5, 1e-12);
  // A load that only stiffens: no buckling at all.
  EXPECT_EQ(SolveBuckling(K, ScaledIdentity(3, 1.0), 2).multipliers.size(), 0);
}

// A cantilever column of N rigid links (length a) with rotational springs c at the clamp and at
// every joint, axial load P at the free top. With the absolute link angles φ_i,
//   U = ½ c Σ (φ_i − φ_{i−1})² (φ_0 = 0) and V = −P a Σ (1 − cos φ_i) ≈ −½ P a Σ φ_i²,
// so K is the fixed–free chain matrix (c) and K_G = −a I per unit P. Hence (see eigen_test.cpp)
//   P_j = (4c/a) sin²((2j − 1)π / (2(2N + 1))),
// which tends to the Euler load π² EI / (4 ℓ²) of a cantilever (ℓ = N a, c = EI / a).
double LinkColumnLoad(int links, double c, double a, int j) {
  return 4.0 * c / a * std::pow(std::sin((2 * j - 1) * kPi / (2.0 * (2 * links + 1))), 2);
}

TEST(SolveBuckling, RigidLinkColumnDenseAndLanczos) {
  const double length = 12.0, bending_stiffness = 3.0e5;  // ℓ (m), EI (N·m²)
  for (const int links : {12, 3000}) {
    const double a = length / links, c = bending_stiffness / a;
    const SparseMat K = ChainStiffness(links, c, true);
    const SparseMat K_G = ScaledIdentity(links, -a);
    const BucklingResult result = SolveBuckling(K, K_G, 3);
    ASSERT_EQ(result.multipliers.size(), 3);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(result.multipliers[j] / LinkColumnLoad(links, c, a, j + 1), 1.0, 1e-9)
          << links << " links, mode " << j + 1;
    }
    ExpectBucklingPairs(K, K_G, result, 1e-8);
  }
  // Against Euler's cantilever load: P_1 = (4EI/a²) sin²(π/(2(2N+1))) ≈ π²EI/(2ℓ + a)², i.e. the
  // link column acts like a cantilever of length ℓ + a/2 (relative difference ≈ −1/N).
  const int links = 3000;
  const double a = length / links;
  const double euler = kPi * kPi * bending_stiffness / (4.0 * length * length);
  const double effective_length_ratio = std::pow(2.0 * links / (2.0 * links + 1.0), 2);
  EXPECT_NEAR(LinkColumnLoad(links, bending_stiffness / a, a, 1) / euler, effective_length_ratio,
              1e-7);
}

// A pinned–pinned beam by central differences, w_i at x_i = i h (h = L/n, w_0 = w_n = 0,
// w'' = 0 at the ends via w_{−1} = −w_1): EI w'''' + P w'' = 0 becomes EI D² w + P D w = 0 with
// D = tridiag(1, −2, 1)/h². So K = EI D², K_G = D per unit P, and with the eigenvalues
// −(4/h²) sin²(jπ/(2n)) of D, P_j = EI (4/h²) sin²(jπ/(2n)) → j² π² EI / L².
struct FiniteDifferenceBeam {
  SparseMat K, K_G;
  FiniteDifferenceBeam(int n, double length, double bending_stiffness) {
    const int m = n - 1;
    const double h = length / n;
    std::vector<Triplet> triplets;
    for (int i = 0; i < m; ++i) {
      triplets.emplace_back(i, i, -2.0 / (h * h));
      if (i > 0) triplets.emplace_back(i, i - 1, 1.0 / (h * h));
      if (i + 1 < m) triplets.emplace_back(i, i + 1, 1.0 / (h * h));
    }
    K_G.resize(m, m);
    K_G.setFromTriplets(triplets.begin(), triplets.end());
    K = bending_stiffness * SparseMat(K_G * K_G);
  }
};

TEST(SolveBuckling, FiniteDifferenceBeamGivesTheEulerLoad) {
  // n = 300: cond(K) = cond(D)² ≈ (4n²/π²)² ≈ 1.3e9, so the rounding of K's entries (1e-16
  // relative) leaves the smallest multipliers accurate to ~1e-9; the truncation error of the
  // scheme, −(π/n)²/12 ≈ −9.1e-6, is then resolved to 1e-3 of itself.
  const int n = 300;
  const double length = 10.0, bending_stiffness = 1.0e6;
  const FiniteDifferenceBeam beam(n, length, bending_stiffness);
  const double h = length / n;
  const BucklingResult lanczos = SolveBucklingLanczos(beam.K, beam.K_G, 2);
  const BucklingResult dense = SolveBucklingDense(beam.K, beam.K_G, 2);
  ASSERT_EQ(lanczos.multipliers.size(), 2);
  ASSERT_EQ(dense.multipliers.size(), 2);
  for (int j = 0; j < 2; ++j) {
    const double discrete =
        bending_stiffness * 4.0 / (h * h) * std::pow(std::sin((j + 1) * kPi / (2.0 * n)), 2);
    EXPECT_NEAR(lanczos.multipliers[j] / discrete, 1.0, 1e-8) << "mode " << j + 1;
    EXPECT_NEAR(dense.multipliers[j] / discrete, 1.0, 1e-8) << "mode " << j + 1;
  }
  const double euler = kPi * kPi * bending_stiffness / (length * length);
  EXPECT_NEAR(lanczos.multipliers[0] / euler - 1.0, -std::pow(kPi / n, 2) / 12.0, 1e-8);
  // Mode 1 is the half sine wave.
  const VecX x = lanczos.modes.col(0);
  const VecX sine = VecX::LinSpaced(n - 1, 1, n - 1).unaryExpr(
      [&](double i) { return std::sin(i * kPi / n); });
  EXPECT_NEAR(std::abs(x.normalized().dot(sine.normalized())), 1.0, 1e-8);
}

TEST(SolveBuckling, KeepsBothPlanesOfASymmetricColumn) {
  // The same link column in two planes: every multiplier is double.
  const int links = 1500;
  const double a = 0.01, c = 2.0e4;
  const SparseMat chain = ChainStiffness(links, c, true);
  const SparseMat K = BlockDiagonal(chain, chain);
  const SparseMat K_G = ScaledIdentity(2 * links, -a);
  const BucklingResult result = SolveBucklingLanczos(K, K_G, 4);
  ASSERT_EQ(result.multipliers.size(), 4);
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(result.multipliers[j] / LinkColumnLoad(links, c, a, j / 2 + 1), 1.0, 1e-9)
        << "multiplier " << j;
  }
  // The two modes of a pair are K-orthogonal.
  EXPECT_NEAR(result.modes.col(0).dot(K * result.modes.col(1)), 0.0, 1e-8);
}

TEST(SolveBuckling, LanczosFindsEveryCopyOfHigherMultiplicities) {
  // `copies` identical link columns plus a stiffer one (1.7 c), 300 links each.
  const int links = 300;
  const double a = 0.02, c = 5.0e4;
  for (const int copies : {2, 3, 4, 6}) {
    SparseMat K = ChainStiffness(links, c, true);
    for (int i = 1; i < copies; ++i) K = BlockDiagonal(K, ChainStiffness(links, c, true));
    K = BlockDiagonal(K, ChainStiffness(links, 1.7 * c, true));
    const SparseMat K_G = ScaledIdentity(static_cast<int>(K.rows()), -a);
    std::vector<double> exact;
    for (int j = 1; j <= 30; ++j) {
      for (int i = 0; i < copies; ++i) exact.push_back(LinkColumnLoad(links, c, a, j));
      exact.push_back(LinkColumnLoad(links, 1.7 * c, a, j));
    }
    std::sort(exact.begin(), exact.end());
    for (const int count : {1, 3, 5, 8, 12, 20}) {
      const BucklingResult result = SolveBucklingLanczos(K, K_G, count);
      ASSERT_EQ(result.multipliers.size(), count);
      for (int j = 0; j < count; ++j) {
        EXPECT_NEAR(result.multipliers[j] / exact[static_cast<size_t>(j)], 1.0, 1e-9)
            << copies << " copies, " << count << " multipliers, multiplier " << j;
      }
      ExpectBucklingPairs(K, K_G, result, 1e-8);
    }
  }
}

TEST(SolveBuckling, RequiresAPositiveDefiniteStiffness) {
  // An unsupported chain (a rigid-body mode, K singular), and the same with a small negative
  // shift (K indefinite).
  const SparseMat free_chain = ChainStiffness(10, 1.0, false);
  EXPECT_THROW(SolveBucklingDense(free_chain, ScaledIdentity(10, -1.0), 1), SolverError);
  const SparseMat indefinite =
      SparseMat(ChainStiffness(700, 1.0, false)) - ScaledIdentity(700, 1e-3);
  EXPECT_THROW(SolveBucklingLanczos(indefinite, ScaledIdentity(700, -1.0), 1), SolverError);
  EXPECT_THROW(SolveBucklingDense(indefinite, ScaledIdentity(700, -1.0), 1), SolverError);
}

}  // namespace buckling_test
}  // namespace drillflex::solvers
