// Dense LU with partial pivoting of a small matrix (the 18 × 18 Schur complements of
// solvers/block_tridiagonal_lu): P A = L U by the right-looking, unblocked elimination. The pivot of
// a column is its largest |a| (real) or |Re a| + |Im a| (complex: LAPACK's choice in zgetrf, via
// izamax/dcabs1).
//
// Why not Eigen::PartialPivLU: for complex scalars its pivot search takes std::abs, a hypot per
// candidate (7 % of the 3 km vibration sweep, measured with perf), and its blocked algorithm
// packs panels for GEMM kernels that an 18 × 18 matrix is too small to repay (another 4 %).
#pragma once

#include <cmath>
#include <complex>
#include <vector>

#include "core/types.hpp"

namespace drillflex::solvers {

template <typename Scalar>
class SmallLu {
 public:
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

  // Factorizes a square matrix. A zero column below the diagonal leaves a zero pivot: the caller
  // reads the pivots (matrixLU().diagonal()) and decides.
  template <typename Derived>
  void compute(const Eigen::MatrixBase<Derived>& a) {
    lu_ = a;
    const Index n = lu_.rows();
    swaps_.resize(n);
    for (Index k = 0; k < n; ++k) {
      Index pivot = k;
      double largest = Magnitude(lu_(k, k));
      for (Index i = k + 1; i < n; ++i) {
        const double size = Magnitude(lu_(i, k));
        if (size > largest) {
          largest = size;
          pivot = i;
        }
      }
      swaps_[k] = pivot;
      if (pivot != k) lu_.row(k).swap(lu_.row(pivot));
      const Index rest = n - k - 1;
      if (largest == 0.0 || rest == 0) continue;
      lu_.col(k).tail(rest) *= Scalar(1.0) / lu_(k, k);
      lu_.bottomRightCorner(rest, rest).noalias() -= lu_.col(k).tail(rest) * lu_.row(k).tail(rest);
    }
  }

  // P A = L U packed: L unit lower (below the diagonal), U upper.
  const Matrix& matrixLU() const { return lu_; }

  // B ← A⁻¹ B (B a matrix or a vector, or a block of one).
  template <typename Target>
  void solveInPlace(Target&& b) const {
    for (Index k = 0; k < std::ssize(swaps_); ++k) {
      if (swaps_[k] != k) b.row(k).swap(b.row(swaps_[k]));
    }
    lu_.template triangularView<Eigen::UnitLower>().solveInPlace(b);
    lu_.template triangularView<Eigen::Upper>().solveInPlace(b);
  }

  // A⁻¹ B.
  template <typename Derived>
  Matrix solve(const Eigen::MatrixBase<Derived>& b) const {
    Matrix x = b;
    solveInPlace(x);
    return x;
  }

 private:
  static double Magnitude(double a) { return std::abs(a); }
  static double Magnitude(const std::complex<double>& z) { return std::abs(z.real()) + std::abs(z.imag()); }

  Matrix lu_;
  std::vector<Index> swaps_;  // row k was exchanged with row swaps_[k] at step k
};

using SmallComplexLu = SmallLu<std::complex<double>>;
using SmallRealLu = SmallLu<double>;

}  // namespace drillflex::solvers
