// Eigen solvers for linearized systems.
//
// Undamped modes: the generalized symmetric problem K x = ω² M x (K symmetric positive
// semi-definite, M symmetric positive definite). Dense (Eigen::GeneralizedSelfAdjointEigenSolver)
// up to kDenseModalLimit DOFs, shift-invert Lanczos (Spectra::SymGEigsShiftSolver, mode
// GEigsMode::ShiftInvert, with a sparse LDLT of K − σM) above.
//
// Lanczos with one start vector sees one direction per eigenspace, so it misses copies of
// multiple eigenvalues (the bending pairs of an axisymmetric string). The sparse path therefore
// locks what it found and runs again on the operator deflated by those vectors,
// (I − X Xᵀ M)(K − σM)⁻¹ M, until a run finds nothing nearer the shift than the modes kept.
//
// Damped modes: the first-order (state-space) form of M ü + D u̇ + K u = 0, for any D (damping,
// gyroscopic) and small to medium sizes (dense).
#pragma once

#include <Eigen/Core>

#include "core/types.hpp"

namespace drillflex::solvers {

// At or below this size SolveModes uses the dense solver.
inline constexpr Eigen::Index kDenseModalLimit = 600;

struct ModalResult {
  VecX eigenvalues;  // ω² (rad²/s²), ascending
  MatX vectors;      // mode shapes as columns, M-normalised (xᵀ M x = 1) and M-orthogonal
};

// The `count` eigenvalues of K x = ω² M x nearest to `shift` (rad²/s²), sorted ascending, with
// their modes; for K positive semi-definite and shift = 0 these are the lowest. K may be singular
// (free-free: rigid-body modes at ω² = 0); multiple eigenvalues are returned with all their
// modes. Dense at n ≤ kDenseModalLimit, Lanczos above. count is clamped to n. Throws SolverError
// if M is not positive definite or the iteration does not converge, LogicError on bad sizes or
// unsymmetric matrices.
ModalResult SolveModes(const SparseMat& K, const SparseMat& M, Index count, double shift = 0.0);

// The two paths of SolveModes, callable directly (the Lanczos one falls back to dense when count
// is close to n).
ModalResult SolveModesDense(const SparseMat& K, const SparseMat& M, Index count,
                            double shift = 0.0);
ModalResult SolveModesLanczos(const SparseMat& K, const SparseMat& M, Index count,
                              double shift = 0.0);

// Natural frequencies (Hz) of eigenvalues ω² (negative round-off values give 0).
VecX FrequenciesHz(const VecX& eigenvalues);

struct ComplexModes {
  // Eigenvalues s of the free response u = x e^{st} (1/s): s = −ζ ω_n ± i ω_d. One of each
  // conjugate pair (Im s ≥ 0) and every real (overdamped) one, sorted by |s|.
  Eigen::VectorXcd eigenvalues;
  Eigen::MatrixXcd vectors;     // displacement part x, unit Euclidean norm, largest entry real > 0
  VecX natural_frequencies;     // ω_n = |s| (rad/s)
  VecX damped_frequencies;      // ω_d = Im s (rad/s)
  VecX damping_ratios;          // ζ = −Re s / |s| (dimensionless; 0 for |s| = 0)
};

// The `count` eigenvalues of smallest |s| of (s² M + s D + K) x = 0, from the state-space matrix
// [[0, I], [−M⁻¹K, −M⁻¹D]] (dense, O(n³)). D need not be symmetric. Throws SolverError if M is
// not positive definite or the eigen solver fails.
ComplexModes SolveDampedModes(const SparseMat& K, const SparseMat& D, const SparseMat& M,
                              Index count);

// The same on dense matrices (e.g. a problem projected on a modal basis: r × r); D may be
// non-symmetric (damping plus a skew gyroscopic Ω G). Without vectors (`vectors` left empty) when
// with_vectors is false: about three times faster.
ComplexModes SolveDampedModes(const MatX& K, const MatX& D, const MatX& M, Index count,
                              bool with_vectors = true);

}  // namespace drillflex::solvers
