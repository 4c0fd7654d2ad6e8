// solvers/small_lu: P A = L U with partial pivoting (complex: on |Re| + |Im|), and A⁻¹ B, against the
// matrix itself (backward error at round-off) and against Eigen's PartialPivLU.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/LU>

#include "solvers/small_lu.hpp"

namespace drillflex::solvers {
namespace small_lu_test {

using ComplexMat = Eigen::MatrixXcd;

// ‖A X − B‖ / (‖A‖ ‖X‖ + ‖B‖), Frobenius.
double BackwardError(const ComplexMat& a, const ComplexMat& x, const ComplexMat& b) {
  return (a * x - b).norm() / (a.norm() * x.norm() + b.norm());
}

TEST(SmallComplexLu, SolvesRandomSystemsToRoundOff) {
  std::srand(7);
  for (const int n : {1, 2, 7, 18, 25}) {
    const ComplexMat a = ComplexMat::Random(n, n);
    const ComplexMat b = ComplexMat::Random(n, n == 18 ? 18 : 3);
    SmallComplexLu lu;
    lu.compute(a);
    const ComplexMat x = lu.solve(b);
    const ComplexMat reference = Eigen::PartialPivLU<ComplexMat>(a).solve(b);
    EXPECT_LT(BackwardError(a, x, b), 1e-14) << "n = " << n;
    EXPECT_LT((x - reference).norm() / reference.norm(), 1e-10) << "n = " << n;
  }
}

// A zero leading entry needs the row exchange; the pivots are the largest |Re| + |Im| of their
// column: in column 0, 3i (row 2) beats 0.1 + 0.1i (row 1) and the zero on the diagonal.
TEST(SmallComplexLu, PivotsOnTheLargestRealPlusImaginaryMagnitude) {
  using C = std::complex<double>;
  ComplexMat a(3, 3);
  a << C(0, 0), C(1, 0), C(2, 1),
       C(0.1, 0.1), C(4, 0), C(0, 1),
       C(0, 3), C(1, 1), C(1, 0);
  SmallComplexLu lu;
  lu.compute(a);
  EXPECT_EQ(lu.matrixLU()(0, 0), C(0, 3));  // row 2 moved up
  const ComplexMat b = ComplexMat::Identity(3, 3);
  EXPECT_LT(BackwardError(a, lu.solve(b), b), 1e-15);
  // |L| ≤ 1 below the diagonal in the pivots' measure.
  for (int j = 0; j < 3; ++j) {
    for (int i = j + 1; i < 3; ++i) {
      EXPECT_LE(std::abs(lu.matrixLU()(i, j).real()) + std::abs(lu.matrixLU()(i, j).imag()), 1.0 + 1e-15);
    }
  }
}

// A singular matrix (a zero column) leaves a zero pivot for the caller to find, and no NaN in
// the factors.
TEST(SmallComplexLu, ZeroColumnLeavesAZeroPivot) {
  ComplexMat a = ComplexMat::Random(5, 5);
  a.col(2).setZero();
  SmallComplexLu lu;
  lu.compute(a);
  EXPECT_EQ(lu.matrixLU().diagonal().cwiseAbs().minCoeff(), 0.0);
  EXPECT_TRUE(lu.matrixLU().allFinite());
}

}  // namespace small_lu_test
}  // namespace drillflex::solvers
