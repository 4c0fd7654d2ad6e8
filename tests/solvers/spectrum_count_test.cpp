// Sylvester's count of the eigenvalues below a shift against the eigenvalues themselves: a fixed–free
// spring–mass chain (all its eigenvalues, between and beside them), an unsymmetric K counted by its
// symmetric part, and a shift on an eigenvalue (no count).
#include "solvers/spectrum_count.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <vector>

#include "toy_problems.hpp"

namespace drillflex::solvers {
namespace spectrum_count_test {

using testing::ChainStiffness;

SparseMat Diagonal(const VecX& values) {
  SparseMat matrix(values.size(), values.size());
  for (Eigen::Index i = 0; i < values.size(); ++i) matrix.insert(i, i) = values(i);
  matrix.makeCompressed();
  return matrix;
}

TEST(SpectrumCount, CountsTheEigenvaluesOfAChainBelowEveryShift) {
  const int n = 40;
  const SparseMat stiffness = ChainStiffness(n, 2e4, true);
  VecX masses(n);
  for (int i = 0; i < n; ++i) masses(i) = 1.0 + 0.1 * (i % 4);
  const SparseMat mass = Diagonal(masses);
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> exact{MatX(stiffness), MatX(mass)};
  const VecX lambda = exact.eigenvalues();
  EXPECT_EQ(CountEigenvaluesBelow(stiffness, mass, 0.0), 0);
  EXPECT_EQ(CountEigenvaluesBelow(stiffness, mass, 1.01 * lambda(n - 1)), n);
  for (int j = 0; j + 1 < n; ++j) {
    const double between = 0.5 * (lambda(j) + lambda(j + 1));
    EXPECT_EQ(CountEigenvaluesBelow(stiffness, mass, between), j + 1) << j;
  }
  // A band from between λ_3 and λ_4 to between λ_20 and λ_21 holds λ_4 … λ_20: 17 of them.
  EXPECT_EQ(CountEigenvaluesBetween(stiffness, mass, 0.5 * (lambda(3) + lambda(4)), 0.5 * (lambda(20) + lambda(21))), 17);
}

TEST(SpectrumCount, AnUnsymmetricStiffnessIsCountedByItsSymmetricPart) {
  const int n = 12;
  SparseMat stiffness = ChainStiffness(n, 1e3, true);
  const SparseMat mass = Diagonal(VecX::Ones(n));
  const Eigen::SelfAdjointEigenSolver<MatX> exact{MatX(stiffness)};
  // A skew part (a follower load's, friction's) leaves the symmetric part, and the count, alone.
  SparseMat skew(n, n);
  for (int i = 0; i + 1 < n; ++i) {
    skew.insert(i, i + 1) = 50.0;
    skew.insert(i + 1, i) = -50.0;
  }
  const SparseMat unsymmetric = stiffness + skew;
  for (int j = 0; j + 1 < n; ++j) {
    const double between = 0.5 * (exact.eigenvalues()(j) + exact.eigenvalues()(j + 1));
    EXPECT_EQ(CountEigenvaluesBelow(unsymmetric, mass, between), j + 1) << j;
  }
}

TEST(SpectrumCount, AShiftOnAnEigenvalueGivesNoCount) {
  // k − σ m = 0 exactly (k = 4, m = 1, σ = 4): a zero pivot.
  const SparseMat k = Diagonal(VecX::Constant(1, 4.0)), m = Diagonal(VecX::Ones(1));
  EXPECT_EQ(CountEigenvaluesBelow(k, m, 4.0), -1);
  EXPECT_EQ(CountEigenvaluesBelow(k, m, 3.0), 0);
  EXPECT_EQ(CountEigenvaluesBelow(k, m, 5.0), 1);
}

}  // namespace spectrum_count_test
}  // namespace drillflex::solvers
