// The block LU of a block-tridiagonal complex matrix against a dense LU (blocks of different
// sizes; real, from one block to 41, the same bits on one and two threads), its refusal of entries outside the structure, and the harmonic solver that uses it: the
// same answers as the general sparse LU on a damped chain (at and between its resonances), and a
// leading block singular at ω (a zero pivot inside the block LU although the whole matrix is
// regular) solved by the general LU instead.
#include "solvers/block_tridiagonal_lu.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "solvers/harmonic.hpp"
#include "random_block_tridiagonal.hpp"

namespace drillflex::solvers {
namespace block_tridiagonal_lu_test {

using Complex = std::complex<double>;
using ComplexSparse = Eigen::SparseMatrix<Complex>;

ComplexSparse RandomBlockTridiagonal(const std::vector<Eigen::Index>& starts, Complex shift, unsigned seed) {
  return testing::RandomBlockTridiagonal<Complex>(starts, shift, seed);
}

TEST(BlockTridiagonalLu, MatchesADenseLuOnBlocksOfDifferentSizes) {
  const std::vector<Eigen::Index> starts{0, 3, 8, 12, 18, 19, 25};
  // Shift 0: no diagonal dominance, the partial pivoting inside the blocks does the work.
  for (const Complex shift : {Complex(0.0, 0.0), Complex(4.0, 1.0)}) {
    const ComplexSparse matrix = RandomBlockTridiagonal(starts, shift, 11);
    BlockTridiagonalLu lu;
    ASSERT_TRUE(lu.Analyze(matrix, starts));
    lu.Factorize(matrix);
    EXPECT_GT(lu.smallest_pivot(), 0.0);
    const Eigen::MatrixXcd rhs = Eigen::MatrixXcd::Random(25, 3);
    const Eigen::MatrixXcd x = lu.Solve(rhs);
    const Eigen::MatrixXcd expected = Eigen::MatrixXcd(matrix).partialPivLu().solve(rhs);
    EXPECT_LT((x - expected).norm(), 1e-11 * expected.norm()) << shift;
    // The product with the values held gives the right-hand side back.
    EXPECT_LT((lu.Multiply(x) - rhs).norm(), 1e-12 * rhs.norm());
    // The same pattern refactorized with other values.
    ComplexSparse other = matrix;
    other.coeffs() *= Complex(0.5, -2.0);
    lu.Factorize(other);
    EXPECT_LT((lu.Solve(rhs) - expected / Complex(0.5, -2.0)).norm(), 1e-11 * expected.norm());
  }
}

// The two sweeps meet at the middle block m = ⌊N/2⌋: one block (only the middle), two (no sweep from
// the bottom), three, and enough blocks for the sweeps to run on two threads (from 16), odd and even.
TEST(BlockTridiagonalLu, TwoWayEliminationMatchesADenseLuForAnyNumberOfBlocks) {
  for (const int blocks : {1, 2, 3, 4, 16, 17, 41}) {
    std::vector<Eigen::Index> starts{0};
    for (int k = 0; k < blocks; ++k) starts.push_back(starts.back() + 2 + (k * 7) % 5);  // sizes 2 to 6
    const Eigen::SparseMatrix<double> matrix = testing::RandomBlockTridiagonal<double>(starts, 0.0, 100 + blocks);
    RealBlockTridiagonalLu lu;
    ASSERT_TRUE(lu.Analyze(matrix, starts));
    lu.Factorize(matrix);
    const Eigen::Index n = starts.back();
    const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 2);
    const Eigen::MatrixXd expected = Eigen::MatrixXd(matrix).partialPivLu().solve(rhs);
    EXPECT_LT((lu.Solve(rhs) - expected).norm(), 1e-10 * expected.norm()) << blocks << " blocks";
    Eigen::VectorXd x = rhs.col(1);
    lu.SolveInPlace(x);
    EXPECT_LT((x - expected.col(1)).norm(), 1e-10 * expected.col(1).norm()) << blocks << " blocks";
  }
}

// The sweeps' arithmetic does not depend on the threads that run them: the same bits on one and two.
TEST(BlockTridiagonalLu, SameBitsOnOneAndTwoThreads) {
  std::vector<Eigen::Index> starts{0};
  for (int k = 0; k < 40; ++k) starts.push_back(starts.back() + 18);
  const Eigen::SparseMatrix<double> matrix = testing::RandomBlockTridiagonal<double>(starts, 2.0, 7);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Random(starts.back());
  const int previous = omp_get_max_threads();
  auto solve = [&](int threads) {
    omp_set_num_threads(threads);
    RealBlockTridiagonalLu lu;
    lu.Analyze(matrix, starts);
    lu.Factorize(matrix);
    Eigen::VectorXd x = rhs;
    lu.SolveInPlace(x);
    return std::make_pair(x, lu.smallest_pivot());
  };
  const auto one = solve(1);
  const auto two = solve(2);
  omp_set_num_threads(previous);
  EXPECT_EQ(one.second, two.second);
  EXPECT_TRUE((one.first.array() == two.first.array()).all());
}

TEST(BlockTridiagonalLu, RefusesEntriesOutsideTheStructureAndBadBlocks) {
  const std::vector<Eigen::Index> starts{0, 2, 4, 6};
  ComplexSparse matrix = RandomBlockTridiagonal(starts, 3.0, 5);
  BlockTridiagonalLu lu;
  EXPECT_TRUE(lu.Analyze(matrix, starts));
  EXPECT_FALSE(lu.Analyze(matrix, {0, 2, 4}));     // does not reach n
  EXPECT_FALSE(lu.Analyze(matrix, {0, 4, 2, 6}));  // not ascending
  EXPECT_FALSE(lu.Analyze(matrix, {1, 2, 4, 6}));  // not from 0
  matrix.coeffRef(0, 5) = 1.0;                     // block 0 to block 2
  matrix.makeCompressed();
  EXPECT_FALSE(lu.Analyze(matrix, starts));
  EXPECT_FALSE(lu.analyzed());
  EXPECT_THROW(lu.Factorize(matrix), std::exception);
}

// A chain of `nodes` masses in x and y, lightly damped (the pattern of harmonic_test's chain):
// blocks of two coordinates, one per node.
LinearSystem DampedChain(int nodes, double damping) {
  const int n = 2 * nodes;
  std::vector<Triplet> k_entries, m_entries, d_entries;
  for (int i = 0; i < nodes; ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      const int dof = 2 * i + axis;
      m_entries.emplace_back(dof, dof, 3.0 + i % 3);
      if (damping > 0.0) d_entries.emplace_back(dof, dof, damping);
      k_entries.emplace_back(dof, dof, (i == 0 ? 1.0 : 2.0) * 1e5);
      if (i > 0) {
        k_entries.emplace_back(dof, dof - 2, -1e5);
        k_entries.emplace_back(dof - 2, dof, -1e5);
      }
    }
  }
  auto build = [n](const std::vector<Triplet>& entries) {
    SparseMat matrix(n, n);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
  };
  return {build(m_entries), damping > 0.0 ? build(d_entries) : SparseMat(), SparseMat(), build(k_entries)};
}

