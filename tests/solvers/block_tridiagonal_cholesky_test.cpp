// solvers::BlockTridiagonalCholesky against Eigen's dense Cholesky on random symmetric
// block-tridiagonal matrices with blocks of several sizes: the solution, positive definiteness found
// exactly where the dense factorization finds it, a shift by a second matrix, and the patterns it
// refuses.
#include "solvers/block_tridiagonal_cholesky.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <Eigen/Cholesky>

#include "solvers/shifted_cholesky.hpp"

namespace drillflex::solvers {
namespace block_tridiagonal_cholesky_test {

// A symmetric block-tridiagonal matrix (blocks of `sizes`), its diagonal raised by `diagonal`.
MatX RandomBlockTridiagonal(const std::vector<Eigen::Index>& starts, double diagonal, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const Eigen::Index n = starts.back();
  MatX a = MatX::Zero(n, n);
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    const Eigen::Index end = k + 2 < starts.size() ? starts[k + 2] : starts[k + 1];
    for (Eigen::Index i = starts[k]; i < end; ++i) {
      for (Eigen::Index j = starts[k]; j <= i; ++j) {
        a(i, j) = a(j, i) = uniform(rng);
      }
    }
  }
  a.diagonal().array() += diagonal;
  return a;
}

const std::vector<Eigen::Index> kStarts = {0, 4, 9, 12, 18, 20};

TEST(BlockTridiagonalCholesky, SolvesAsTheDenseCholeskyDoes) {
  const MatX a = RandomBlockTridiagonal(kStarts, 12.0, 1);
  const SparseMat sparse = a.sparseView();
  BlockTridiagonalCholesky blocks;
  ASSERT_TRUE(blocks.Analyze(sparse, kStarts));
  ASSERT_TRUE(blocks.Factorize(sparse.valuePtr(), nullptr, 0.0));
  const VecX b = VecX::LinSpaced(a.rows(), -1.0, 2.0);
  VecX x = b;
  blocks.SolveInPlace(x);
  const VecX dense = Eigen::LLT<MatX>(a).solve(b);
  EXPECT_LT((x - dense).norm(), 1e-12 * dense.norm());
}

TEST(BlockTridiagonalCholesky, FindsPositiveDefinitenessWhereTheDenseFactorizationDoes) {
  // The diagonal lowered until the matrix is indefinite: both factorizations agree at every level.
  for (const double diagonal : {12.0, 6.0, 3.0, 2.0, 1.0, 0.0, -2.0}) {
    const MatX a = RandomBlockTridiagonal(kStarts, diagonal, 2);
    const SparseMat sparse = a.sparseView();
    BlockTridiagonalCholesky blocks;
    ASSERT_TRUE(blocks.Analyze(sparse, kStarts));
    const bool dense = Eigen::LLT<MatX>(a).info() == Eigen::Success;
    EXPECT_EQ(blocks.Factorize(sparse.valuePtr(), nullptr, 0.0), dense) << "diagonal " << diagonal;
  }
}

TEST(BlockTridiagonalCholesky, ShiftsByASecondMatrixInThePattern) {
  // H + σM through ShiftedCholesky, by blocks and by its band path: the same solution.
  const MatX h = RandomBlockTridiagonal(kStarts, 0.5, 3);
  MatX m = MatX::Zero(h.rows(), h.cols());
  m.diagonal().setConstant(2.0);
  ShiftedCholesky by_blocks(h.sparseView(), m.sparseView(), kStarts);
  ShiftedCholesky banded(h.sparseView(), m.sparseView());
  const bool positive = Eigen::LLT<MatX>(h + 3.0 * m).info() == Eigen::Success;
  ASSERT_TRUE(positive);
  ASSERT_TRUE(by_blocks.Factorize(3.0));
  ASSERT_TRUE(banded.Factorize(3.0));
  const VecX b = VecX::Ones(h.rows());
  const VecX expected = Eigen::LLT<MatX>(h + 3.0 * m).solve(b);
  EXPECT_LT((by_blocks.Solve(b) - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LT((banded.Solve(b) - expected).norm(), 1e-12 * expected.norm());
}

TEST(BlockTridiagonalCholesky, RefusesAPatternBeyondTheNeighbouringBlocks) {
  MatX a = RandomBlockTridiagonal(kStarts, 12.0, 4);
  a(15, 2) = a(2, 15) = 0.5;  // block 3 with block 0
  BlockTridiagonalCholesky blocks;
  const SparseMat sparse = a.sparseView();
  EXPECT_FALSE(blocks.Analyze(sparse, kStarts));
  EXPECT_FALSE(blocks.Analyze(SparseMat(RandomBlockTridiagonal(kStarts, 12.0, 4).sparseView()), {0, 4, 30}));
}

}  // namespace block_tridiagonal_cholesky_test
}  // namespace drillflex::solvers
