// solvers/iteration_matrix_lu: the method each matrix gets (dense, block tridiagonal, banded,
// sparse), the same solution from each against a dense LU, and the banded fallback when a block's
// Schur complement has a zero pivot although the whole matrix is regular.
#include "solvers/iteration_matrix_lu.hpp"

#include <gtest/gtest.h>

#include <vector>

#include <Eigen/Dense>

#include "core/error.hpp"
#include "random_block_tridiagonal.hpp"

namespace drillflex::solvers {
namespace iteration_matrix_lu_test {

using Method = IterationMatrixLu::Method;

SparseMat RandomBlockTridiagonal(const std::vector<Eigen::Index>& starts, double shift, unsigned seed) {
  return testing::RandomBlockTridiagonal<double>(starts, shift, seed);
}

std::vector<Eigen::Index> EqualBlocks(int count, int size) {
  std::vector<Eigen::Index> starts;
  for (int k = 0; k <= count; ++k) starts.push_back(static_cast<Eigen::Index>(k) * size);
  return starts;
}

VecX Solve(IterationMatrixLu& lu, const SparseMat& matrix, const VecX& rhs) {
  lu.Factorize(matrix);
  VecX x = rhs;
  lu.SolveInPlace(x);
  return x;
}

TEST(IterationMatrixLu, EveryMethodSolvesTheSameSystem) {
  const std::vector<Eigen::Index> starts = EqualBlocks(30, 9);  // 270 coordinates
  const SparseMat matrix = RandomBlockTridiagonal(starts, 0.0, 3);  // no diagonal dominance
  const VecX rhs = VecX::LinSpaced(270, -1.0, 2.0);
  const VecX expected = MatX(matrix).partialPivLu().solve(rhs);

  IterationMatrixLu dense(IterationMatrixLuOptions{300, 4.0});
  IterationMatrixLu blocked(IterationMatrixLuOptions{100, 4.0});
  blocked.SetBlocks(starts);
  IterationMatrixLu banded(IterationMatrixLuOptions{100, 4.0});
  IterationMatrixLu sparse(IterationMatrixLuOptions{100, 0.0});
  const std::pair<IterationMatrixLu*, Method> cases[] = {
      {&dense, Method::kDense}, {&blocked, Method::kBlockTridiagonal}, {&banded, Method::kBanded}, {&sparse, Method::kSparse}};
  for (const auto& [lu, method] : cases) {
    const VecX x = Solve(*lu, matrix, rhs);
    EXPECT_EQ(lu->method(), method);
    EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm()) << static_cast<int>(method);
  }
  // The same pattern with other values: the block analysis is kept and still right.
  SparseMat other = matrix;
  other.coeffs() *= -3.0;
  EXPECT_LT((Solve(blocked, other, rhs) + expected / 3.0).norm(), 1e-10 * expected.norm());
  EXPECT_EQ(blocked.method(), Method::kBlockTridiagonal);
}

TEST(IterationMatrixLu, AnEntryOutsideTheBlockStructureFallsBackToTheBand) {
  const std::vector<Eigen::Index> starts = EqualBlocks(30, 9);
  SparseMat matrix = RandomBlockTridiagonal(starts, 4.0, 5);
  matrix.coeffRef(0, 20) = 0.5;  // block 0 with block 2
  matrix.makeCompressed();
  IterationMatrixLu lu(IterationMatrixLuOptions{100, 4.0});
  lu.SetBlocks(starts);
  const VecX rhs = VecX::Ones(270);
  const VecX x = Solve(lu, matrix, rhs);
  EXPECT_EQ(lu.method(), Method::kBanded);
  EXPECT_LT((matrix * x - rhs).norm(), 1e-12 * rhs.norm() * MatX(matrix).norm());
}

// Block 0 is singular (its first row and column zero inside the block), so S_0 has a zero pivot;
// the couplings to block 1 make the whole matrix regular. The block LU sees the pivot and the
// banded LU, pivoting across the blocks, solves it.
TEST(IterationMatrixLu, AZeroPivotInsideABlockFallsBackToTheBand) {
  const std::vector<Eigen::Index> starts = EqualBlocks(30, 9);
  SparseMat matrix = RandomBlockTridiagonal(starts, 4.0, 7);
  for (Eigen::Index j = 0; j < 9; ++j) {
    matrix.coeffRef(0, j) = 0.0;
    matrix.coeffRef(j, 0) = 0.0;
  }
  const MatX dense = MatX(matrix);
  ASSERT_GT(std::abs(dense.partialPivLu().determinant()), 0.0);
  IterationMatrixLu lu(IterationMatrixLuOptions{100, 4.0});
  lu.SetBlocks(starts);
  const VecX rhs = VecX::LinSpaced(270, 1.0, 2.0);
  const VecX x = Solve(lu, matrix, rhs);
  EXPECT_EQ(lu.method(), Method::kBanded);
  const VecX expected = dense.partialPivLu().solve(rhs);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
}

TEST(IterationMatrixLu, RefusesNonFiniteAndSingularMatrices) {
  const std::vector<Eigen::Index> starts = EqualBlocks(30, 9);
  SparseMat matrix = RandomBlockTridiagonal(starts, 4.0, 9);
  IterationMatrixLu lu(IterationMatrixLuOptions{100, 4.0});
  lu.SetBlocks(starts);
  matrix.coeffRef(40, 41) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(lu.Factorize(matrix), SolverError);
  VecX x = VecX::Ones(270);
  EXPECT_THROW(lu.SolveInPlace(x), LogicError);  // nothing factorized
  SparseMat singular = RandomBlockTridiagonal(starts, 4.0, 9);
  for (Eigen::Index j = 0; j < 270; ++j) singular.coeffRef(100, j) = 0.0;  // a zero row
  EXPECT_THROW(lu.Factorize(singular), SolverError);
}

}  // namespace iteration_matrix_lu_test
}  // namespace drillflex::solvers
