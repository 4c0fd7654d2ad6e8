// A sparse direct solver for the iteration matrices of the Newton and time-integration solvers
// and for shift-invert eigen solvers.
//
// Symmetric matrices go to Eigen::SimplicialLDLT (no pivoting, so also fine for the symmetric
// indefinite matrices of K − σM), unsymmetric ones to Eigen::SparseLU. Every LDLT solution is
// checked by its backward error; a failed check (tiny pivots, or a matrix that was not symmetric
// after all) falls back to SparseLU for this factorization.
//
// Ordering: the matrices of a drill string are banded (DOFs numbered along the string). Measured
// on a 20,000-DOF banded SPD matrix (half bandwidth 6 / 30 / 60): SimplicialLDLT with the natural
// ordering 3.8 / 28 / 50 ms, with AMD 15 / 93 / 193 ms, CHOLMOD supernodal 19 / 70 / 272 ms,
// CHOLMOD auto 7 / 43 / 217 ms; SparseLU natural 13 / 49 ms, COLAMD 21 / 139 ms, UMFPACK 22 /
// 186 ms. So SuiteSparse is not used; a matrix whose band is narrow (n · bandwidth ≤ 8 nnz) is
// factorized in its own order, any other with AMD (LDLT) / COLAMD (LU).
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <memory>

#include "core/types.hpp"

namespace drillflex::solvers {

enum class MatrixSymmetry {
  kAuto,         // checked numerically: ‖A − Aᵀ‖_F ≤ 1e-12 ‖A‖_F → symmetric
  kSymmetric,    // trusted (LDLT reads the lower triangle), still verified by the backward error
  kUnsymmetric,  // straight to LU
};

class SparseLinearSolver {
 public:
  SparseLinearSolver();
  ~SparseLinearSolver();
  SparseLinearSolver(SparseLinearSolver&&) noexcept;
  SparseLinearSolver& operator=(SparseLinearSolver&&) noexcept;

  // Factorizes a square matrix. The symbolic analysis is reused while the sparsity pattern stays
  // the same. Throws SolverError if the matrix has non-finite entries or is singular.
  void Factorize(const SparseMat& matrix, MatrixSymmetry symmetry = MatrixSymmetry::kAuto);

  // x with A x = rhs. Throws SolverError if no factorization is held or the solution is not
  // finite. An LDLT solution with backward error > 1e-10 triggers the LU fallback.
  VecX Solve(const VecX& rhs);
  // The same for several right-hand sides (columns) at once.
  MatX SolveColumns(const MatX& rhs);

  bool has_factorization() const { return factorized_; }
  bool uses_lu() const { return use_lu_; }
  Eigen::Index size() const { return matrix_.rows(); }

 private:
  struct Factors;
  void FactorizeLu();
  bool SamePattern(const SparseMat& matrix) const;

  SparseMat matrix_;  // compressed copy, for the backward-error check and the LU fallback
  double matrix_norm_ = 0.0;  // ‖matrix_‖_F
  std::unique_ptr<Factors> factors_;
  bool factorized_ = false;
  bool use_lu_ = false;
  bool natural_order_ = false;
  bool ldlt_analyzed_ = false;
  bool lu_analyzed_ = false;
};

// Half bandwidth max |i − j| over the non-zero entries.
Eigen::Index HalfBandwidth(const SparseMat& matrix);

// The ordering rule of the header: factorize in the matrix's own order when its band is narrow,
// i.e. the band fill n · HalfBandwidth is at most 8 times the entries already there.
bool FactorizeInOwnOrder(const SparseMat& matrix);

}  // namespace drillflex::solvers
