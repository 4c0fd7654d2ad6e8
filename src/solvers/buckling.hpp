// Linearized buckling: (K + λ K_G) x = 0, with K the (positive definite) stiffness of the
// supported structure and K_G the geometric stiffness of a reference load; λ is the multiplier
// of that load at which the structure buckles.
//
// Solved as the symmetric-definite problem −K_G x = ν K x with ν = 1/λ (K positive definite, so
// K_G may be indefinite or singular: directions without geometric stiffness give ν = 0, λ = ∞).
// The smallest positive λ are the largest positive ν. Dense: GeneralizedSelfAdjointEigenSolver;
// sparse: Spectra's Lanczos in Cholesky mode (C = L⁻¹(−K_G)L⁻ᵀ, K = L Lᵀ) for the largest ν,
// which converges fast because the ν of higher modes cluster at 0.
#pragma once

#include "core/types.hpp"

namespace drillflex::solvers {

// At or below this size SolveBuckling uses the dense solver.
inline constexpr Eigen::Index kDenseBucklingLimit = 600;

struct BucklingResult {
  VecX multipliers;  // the smallest positive λ, ascending (dimensionless); may hold fewer than
                     // asked, none if the reference load only stiffens the structure
  MatX modes;        // buckling modes as columns, K-normalised (xᵀ K x = 1)
};

// The `count` smallest positive load multipliers λ with (K + λ K_G) x = 0. Throws SolverError if
// K is not positive definite (the structure must be supported) or Lanczos does not converge,
// LogicError on bad sizes or unsymmetric matrices.
BucklingResult SolveBuckling(const SparseMat& K, const SparseMat& K_G, Index count = 1);

BucklingResult SolveBucklingDense(const SparseMat& K, const SparseMat& K_G, Index count = 1);
BucklingResult SolveBucklingLanczos(const SparseMat& K, const SparseMat& K_G, Index count = 1);

}  // namespace drillflex::solvers
