// BandLuSolver (LAPACK dgbtrf/dgbtrs): the band widths of a pattern, solutions against Eigen's dense
// partial-pivot LU on random unsymmetric banded matrices (with unequal lower and upper bands, and
// one that needs row interchanges), and a singular matrix.
#include "solvers/band_lu.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <limits>
#include <random>
#include <vector>

#include "core/error.hpp"

namespace drillflex::solvers {
namespace band_lu_test {

// A random n×n matrix with entries in [−1, 1] on the band −lower..upper and `diagonal` added on
// the diagonal (0: no dominance, so partial pivoting has to interchange rows).
SparseMat RandomBandMatrix(int n, int lower, int upper, double diagonal, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Triplet> triplets;
  for (int j = 0; j < n; ++j) {
    for (int i = std::max(0, j - upper); i <= std::min(n - 1, j + lower); ++i) {
      triplets.emplace_back(i, j, value(generator) + (i == j ? diagonal : 0.0));
    }
  }
  SparseMat matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

TEST(BandWidths, OfABandAndAnArrow) {
  EXPECT_EQ(BandWidths(RandomBandMatrix(40, 3, 5, 1.0, 1)), std::make_pair(3, 5));
  SparseMat arrow(5, 5);
  arrow.insert(0, 0) = 1;
  arrow.insert(4, 0) = 1;
  EXPECT_EQ(BandWidths(arrow), std::make_pair(4, 0));
}

TEST(BandLuSolver, MatchesDenseLuOnRandomBandedMatrices) {
  struct Case {
    int n, lower, upper;
    double diagonal;
  };
  for (const Case c : {Case{300, 35, 35, 40.0}, Case{257, 7, 19, 0.0}, Case{120, 0, 3, 2.0}, Case{1, 0, 0, 3.0}}) {
    const SparseMat a = RandomBandMatrix(c.n, c.lower, c.upper, c.diagonal, 11u + static_cast<unsigned>(c.n));
    const VecX b = VecX::LinSpaced(c.n, -1.0, 2.0);
    const VecX reference = Eigen::PartialPivLU<MatX>(MatX(a)).solve(b);
    BandLuSolver solver;
    solver.Factorize(a);
    EXPECT_EQ(solver.lower_bandwidth(), c.lower);
    EXPECT_EQ(solver.upper_bandwidth(), c.upper);
    const VecX x = solver.Solve(b);
    EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << "n = " << c.n;
    EXPECT_LT((a * x - b).norm(), 1e-12 * (MatX(a).norm() * x.norm())) << "n = " << c.n;
  }
}

TEST(BandLuSolver, RefactorizesANewMatrixOfAnotherBand) {
  BandLuSolver solver;
  solver.Factorize(RandomBandMatrix(100, 2, 2, 10.0, 3));
  const SparseMat wider = RandomBandMatrix(100, 9, 4, 10.0, 4);
  solver.Factorize(wider);
  const VecX b = VecX::Ones(100);
  EXPECT_LT((wider * solver.Solve(b) - b).norm(), 1e-12 * b.norm() * MatX(wider).norm());
}

TEST(BandLuSolver, RejectsSingularAndNonFiniteMatrices) {
  SparseMat a = RandomBandMatrix(50, 2, 2, 10.0, 5);
  for (int j = 5; j <= 9; ++j) a.coeffRef(7, j) = 0.0;  // row 7 zero within its band
  BandLuSolver solver;
  EXPECT_THROW(solver.Factorize(a), SolverError);
  EXPECT_FALSE(solver.has_factorization());
  EXPECT_THROW(solver.Solve(VecX::Ones(50)), LogicError);
  SparseMat b = RandomBandMatrix(50, 2, 2, 10.0, 6);
  b.coeffRef(3, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solver.Factorize(b), SolverError);
}

}  // namespace band_lu_test
}  // namespace drillflex::solvers
