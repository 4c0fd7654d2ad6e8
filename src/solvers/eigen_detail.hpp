// Internal helpers shared by the dense and Lanczos paths of the eigen solvers (not a public API).
#pragma once

#include "core/types.hpp"
#include "solvers/eigen.hpp"

namespace drillflex::solvers::detail {

// Throws LogicError unless `matrix` is n×n and symmetric to ‖A − Aᵀ‖_F ≤ 1e-10 ‖A‖_F.
void CheckSymmetric(const SparseMat& matrix, Eigen::Index n, const char* name);

// Flips each column so that its entry of largest magnitude is positive (a reproducible sign).
void NormalizeSigns(MatX& vectors);

struct DenseDefinitePairs {
  VecX values;   // ascending
  MatX vectors;  // B-normalised columns
};

// A x = μ B x for symmetric A and symmetric positive definite B (dense), by the Cholesky
// reduction C = L⁻¹ A L⁻ᵀ, B = L Lᵀ, x = L⁻ᵀ y (Golub & Van Loan §8.7.2). Returns false (and
// leaves `pairs` untouched) if B is not positive definite; throws SolverError if the symmetric
// eigen solver fails.
bool SolveDenseDefinite(const MatX& a, const MatX& b, DenseDefinitePairs& pairs);

// The `count` pairs whose eigenvalues are nearest to `shift`, sorted ascending, signs normalised.
ModalResult SelectNearest(const VecX& eigenvalues, const MatX& vectors, Eigen::Index count,
                          double shift);

}  // namespace drillflex::solvers::detail
