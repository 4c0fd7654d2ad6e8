// SparseLinearSolver: LDLT for symmetric matrices (banded or not), LU for unsymmetric ones, the
// fallback when a matrix claimed symmetric is not, pattern reuse, and singular matrices.
#include "solvers/linear_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/error.hpp"

namespace drillflex::solvers {
namespace linear_solver_test {

// A random n×n matrix with the given half bandwidth (or random positions when scattered),
// diagonally dominant; symmetric if asked.
SparseMat RandomMatrix(int n, int half_band, bool symmetric, bool scattered, double diagonal,
                       unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> index(0, n - 1);
  std::vector<Triplet> triplets;
  for (int i = 0; i < n; ++i) {
    triplets.emplace_back(i, i, diagonal);
    for (int d = 1; d <= half_band; ++d) {
      const int j = scattered ? index(generator) : i + d;
      if (j >= n || j == i) continue;
      const double x = value(generator);
      triplets.emplace_back(i, j, x);
      triplets.emplace_back(j, i, symmetric ? x : value(generator));
    }
  }
  SparseMat matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

double RelativeResidual(const SparseMat& a, const VecX& x, const VecX& b) {
  return (a * x - b).norm() / b.norm();
}

TEST(HalfBandwidth, OfATridiagonalAndAnArrowMatrix) {
  EXPECT_EQ(HalfBandwidth(RandomMatrix(50, 1, true, false, 4.0, 1)), 1);
  SparseMat arrow(5, 5);
  arrow.insert(0, 0) = 1;
  arrow.insert(4, 0) = 1;
  EXPECT_EQ(HalfBandwidth(arrow), 4);
}

TEST(SparseLinearSolver, SolvesBandedAndScatteredSymmetricSystemsWithLdlt) {
  for (const bool scattered : {false, true}) {
    const SparseMat a = RandomMatrix(2000, 6, true, scattered, 20.0, 7);
    const VecX b = VecX::LinSpaced(2000, -1.0, 3.0);
    SparseLinearSolver solver;
    solver.Factorize(a);
    const VecX x = solver.Solve(b);
    EXPECT_FALSE(solver.uses_lu());
    EXPECT_LT(RelativeResidual(a, x, b), 1e-13) << "scattered = " << scattered;
  }
}

TEST(SparseLinearSolver, SolvesSymmetricIndefiniteSystems) {
  // K − σI for the fixed–free chain K = tridiag(−1, 2, −1) (last diagonal 1), with σ halfway
  // between its eigenvalues 4 sin²((2j−1)π/(2(2n+1))) for j = 100 and 101: indefinite, and
  // cond = max|λ − σ| / min|λ − σ| ≈ 4 / 0.0045 ≈ 900.
  const int n = 500;
  std::vector<Triplet> triplets;
  auto eigenvalue = [&](int j) {
    return 4.0 * std::pow(std::sin((2 * j - 1) * 3.14159265358979323846 / (2.0 * (2 * n + 1))), 2);
  };
  const double sigma = 0.5 * (eigenvalue(100) + eigenvalue(101));
  for (int i = 0; i < n; ++i) {
    triplets.emplace_back(i, i, (i + 1 < n ? 2.0 : 1.0) - sigma);
    if (i > 0) {
      triplets.emplace_back(i, i - 1, -1.0);
      triplets.emplace_back(i - 1, i, -1.0);
    }
  }
  SparseMat a(n, n);
  a.setFromTriplets(triplets.begin(), triplets.end());
  const VecX b = VecX::LinSpaced(n, -1.0, 1.0);
  SparseLinearSolver solver;
  solver.Factorize(a);
  EXPECT_LT(RelativeResidual(a, solver.Solve(b), b), 1e-12);
}

TEST(SparseLinearSolver, UsesLuForUnsymmetricMatrices) {
  const SparseMat a = RandomMatrix(1000, 4, false, true, 8.0, 11);
  const VecX b = VecX::LinSpaced(1000, 1.0, 2.0);
  SparseLinearSolver solver;
  solver.Factorize(a);
  EXPECT_TRUE(solver.uses_lu());
  EXPECT_LT(RelativeResidual(a, solver.Solve(b), b), 1e-13);
}

TEST(SparseLinearSolver, FallsBackToLuWhenAMatrixClaimedSymmetricIsNot) {
  // LDLT reads only the lower triangle, so its solution is wrong; the backward-error check sees it.
  const SparseMat a = RandomMatrix(300, 3, false, false, 6.0, 5);
  const VecX b = VecX::Ones(300);
  SparseLinearSolver solver;
  solver.Factorize(a, MatrixSymmetry::kSymmetric);
  const VecX x = solver.Solve(b);
  EXPECT_TRUE(solver.uses_lu());
  EXPECT_LT(RelativeResidual(a, x, b), 1e-13);
}

TEST(SparseLinearSolver, ReusesThePatternWithNewValues) {
  const SparseMat a = RandomMatrix(400, 5, true, true, 12.0, 2);
  const SparseMat b = 3.0 * a + SparseMat(RandomMatrix(400, 0, true, true, 1.0, 2));
  const VecX rhs = VecX::LinSpaced(400, 0.5, 1.5);
  SparseLinearSolver solver;
  solver.Factorize(a);
  EXPECT_LT(RelativeResidual(a, solver.Solve(rhs), rhs), 1e-13);
  solver.Factorize(b);  // same pattern (the diagonal was already there), new values
  EXPECT_LT(RelativeResidual(b, solver.Solve(rhs), rhs), 1e-13);
  const SparseMat c = RandomMatrix(400, 2, true, false, 5.0, 9);  // another pattern
  solver.Factorize(c);
  EXPECT_LT(RelativeResidual(c, solver.Solve(rhs), rhs), 1e-13);
}

TEST(SparseLinearSolver, ThrowsSolverErrorOnSingularOrNonFiniteMatrices) {
  SparseMat singular(3, 3);
  singular.insert(0, 0) = 1.0;
  singular.insert(1, 1) = 1.0;  // row and column 2 empty
  SparseLinearSolver solver;
  EXPECT_THROW(solver.Factorize(singular), SolverError);
  SparseMat nan_matrix(2, 2);
  nan_matrix.insert(0, 0) = std::numeric_limits<double>::quiet_NaN();
  nan_matrix.insert(1, 1) = 1.0;
  EXPECT_THROW(solver.Factorize(nan_matrix), SolverError);
  EXPECT_THROW(solver.Solve(VecX::Ones(2)), LogicError);  // nothing factorized
}

}  // namespace linear_solver_test
}  // namespace drillflex::solvers
