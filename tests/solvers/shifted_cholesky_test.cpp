// solvers/shifted_cholesky.hpp against dense linear algebra: the solve of (H + σM) x = b, the
// positive-definiteness test at the threshold −λ₁ of the pencil (H, M), the tangent replaced on the
// same pattern (entry maps) and on another, and contacts switched as outer products — for a banded
// matrix (LAPACK's band Cholesky) and a wide one (Eigen's AMD Cholesky).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <Eigen/Eigenvalues>

#include "solvers/shifted_cholesky.hpp"

namespace drillflex::solvers {
namespace shifted_cholesky_test {

// A random symmetric-pattern matrix: block tridiagonal (blocks of 6) with, when `wide`, couplings
// between the first and the last block too (a band as wide as the matrix). Unsymmetric values.
SparseMat RandomStiffness(int blocks, bool wide, std::mt19937& random, double diagonal) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int n = 6 * blocks;
  MatX dense = MatX::Zero(n, n);
  for (int b = 0; b < blocks; ++b) {
    for (int c = std::max(0, b - 1); c <= std::min(blocks - 1, b + 1); ++c) {
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) dense(6 * b + i, 6 * c + j) = uniform(random);
      }
    }
  }
  if (wide) {
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        dense(i, n - 6 + j) = 0.1 * uniform(random);
        dense(n - 6 + j, i) = 0.1 * uniform(random);
      }
    }
  }
  dense.diagonal().array() += diagonal;
  return dense.sparseView(0.0, 0.0);
}

SparseMat MassMatrix(int n) {
  MatX mass = MatX::Identity(n, n);
  for (int i = 0; i + 1 < n; i += 2) mass(i, i) = 3.0;
  return mass.sparseView();
}

// Banded: 8 blocks in their own order (LAPACK's band Cholesky). Wide: 40 blocks with the corner
// couplings, whose band is too wide for that (solvers::FactorizeInOwnOrder): Eigen's AMD Cholesky.
// By blocks: 20 blocks given as coordinate blocks (solvers/block_tridiagonal_cholesky.hpp, H and M in
// block storage).
enum class Path { kBanded, kWide, kByBlocks };
class ShiftedCholeskyTest : public ::testing::TestWithParam<Path> {
 protected:
  int Blocks() const { return GetParam() == Path::kWide ? 40 : GetParam() == Path::kByBlocks ? 20 : 8; }
  bool Wide() const { return GetParam() == Path::kWide; }
  std::vector<Eigen::Index> Starts() const {
    std::vector<Eigen::Index> starts;
    if (GetParam() != Path::kByBlocks) return starts;
    for (int b = 0; b <= Blocks(); ++b) starts.push_back(6 * b);
    return starts;
  }
  ShiftedCholesky Make(const SparseMat& k, const SparseMat& m) const { return ShiftedCholesky(k, m, Starts()); }
};

// H as the object holds it, column by column through its product.
MatX Stiffness(const ShiftedCholesky& cholesky, int n) {
  MatX dense(n, n);
  for (int j = 0; j < n; ++j) dense.col(j) = cholesky.StiffnessTimes(VecX::Unit(n, j));
  return dense;
}

TEST_P(ShiftedCholeskyTest, SolvesAndFindsThePositiveDefiniteThreshold) {
  std::mt19937 random(11);
  const SparseMat k = RandomStiffness(Blocks(), Wide(), random, 0.5);
  const int n = 6 * Blocks();
  const SparseMat m = MassMatrix(n);
  ShiftedCholesky cholesky = Make(k, m);
  const MatX symmetric = 0.5 * (MatX(k) + MatX(k).transpose());
  // λ₁ of (H, M): H indefinite here.
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> pencil(symmetric, MatX(m));
  const double lowest = pencil.eigenvalues()[0];
  ASSERT_LT(lowest, 0.0);
  EXPECT_FALSE(cholesky.Factorize(0.0));
  EXPECT_FALSE(cholesky.Factorize(-lowest * 0.999));
  ASSERT_TRUE(cholesky.Factorize(-lowest * 1.001 + 1e-3));
  const VecX rhs = VecX::LinSpaced(n, -1.0, 2.0);
  const VecX expected = (symmetric + cholesky.shift() * MatX(m)).ldlt().solve(rhs);
  EXPECT_LT((cholesky.Solve(rhs) - expected).norm(), 1e-8 * expected.norm());
}

TEST_P(ShiftedCholeskyTest, ANewTangentOnTheSamePatternEqualsAFreshOne) {
  std::mt19937 random(5);
  const SparseMat first = RandomStiffness(Blocks(), Wide(), random, 8.0);
  const SparseMat second = RandomStiffness(Blocks(), Wide(), random, 8.0);
  const int n = 6 * Blocks();
  const SparseMat m = MassMatrix(n);
  ShiftedCholesky reused = Make(first, m);
  reused.SetStiffness(second);
  ShiftedCholesky fresh = Make(second, m);
  EXPECT_EQ(Stiffness(reused, n), Stiffness(fresh, n));
  ASSERT_TRUE(reused.Factorize(0.3));
  ASSERT_TRUE(fresh.Factorize(0.3));
  const VecX rhs = VecX::Ones(n);
  EXPECT_LT((reused.Solve(rhs) - fresh.Solve(rhs)).norm(), 1e-12 * fresh.Solve(rhs).norm());
  // Another pattern (a block fewer coupled): rebuilt, still right.
  SparseMat other = second;
  other.coeffRef(0, 7) = 0.0;
  other.prune(0.0, 0.0);
  reused.SetStiffness(other);
  ShiftedCholesky direct = Make(other, m);
  EXPECT_EQ(Stiffness(reused, n), Stiffness(direct, n));
}

TEST_P(ShiftedCholeskyTest, OuterProductsSwitchOnAndBack) {
  std::mt19937 random(3);
  const SparseMat k = RandomStiffness(Blocks(), Wide(), random, 8.0);
  const SparseMat m = MassMatrix(6 * Blocks());
  ShiftedCholesky cholesky = Make(k, m);
  const int n = 6 * Blocks();
  const MatX before = Stiffness(cholesky, n);
  const std::vector<Index> indices{6, 7, 9};
  const std::vector<double> values{1.0, -2.0, 0.5};
  cholesky.AddOuterProduct(indices, values, 4.0);
  MatX expected = before;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) expected(indices[i], indices[j]) += 4.0 * values[i] * values[j];
  }
  EXPECT_LT((Stiffness(cholesky, n) - expected).norm(), 1e-14 * expected.norm());
  EXPECT_FALSE(cholesky.has_factorization());
  cholesky.RestoreStiffness();
  EXPECT_EQ(Stiffness(cholesky, n), before);
  // Switched on and back again: the tangent as set, to the last bit.
  cholesky.AddOuterProduct(indices, values, 4.0);
  cholesky.RestoreStiffness();
  EXPECT_EQ(Stiffness(cholesky, n), before);
}

INSTANTIATE_TEST_SUITE_P(BandedWideAndByBlocks, ShiftedCholeskyTest,
                         ::testing::Values(Path::kBanded, Path::kWide, Path::kByBlocks));

}  // namespace shifted_cholesky_test
}  // namespace drillflex::solvers
