// LU with partial pivoting of a banded matrix by LAPACK (dgbtrf / dgbtrs, Anderson et al., "LAPACK
// Users' Guide", 3rd ed., SIAM 1999, §5.3.2): for the time integrator's iteration matrices of a
// string, whose coordinates are numbered along the string so that every non-zero lies within a
// narrow band (a body's block and its neighbours': half bandwidth 2·18 − 1 = 35 for 18-coordinate
// bodies).
//
// Measured on the bundled example's 1872² transient iteration matrix (bench/rotary_transient_bench,
// band 35/35, 1 thread): Eigen::SparseLU in natural order ~9 ms (ATLAS-free reference BLAS here),
// dgbtrf ~1.8 ms; KLU refactor ~3.8 ms; UMFPACK slower still (the header of linear_solver.hpp).
// The band storage is (2 kl + ku + 1) × n: ~1.6 MB for that matrix.
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
