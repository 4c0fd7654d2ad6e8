// Cholesky factorizations of H + σM, H symmetric (the symmetric part of a tangent stiffness) and M
// positive definite (a mass matrix), for a sequence of shifts σ with one symbolic analysis: the
// trust-region subproblem of solvers/energy_trust_region.hpp. A factorization that meets a pivot
// ≤ 0 fails, and so tells that H + σM is not positive definite (Golub & Van Loan, Matrix
// Computations, 4th ed., §4.2): the test of whether an equilibrium is stable.
//
// Ordering as solvers/linear_solver.hpp: the matrix's own order when its band is narrow (a string's
// coordinates run along it), AMD otherwise.
#pragma once

#include <memory>

#include "core/types.hpp"

namespace drillflex::solvers {

class ShiftedCholesky {
 public:
  // H is symmetrized here ((H + Hᵀ)/2); H and M square, of one size, finite.
  ShiftedCholesky(const SparseMat& stiffness, const SparseMat& metric);
  ~ShiftedCholesky();
  ShiftedCholesky(ShiftedCholesky&&) noexcept;
  ShiftedCholesky& operator=(ShiftedCholesky&&) noexcept;

  // Factorizes H + σM; true when it is positive definite (the factorization succeeded).
  bool Factorize(double shift);
  // (H + σM)⁻¹ rhs with the last successful factorization. Throws LogicError without one.
  VecX Solve(const VecX& rhs) const;

  const SparseMat& stiffness() const { return stiffness_; }  // (H + Hᵀ)/2
  const SparseMat& metric() const { return metric_; }
  double shift() const { return shift_; }         // σ of the last successful factorization
  int factorizations() const { return count_; }   // attempted, successful or not
  bool has_factorization() const { return factorized_; }

 private:
  struct Factors;
  SparseMat stiffness_, metric_, shifted_;  // one pattern, the union of H's and M's
  std::unique_ptr<Factors> factors_;
  bool natural_order_ = false;
  bool factorized_ = false;
  double shift_ = 0.0;
  int count_ = 0;
};

}  // namespace drillflex::solvers
