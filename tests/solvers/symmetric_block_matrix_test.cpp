// solvers::SymmetricBlockMatrix against dense algebra: the symmetric part of an unsymmetric
// block-tridiagonal matrix and its product, an outer product added within the blocks, and the
// shapes it refuses.
#include "solvers/symmetric_block_matrix.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/error.hpp"

namespace drillflex::solvers {
namespace symmetric_block_matrix_test {

const std::vector<Eigen::Index> kStarts = {0, 4, 9, 12, 18, 20};

// An unsymmetric matrix with the blocks' tridiagonal shape (every entry of it present).
MatX RandomUnsymmetric(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const Eigen::Index n = kStarts.back();
  MatX a = MatX::Zero(n, n);
  for (std::size_t k = 0; k + 1 < kStarts.size(); ++k) {
    const Eigen::Index end = k + 2 < kStarts.size() ? kStarts[k + 2] : kStarts[k + 1];
    for (Eigen::Index i = kStarts[k]; i < end; ++i) {
      for (Eigen::Index j = kStarts[k]; j < end; ++j) a(i, j) = uniform(rng);
    }
  }
  return a;
}

// `a` in block storage (analysed and assigned); false when it does not fit the blocks.
bool InBlocks(const MatX& a, bool symmetrize, SymmetricBlockMatrix& blocks) {
  const SparseMat sparse = a.sparseView(0.0, 0.0);
  if (!blocks.Analyze(sparse, kStarts, symmetrize)) return false;
  blocks.Assign(sparse.valuePtr());
  return true;
}

TEST(SymmetricBlockMatrix, MultipliesByTheSymmetricPart) {
  const MatX a = RandomUnsymmetric(1);
  SymmetricBlockMatrix blocks;
  ASSERT_TRUE(InBlocks(a, true, blocks));
  const VecX x = VecX::LinSpaced(a.rows(), -1.0, 2.0);
  const VecX expected = 0.5 * (a + a.transpose()) * x;
  EXPECT_LT((blocks.Multiply(x) - expected).norm(), 1e-13 * expected.norm());
  EXPECT_NEAR(blocks.Quadratic(x), x.dot(a * x), 1e-12 * std::abs(x.dot(a * x)));
  EXPECT_DOUBLE_EQ(blocks.LargestDiagonal(), a.diagonal().cwiseAbs().maxCoeff());
  EXPECT_FALSE(blocks.BlockDiagonal());
}

TEST(SymmetricBlockMatrix, ReadsOnlyTheLowerTriangleUnlessSymmetrizing) {
  const MatX a = RandomUnsymmetric(2);
  SymmetricBlockMatrix blocks;
  ASSERT_TRUE(InBlocks(a, false, blocks));
  const MatX lower = a.triangularView<Eigen::Lower>();
  const MatX symmetric = lower + lower.transpose() - MatX(a.diagonal().asDiagonal());
  const VecX x = VecX::Ones(a.rows());
  EXPECT_LT((blocks.Multiply(x) - symmetric * x).norm(), 1e-13 * (symmetric * x).norm());
}

TEST(SymmetricBlockMatrix, AddsAnOuterProductWithinTheBlocks) {
  const MatX a = RandomUnsymmetric(3);
  SymmetricBlockMatrix blocks;
  ASSERT_TRUE(InBlocks(a, true, blocks));
  const std::vector<double> kept = blocks.values();
  const std::vector<Index> indices = {10, 4, 8};  // blocks 2 and 1: neighbours
  const std::vector<double> values = {0.5, -2.0, 1.5};
  blocks.AddOuterProduct(indices, values, 3.0);
  VecX v = VecX::Zero(a.rows());
  for (std::size_t j = 0; j < indices.size(); ++j) v[indices[j]] = values[j];
  const MatX expected = 0.5 * (a + a.transpose()) + 3.0 * v * v.transpose();
  const VecX x = VecX::LinSpaced(a.rows(), 1.0, 3.0);
  EXPECT_LT((blocks.Multiply(x) - expected * x).norm(), 1e-13 * (expected * x).norm());
  EXPECT_LT((blocks.Multiply(kept, x) - 0.5 * (a + a.transpose()) * x).norm(), 1e-13 * (expected * x).norm());
  EXPECT_THROW(blocks.AddOuterProduct({0, 19}, {1.0, 1.0}, 1.0), LogicError);  // blocks 0 and 4
}

TEST(SymmetricBlockMatrix, RefusesAShapeBeyondTheNeighbouringBlocks) {
  MatX a = RandomUnsymmetric(4);
  a(15, 2) = 0.5;  // block 3 with block 0, below the diagonal
  SymmetricBlockMatrix blocks;
  EXPECT_FALSE(blocks.Analyze(SparseMat(a.sparseView(0.0, 0.0)), kStarts, false));
  MatX b = RandomUnsymmetric(4);
  b(2, 15) = 0.5;  // above the diagonal: read only when symmetrizing
  EXPECT_TRUE(blocks.Analyze(SparseMat(b.sparseView(0.0, 0.0)), kStarts, false));
  EXPECT_FALSE(blocks.Analyze(SparseMat(b.sparseView(0.0, 0.0)), kStarts, true));
}

}  // namespace symmetric_block_matrix_test
}  // namespace drillflex::solvers