std::vector<Eigen::Index> NodeBlocks(int nodes) {
  std::vector<Eigen::Index> starts;
  for (int i = 0; i <= nodes; ++i) starts.push_back(2 * i);
  return starts;
}

TEST(HarmonicBlockLu, SameAnswersAsTheGeneralLuAtAndBetweenResonances) {
  const int nodes = 40;
  const LinearSystem system = DampedChain(nodes, 0.5);
  HarmonicOptions options;
  options.block_starts = NodeBlocks(nodes);
  HarmonicSolver blocked(system, options), general(system);
  EXPECT_TRUE(blocked.block_lu());
  EXPECT_FALSE(general.block_lu());
  // The undamped natural frequencies, to hit resonances.
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> modes(MatX(system.stiffness), MatX(system.mass));
  std::vector<double> frequencies{0.0, 1.0, 37.0, 250.0};
  for (int j = 0; j < 5; ++j) frequencies.push_back(std::sqrt(modes.eigenvalues()(j)));
  const ComplexMat loads = ComplexMat::Random(2 * nodes, 2);
  for (const double omega : frequencies) {
    const ComplexMat x = blocked.Solve(omega, loads);
    const ComplexMat expected = general.Solve(omega, loads);
    EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm()) << omega;
  }
  EXPECT_EQ(blocked.block_fallbacks(), 0);
  // A pattern that breaks the blocks (a spring from the first node to the last): the general LU.
  LinearSystem looped = system;
  looped.stiffness.coeffRef(0, 2 * nodes - 2) += -1e3;
  looped.stiffness.coeffRef(2 * nodes - 2, 0) += -1e3;
  EXPECT_FALSE(HarmonicSolver(looped, options).block_lu());
}

TEST(HarmonicBlockLu, ALeadingBlockSingularAtTheFrequencyFallsBackToTheGeneralLu) {
  // Node 0 hangs on its coupling spring alone (K_00 = 1e5 in x and y), M_00 = 3, undamped: at
  // ω = √(K_00/M_00) its block S_0 = K_00 − ω² M_00 is zero exactly, while the whole chain, the
  // other nodes damped, is regular. The block LU meets a zero pivot; the general LU (with row
  // exchanges) solves it.
  const int nodes = 6;
  LinearSystem system = DampedChain(nodes, 0.0);
  SparseMat damping(2 * nodes, 2 * nodes);
  for (int dof = 2; dof < 2 * nodes; ++dof) damping.insert(dof, dof) = 5.0;  // node 0 undamped
  system.damping = damping;
  const double omega = std::sqrt(1e5 / 3.0);  // K_00 = 1e5, M_00 = 3: K_00 − ω² M_00 = 0
  HarmonicOptions options;
  options.block_starts = NodeBlocks(nodes);
  HarmonicSolver blocked(system, options), general(system);
  const ComplexMat loads = ComplexMat::Random(2 * nodes, 1);
  const ComplexMat x = blocked.Solve(omega, loads);
  const ComplexMat expected = general.Solve(omega, loads);
  EXPECT_EQ(blocked.block_fallbacks(), 1);
  EXPECT_LT((x - expected).norm(), 1e-12 * expected.norm());
  // The answer solves the system.
  const Eigen::MatrixXcd dense = MatX(system.stiffness).cast<Complex>() - omega * omega * MatX(system.mass).cast<Complex>() +
                                 Complex(0.0, omega) * MatX(system.damping).cast<Complex>();
  EXPECT_LT((dense * x - loads).norm(), 1e-9 * loads.norm());
}

TEST(HarmonicBlockLu, AnUndampedChainAtItsNaturalFrequenciesIsStillAClearError) {
  const int nodes = 10;
  const LinearSystem system = DampedChain(nodes, 0.0);
  HarmonicOptions options;
  options.block_starts = NodeBlocks(nodes);
  HarmonicSolver blocked(system, options);
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> modes(MatX(system.stiffness), MatX(system.mass));
  const ComplexMat loads = ComplexMat::Ones(2 * nodes, 1);
  for (Eigen::Index j = 0; j < modes.eigenvalues().size(); ++j) {
    EXPECT_THROW(blocked.Solve(std::sqrt(modes.eigenvalues()(j)), loads), SolverError) << j;
  }
}

}  // namespace block_tridiagonal_lu_test
}  // namespace drillflex::solvers
