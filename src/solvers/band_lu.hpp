// LU with partial pivoting of a banded matrix by LAPACK (dgbtrf / dgbtrs, Anderson et al., "LAPACK
// Users' Guide", 3rd ed., SIAM 1999, §5.3.2): for the time integrator's iteration matrices of a
// string, whose coordinates are numbered along the string so that every non-zero lies within a
// narrow band (a body's block and its neighbours': half bandwidth 2·18 − 1 = 35 for 18-coordinate
// bodies).
//
// Measured (Release, loaded 2-core machine) on a random block-tridiagonal 1872² matrix of the bundled
// example's shape (104 blocks of 18, band 35/35): Eigen::SparseLU in natural order 3.2–5.8 ms,
// dgbtrf 1.7–1.8 ms (Debian's reference BLAS), KLU 6.9–8.4 ms (klu_refactor 3.7–3.9 ms); in the
// transient run of bench/rotary_transient_bench, copy into band storage plus dgbtrf ~2.7 ms a
// factorization at load 7 (SparseLU: ~9 ms at load 1.5, docs/validation.md).
// The band storage is (2 kl + ku + 1) × n values: 1.6 MB for that matrix.
#pragma once

#include <utility>
#include <vector>

#include "core/types.hpp"

namespace drillflex::solvers {

class BandLuSolver {
 public:
  // Factorizes a square sparse matrix; the band is measured on its pattern at every call (O(nnz),
  // ~0.1 ms for the bundled example's). Throws SolverError if an entry is not finite or a pivot is
  // zero or below 1e-14 of the largest (the matrix is singular to working precision).
  void Factorize(const SparseMat& matrix);

  // x with A x = rhs, in place. Throws LogicError without a factorization or on a size mismatch.
  void SolveInPlace(VecX& rhs) const;
  VecX Solve(const VecX& rhs) const;

  bool has_factorization() const { return factorized_; }
  int lower_bandwidth() const { return lower_; }
  int upper_bandwidth() const { return upper_; }

 private:
  int size_ = 0;
  int lower_ = 0;  // kl: A(i, j) = 0 for i > j + kl
  int upper_ = 0;  // ku: A(i, j) = 0 for j > i + ku
  std::vector<double> band_;  // LAPACK band storage, leading dimension 2 kl + ku + 1, column major
  std::vector<int> pivots_;
  bool factorized_ = false;
};

// The lower and upper half bandwidths (kl, ku) of a sparse matrix's pattern.
std::pair<int, int> BandWidths(const SparseMat& matrix);

}  // namespace drillflex::solvers
