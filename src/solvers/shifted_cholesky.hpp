// Cholesky factorizations of H + σM, H symmetric (the symmetric part of a tangent stiffness) and M
// positive definite (a mass matrix), for a sequence of shifts σ with one analysis of the pattern:
// the trust-region subproblem of solvers/energy_trust_region.hpp. A factorization that meets a
// pivot ≤ 0 fails, and so tells that H + σM is not positive definite (Golub & Van Loan, Matrix
// Computations, 4th ed., §4.2): the test of whether an equilibrium is stable.
//
// A matrix whose band is narrow (a string's coordinates run along it: solvers/linear_solver.hpp's
// rule) is factorized in LAPACK's band storage (dpbtrf / dpbtrs, Anderson et al., LAPACK Users'
// Guide §5.3.2): no permutation or symbolic step per factorization, which in Eigen's simplicial
// Cholesky took more time than the factorization itself (profiled on a vertical-hole robustness
// case: its copies and permutations ~20 % of the solve, the numeric factorization 5 %). Any other
// goes to Eigen::SimplicialLLT with AMD. Given coordinate blocks that the matrix couples only to
// their neighbours (a string's bodies), it is factorized by blocks instead
// (solvers/block_tridiagonal_cholesky.hpp), which skips the band's zeros, and H and M are held in
// block storage (solvers/symmetric_block_matrix.hpp), H's products by blocks too.
#pragma once

#include <memory>
#include <vector>

#include "core/types.hpp"
#include "solvers/block_tridiagonal_cholesky.hpp"
#include "solvers/column_runs.hpp"
#include "solvers/symmetric_block_matrix.hpp"

namespace drillflex::solvers {

class ShiftedCholesky {
 public:
  // H is symmetrized here ((H + Hᵀ)/2); H and M square, of one size, finite. `blocks`: the first
  // coordinate of each block and then n (solvers::Problem::CoordinateBlocks), or empty.
  ShiftedCholesky(const SparseMat& stiffness, const SparseMat& metric, std::vector<Eigen::Index> blocks = {});
  // A new H with the metric kept: where H has the pattern of the first one (a model's tangent has a
  // fixed pattern), its symmetric part is formed entry by entry through maps set up once, without
  // the sparse sums and transposes (which took two thirds of a solve when done each iteration).
  void SetStiffness(const SparseMat& stiffness);
  ~ShiftedCholesky();
  ShiftedCholesky(ShiftedCholesky&&) noexcept;
  ShiftedCholesky& operator=(ShiftedCholesky&&) noexcept;

  // Factorizes H + σM; true when it is positive definite (the factorization succeeded).
  bool Factorize(double shift);
  // (H + σM)⁻¹ rhs with the last successful factorization. Throws LogicError without one.
  VecX Solve(const VecX& rhs) const;

  // H ← H + scale a aᵀ, a sparse (`indices`, `values`) within H's pattern (a body's dense block):
  // a contact's stiffness k a aᵀ switched on or off. Drops the factorization held.
  void AddOuterProduct(const std::vector<Index>& indices, const std::vector<double>& values, double scale);
  // H back to what the constructor was given. Drops the factorization held.
  void RestoreStiffness();

  // (H + Hᵀ)/2 x, with any outer products added; M x (summed as Eigen's sparse product sums it).
  VecX StiffnessTimes(const VecX& x) const;
  VecX MetricTimes(const VecX& x) const;
  // K x for the tangent K last given (its pattern; the values may be of the matrix as it is now),
  // summed as Eigen's sparse product sums it (solvers/column_runs.hpp).
  VecX TangentTimes(const SparseMat& tangent, const VecX& x) const { return tangent_runs_.Multiply(tangent, x); }
  double shift() const { return shift_; }         // σ of the last successful factorization
  int factorizations() const { return count_; }   // attempted, successful or not
  bool has_factorization() const { return factorized_; }

 private:
  struct Factors;
  void Build(const SparseMat& stiffness);
  SparseMat metric_given_;                  // M as given
  SparseMat stiffness_, metric_, shifted_;  // one pattern, the union of H's, Hᵀ's and M's
  std::vector<double> original_;            // the stiffness values last set
  // H's first pattern (compressed: its outer and inner indices) and, per entry of the union
  // pattern, the positions of H(i, j) and H(j, i) in H's values (−1: not in H's pattern).
  std::vector<int> first_outer_, first_inner_;
  std::vector<int> from_entry_, from_transposed_;
  std::unique_ptr<Factors> factors_;
  std::vector<Eigen::Index> blocks_;
  bool by_blocks_ = false;
  // By blocks, H and M live in block storage (solvers/symmetric_block_matrix.hpp) instead of the
  // union pattern: H as set (`block_original_`, kept while outer products change `block_stiffness_`).
  // M's products stay with M's own sparse pattern (MetricTimes).
  SymmetricBlockMatrix block_stiffness_, block_metric_;
  std::vector<double> block_original_;
  bool block_modified_ = false;  // outer products added since H was set
  ColumnRuns tangent_runs_, metric_runs_;  // the products with K's and M's own patterns
  bool metric_coupled_ = true;   // M has blocks below the diagonal
  BlockTridiagonalCholesky block_factors_;
  bool banded_ = false;
  int half_bandwidth_ = 0;
  std::vector<double> band_;  // H + σM's lower band, LAPACK storage (ldab = half_bandwidth + 1)
  bool factorized_ = false;
  double shift_ = 0.0;
  int count_ = 0;
};

}  // namespace drillflex::solvers
