// Cholesky factorization A = C Cᵀ of a symmetric block-tridiagonal matrix: a string's tangent
// stiffness (shifted by its mass, H + σM), whose coordinates are numbered body by body and whose
// bodies are coupled only to their neighbours. With D_k the diagonal blocks and L_k = A(k+1, k),
// the block Cholesky (Golub & Van Loan, Matrix Computations, 4th ed., 2013, §4.5):
//   S_0 = D_0,   C_k C_kᵀ = S_k,   W_k = L_k C_k⁻ᵀ,   S_{k+1} = D_{k+1} − W_k W_kᵀ;
// solve C Cᵀ x = b by y_k = C_k⁻¹ (b_k − W_{k−1} y_{k−1}) down the string and
// x_k = C_k⁻ᵀ (y_k − W_kᵀ x_{k+1}) back up. A is positive definite exactly when every S_k is (its
// Schur complements are), so a failed block factorization says the matrix is not: the stability
// test of the energy trust region (solvers/shifted_cholesky.hpp). One sweep on one thread: the two
// sweeps of block_tridiagonal_lu.hpp side by side (tried) made the trust region slower on a shared
// machine, each of its ~100 solves a solve then waiting on a second thread.
//
// Why: on a 740-body string (13 324 coordinates, half bandwidth 35) LAPACK's band Cholesky (dpbtrf,
// level-2 updates in the reference BLAS) spends ~n·kd² multiply-adds through the band's zeros; the
// blocks cost ~(7/3) b³ each for b = 18 coordinates a body, dense products of small matrices.
#pragma once

#include <vector>

#include <cstddef>

#include "core/types.hpp"
#include "solvers/symmetric_block_matrix.hpp"

namespace drillflex::solvers {

class BlockTridiagonalCholesky {
 public:
  // Takes the blocks (starts[k] the first row of block k, ascending from 0, then n) and a matrix's
  // pattern (compressed, column major; only its lower triangle is read). False, and unusable, when
  // the blocks do not partition the rows or an entry of the lower triangle lies outside the
  // block-tridiagonal structure.
  bool Analyze(const SparseMat& pattern, const std::vector<Index>& starts);
  // Factorizes the matrix whose lower-triangle values are `values` (in the analysed pattern's order)
  // plus `shift` times `metric_values` (same pattern; null: none). False when it is not positive
  // definite (a block pivot ≤ 0); the factorization is then unusable.
  bool Factorize(const double* values, const double* metric_values, double shift);
  // Factorizes H + σM given in block storage (M null: none; else of H's layout, and its blocks below
  // the diagonal are read only when `metric_coupled`). Needs no Analyze. False when not positive
  // definite.
  bool Factorize(const SymmetricBlockMatrix& stiffness, const SymmetricBlockMatrix* metric, double shift,
                 bool metric_coupled = true);
  // x ← A⁻¹ x with the last successful factorization.
  void SolveInPlace(VecX& x) const;

  bool analysed() const { return assembled_.analysed(); }

 private:
  void Layout(const std::vector<Index>& starts);
  SymmetricBlockMatrix assembled_;  // the matrix of the sparse Factorize, scattered into blocks
  SymmetricBlockMatrix metric_assembled_;
  std::vector<Index> starts_;
  // The factors in one buffer, column major: C_k (lower triangle) and T_k = W_kᵀ = C_k⁻¹ L_kᵀ
  // (n_k × n_{k+1}).
  std::vector<double> storage_;
  std::vector<Index> diagonal_, coupling_;  // offsets into storage_
  bool factorized_ = false;
  Index size(Index k) const { return starts_[k + 1] - starts_[k]; }
};

}  // namespace drillflex::solvers
