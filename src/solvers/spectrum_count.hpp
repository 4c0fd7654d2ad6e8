// How many eigenvalues of a symmetric pencil lie below a shift, without solving for them:
// Sylvester's law of inertia (Parlett, "The Symmetric Eigenvalue Problem", SIAM 1998, §3.3) — the
// number of λ < σ of K φ = λ M φ (M positive definite) equals the number of negative pivots of the
// LDLᵀ factorization of K − σM. The vibration sweep uses it to see, before it builds a reduced
// basis, how many resonances its band crosses (analyses/vibration_analysis.cpp).
#pragma once

#include "core/types.hpp"

namespace drillflex::solvers {

// The count for the symmetric part (K + Kᵀ)/2 (a linearized string's K is slightly unsymmetric
// with friction; its undamped modes are those of the symmetric part to that order). -1 when the
// count cannot be trusted: the factorization (no pivoting) meets a zero or non-finite pivot, e.g.
// σ on an eigenvalue.
int CountEigenvaluesBelow(const SparseMat& K, const SparseMat& M, double sigma);

// The count of eigenvalues λ in [lowest, highest) (two factorizations of one symmetric part); -1 when
// either fails.
int CountEigenvaluesBetween(const SparseMat& K, const SparseMat& M, double lowest, double highest);

}  // namespace drillflex::solvers
