// Modal solvers on spring–mass chains with closed-form spectra.
//
// Chain of n equal masses m joined by springs k. With u_i = sin(iθ) (u_0 = 0, the wall) the
// interior equations −k u_{i−1} + 2k u_i − k u_{i+1} = ω² m u_i give ω² = (4k/m) sin²(θ/2).
//  • fixed–free: the free last mass needs k(u_n − u_{n−1}) = ω² m u_n, i.e. a ghost
//    u_{n+1} = u_n: sin((n+1)θ) − sin(nθ) = 2 cos((2n+1)θ/2) sin(θ/2) = 0, so
//    θ_j = (2j−1)π/(2n+1) and ω_j² = (4k/m) sin²((2j−1)π / (2(2n+1))), j = 1..n.
//    (The brief's sin²(jπ/(2(2n+1))) would skip every other mode; checked below against the
//    dense solver as well.)
//  • free–free: u_i = cos((i − ½)θ), θ_j = jπ/n: ω_j² = (4k/m) sin²(jπ/(2n)), j = 0..n−1.
#include "solvers/eigen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <complex>
#include <vector>

#include "core/error.hpp"
#include "toy_problems.hpp"

namespace drillflex::solvers {
namespace eigen_test {

using testing::BlockDiagonal;
using testing::ChainStiffness;
using testing::ScaledIdentity;

constexpr double kStiffness = 2.0e6;  // N/m
constexpr double kMass = 3.0;         // kg

double FixedFreeEigenvalue(int n, int j) {
  return 4.0 * kStiffness / kMass * std::pow(std::sin((2 * j - 1) * kPi / (2.0 * (2 * n + 1))), 2);
}

double FreeFreeEigenvalue(int n, int j) {
  return 4.0 * kStiffness / kMass * std::pow(std::sin(j * kPi / (2.0 * n)), 2);
}

// max_j ‖K x_j − ω_j² M x_j‖ / (ω_max² ‖M x_j‖), and ‖Xᵀ M X − I‖_max.
void ExpectEigenpairs(const SparseMat& K, const SparseMat& M, const ModalResult& modes,
                      double tolerance) {
  const double scale = modes.eigenvalues.cwiseAbs().maxCoeff();
  for (Eigen::Index j = 0; j < modes.eigenvalues.size(); ++j) {
    const VecX x = modes.vectors.col(j);
    const VecX residual = K * x - modes.eigenvalues[j] * (M * x);
    EXPECT_LT(residual.norm() / (scale * (M * x).norm()), tolerance) << "mode " << j;
  }
  const MatX gram = modes.vectors.transpose() * (M * modes.vectors);
  EXPECT_LT((gram - MatX::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff(), tolerance);
}

TEST(SolveModes, TwoDofOscillator) {
  // Fixed–free chain of 2: K = k[[2, −1], [−1, 1]], ω² = (k/m)(3 ∓ √5)/2 (the formula at n = 2).
  const SparseMat K = ChainStiffness(2, kStiffness, true);
  const SparseMat M = ScaledIdentity(2, kMass);
  const ModalResult modes = SolveModes(K, M, 2);
  ASSERT_EQ(modes.eigenvalues.size(), 2);
  EXPECT_NEAR(modes.eigenvalues[0], kStiffness / kMass * (3.0 - std::sqrt(5.0)) / 2.0, 1e-9);
  EXPECT_NEAR(modes.eigenvalues[1], kStiffness / kMass * (3.0 + std::sqrt(5.0)) / 2.0, 1e-9);
  EXPECT_NEAR(modes.eigenvalues[0], FixedFreeEigenvalue(2, 1), 1e-9);
  // First mode: u2/u1 = (2k − m ω²)/k = (1 + √5)/2, both positive.
  EXPECT_NEAR(modes.vectors(1, 0) / modes.vectors(0, 0), (1.0 + std::sqrt(5.0)) / 2.0, 1e-12);
  ExpectEigenpairs(K, M, modes, 1e-12);
}

TEST(SolveModes, DenseAndLanczosAgreeOnA2000DofFixedFreeChain) {
  const int n = 2000, count = 12;
  const SparseMat K = ChainStiffness(n, kStiffness, true);
  const SparseMat M = ScaledIdentity(n, kMass);
  const ModalResult lanczos = SolveModesLanczos(K, M, count);
  const ModalResult dense = SolveModesDense(K, M, count);
  ASSERT_EQ(lanczos.eigenvalues.size(), count);
  ASSERT_EQ(dense.eigenvalues.size(), count);
  for (int j = 0; j < count; ++j) {
    const double exact = FixedFreeEigenvalue(n, j + 1);
    EXPECT_NEAR(lanczos.eigenvalues[j] / exact, 1.0, 1e-9) << "mode " << j + 1;
    EXPECT_NEAR(dense.eigenvalues[j] / exact, 1.0, 1e-8) << "mode " << j + 1;
    EXPECT_NEAR(lanczos.eigenvalues[j] / dense.eigenvalues[j], 1.0, 1e-8) << "mode " << j + 1;
    // Same mode: |x_dᵀ M x_l| = 1 for M-normalised vectors; the sign convention makes it +1.
    EXPECT_NEAR(dense.vectors.col(j).dot(M * lanczos.vectors.col(j)), 1.0, 1e-8);
  }
  ExpectEigenpairs(K, M, lanczos, 1e-10);
  // The exact mode shape of mode 1: u_i ∝ sin(iθ_1).
  const double theta = kPi / (2 * n + 1);
  VecX exact_shape =
      VecX::LinSpaced(n, 1, n).unaryExpr([&](double i) { return std::sin(i * theta); });
  exact_shape /= std::sqrt(exact_shape.dot(M * exact_shape));
  EXPECT_LT((lanczos.vectors.col(0) - exact_shape).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(SolveModes, KeepsBothMembersOfDegeneratePairs) {
  // Two identical, uncoupled chains (a bending pair): every eigenvalue is double.
  const int n = 400, count = 10;
  const SparseMat chain = ChainStiffness(n, kStiffness, true);
  const SparseMat K = BlockDiagonal(chain, chain);
  const SparseMat M = ScaledIdentity(2 * n, kMass);
  for (const bool use_lanczos : {true, false}) {
    const ModalResult modes =
        use_lanczos ? SolveModesLanczos(K, M, count) : SolveModesDense(K, M, count);
    ASSERT_EQ(modes.eigenvalues.size(), count);
    for (int j = 0; j < count; ++j) {
      EXPECT_NEAR(modes.eigenvalues[j] / FixedFreeEigenvalue(n, j / 2 + 1), 1.0, 1e-9)
          << (use_lanczos ? "Lanczos" : "dense") << " eigenvalue " << j;
    }
    ExpectEigenpairs(K, M, modes, 1e-9);  // includes M-orthogonality inside each pair
    // Each pair spans both chains: the M-weighted share of chain 1 sums to 1 over the pair.
    for (int j = 0; j < count; j += 2) {
      const double share = kMass * (modes.vectors.col(j).head(n).squaredNorm() +
                                    modes.vectors.col(j + 1).head(n).squaredNorm());
      EXPECT_NEAR(share, 1.0, 1e-8) << "pair " << j / 2;
    }
  }
}

TEST(SolveModes, LanczosFindsEveryCopyOfHigherMultiplicities) {
  // `copies` identical chains (stiffness k) plus one stiffer chain (1.7 k), n = 300 each: the
  // spectrum interleaves eigenvalues of multiplicity `copies` and simple ones. A single Lanczos
  // run misses copies for some of these counts (measured with the reruns switched off: 3 copies
  // / 8 modes and 6 copies / 8 modes); the deflated reruns must not.
  const int n = 300;
  const SparseMat chain = ChainStiffness(n, kStiffness, true);
  const SparseMat stiffer = ChainStiffness(n, 1.7 * kStiffness, true);
  for (const int copies : {2, 3, 4, 6}) {
    SparseMat K = chain;
    for (int c = 1; c < copies; ++c) K = BlockDiagonal(K, chain);
    K = BlockDiagonal(K, stiffer);
    const SparseMat M = ScaledIdentity(static_cast<int>(K.rows()), kMass);
    std::vector<double> exact;
    for (int j = 1; j <= 30; ++j) {
      for (int c = 0; c < copies; ++c) exact.push_back(FixedFreeEigenvalue(n, j));
      exact.push_back(1.7 * FixedFreeEigenvalue(n, j));
    }
    std::sort(exact.begin(), exact.end());
    for (const int count : {1, 3, 5, 8, 12, 20}) {
      const ModalResult modes = SolveModesLanczos(K, M, count);
      ASSERT_EQ(modes.eigenvalues.size(), count);
      for (int j = 0; j < count; ++j) {
        EXPECT_NEAR(modes.eigenvalues[j] / exact[static_cast<size_t>(j)], 1.0, 1e-9)
            << copies << " copies, " << count << " modes, eigenvalue " << j;
      }
      ExpectEigenpairs(K, M, modes, 1e-9);
    }
  }
}

TEST(SolveModes, HandlesAFreeFreeChainWithARigidBodyMode) {
  for (const int n : {40, 1500}) {  // dense and Lanczos
    const SparseMat K = ChainStiffness(n, kStiffness, false);
    const SparseMat M = ScaledIdentity(n, kMass);
    const ModalResult modes = SolveModes(K, M, 6);
    ASSERT_EQ(modes.eigenvalues.size(), 6);
    const double highest = 4.0 * kStiffness / kMass;
    EXPECT_NEAR(modes.eigenvalues[0], 0.0, 1e-12 * highest) << "n = " << n;
    // Rigid-body mode: uniform, M-normalised: u_i = 1/√(n m).
    EXPECT_LT((modes.vectors.col(0).array() - 1.0 / std::sqrt(n * kMass)).abs().maxCoeff(), 1e-8);
    for (int j = 1; j < 6; ++j) {
      EXPECT_NEAR(modes.eigenvalues[j] / FreeFreeEigenvalue(n, j), 1.0, 1e-9) << "n = " << n;
    }
  }
}

TEST(SolveModes, ReturnsTheModesNearestToTheShift) {
  const int n = 700;
  const SparseMat K = ChainStiffness(n, kStiffness, true);
  const SparseMat M = ScaledIdentity(n, kMass);
  // Shift between modes 20 and 21: the 4 nearest are modes 19..22.
  const double shift = 0.5 * (FixedFreeEigenvalue(n, 20) + FixedFreeEigenvalue(n, 21));
  for (const bool use_lanczos : {true, false}) {
    const ModalResult modes = use_lanczos ? SolveModesLanczos(K, M, 4, shift)
                                          : SolveModesDense(K, M, 4, shift);
    ASSERT_EQ(modes.eigenvalues.size(), 4);
    for (int j = 0; j < 4; ++j) {
      EXPECT_NEAR(modes.eigenvalues[j] / FixedFreeEigenvalue(n, 19 + j), 1.0, 1e-9);
    }
  }
}

TEST(SolveModes, RejectsUnsymmetricOrMismatchedMatrices) {
  SparseMat K = ChainStiffness(5, 1.0, true);
  const SparseMat M = ScaledIdentity(5, 1.0);
  EXPECT_THROW(SolveModes(K, ScaledIdentity(4, 1.0), 2), LogicError);
  K.coeffRef(0, 1) = 0.5;
  EXPECT_THROW(SolveModes(K, M, 2), LogicError);
  // A mass matrix that is not positive definite.
  EXPECT_THROW(SolveModesDense(ChainStiffness(5, 1.0, true), ScaledIdentity(5, -1.0), 2),
               SolverError);
}

TEST(FrequenciesHz, IsSqrtOverTwoPi) {
  VecX w2(3);
  w2 << -1e-9, 4.0 * kPi * kPi, 100.0 * 4.0 * kPi * kPi;
  const VecX f = FrequenciesHz(w2);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_NEAR(f[1], 1.0, 1e-14);
  EXPECT_NEAR(f[2], 10.0, 1e-13);
}

TEST(SolveDampedModes, SingleDofUnderdampedAndOverdamped) {
  // m ü + c u̇ + k u = 0: s = −ζω ± iω√(1 − ζ²), ω = √(k/m), ζ = c / (2√(km)).
  const double m = 2.0, k = 800.0;  // ω = 20 rad/s
  for (const double zeta : {0.05, 0.3}) {
    const double c = 2.0 * zeta * std::sqrt(k * m);
    const ComplexModes modes =
        SolveDampedModes(ScaledIdentity(1, k), ScaledIdentity(1, c), ScaledIdentity(1, m), 5);
    ASSERT_EQ(modes.eigenvalues.size(), 1);
    EXPECT_NEAR(modes.eigenvalues[0].real(), -zeta * 20.0, 1e-10);
    EXPECT_NEAR(modes.eigenvalues[0].imag(), 20.0 * std::sqrt(1.0 - zeta * zeta), 1e-10);
    EXPECT_NEAR(modes.natural_frequencies[0], 20.0, 1e-10);
    EXPECT_NEAR(modes.damping_ratios[0], zeta, 1e-12);
  }
  // ζ = 2: two real roots s = −ω(ζ ∓ √(ζ² − 1)), both kept, sorted by |s|.
  const double c = 2.0 * 2.0 * std::sqrt(k * m);
  const ComplexModes over =
      SolveDampedModes(ScaledIdentity(1, k), ScaledIdentity(1, c), ScaledIdentity(1, m), 5);
  ASSERT_EQ(over.eigenvalues.size(), 2);
  EXPECT_NEAR(over.eigenvalues[0].real(), -20.0 * (2.0 - std::sqrt(3.0)), 1e-9);
  EXPECT_NEAR(over.eigenvalues[1].real(), -20.0 * (2.0 + std::sqrt(3.0)), 1e-9);
  EXPECT_EQ(over.damped_frequencies[0], 0.0);
}

TEST(SolveDampedModes, ProportionalDampingOfATwoDofChain) {
  // D = αM + βK keeps the undamped modes; ζ_j = α/(2ω_j) + βω_j/2 (Rayleigh damping).
  const SparseMat K = ChainStiffness(2, kStiffness, true);
  const SparseMat M = ScaledIdentity(2, kMass);
  const double alpha = 3.0, beta = 2e-5;
  const SparseMat D = alpha * M + beta * K;
  const ComplexModes modes = SolveDampedModes(K, D, M, 2);
  ASSERT_EQ(modes.eigenvalues.size(), 2);
  for (int j = 0; j < 2; ++j) {
    const double omega = std::sqrt(FixedFreeEigenvalue(2, j + 1));
    // Round-off of the 4×4 state-space eigenproblem with entries up to k/m ≈ 7e5: ~1e-11.
    EXPECT_NEAR(modes.natural_frequencies[j] / omega, 1.0, 1e-10);
    EXPECT_NEAR(modes.damping_ratios[j], alpha / (2 * omega) + beta * omega / 2, 1e-10);
    // The displacement part is the undamped mode (real up to the phase fixed by the solver).
    EXPECT_LT(modes.vectors.col(j).imag().norm(), 1e-10);
  }
  // First mode shape: u2/u1 = (1 + √5)/2.
  EXPECT_NEAR(modes.vectors(1, 0).real() / modes.vectors(0, 0).real(), (1 + std::sqrt(5.0)) / 2,
              1e-10);
}

}  // namespace eigen_test
}  // namespace drillflex::solvers
