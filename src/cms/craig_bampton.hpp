// Craig–Bampton reduction of a body's FE model and removal of its rigid-body motion
// (method.md §3 steps 2–7; Craig & Bampton, AIAA J. 6 (1968) 1313).
//
// Eigenproblems are solved in the stiffness-Cholesky form: with K = LLᵀ positive definite,
// K x = λ M x becomes L⁻¹ M L⁻ᵀ y = (1/λ) y, which needs no positive definite M (a lumped mass
// without bending rotary inertia is singular) and yields the lowest modes as the largest 1/λ.
// Degenerate pairs (equal y and z bending of a round section) are kept: the H lowest eigenpairs
// are taken by value, ties included, and every pair is rotated into its x-y and x-z planes.
//
// Rigid-body removal (step 6) is done by construction rather than by detecting λ ≈ 0: the six
// rigid fields R̄ are known exactly in Craig–Bampton coordinates (boundary rows of R, zero modal
// rows: constraint modes reproduce rigid motion), so the elastic eigenvectors are sought in the
// M̄-orthogonal complement of R̄. The reduction checks that there are exactly six zero-energy modes
// (K̄ R̄ ≈ 0 and the complement positive definite) and throws LogicError otherwise.
#pragma once

#include <vector>

#include "cms/reduced_body.hpp"
#include "core/types.hpp"
#include "fe/body_fe_model.hpp"

namespace drillflex::cms {

// The Craig–Bampton basis of steps 2–5 on any FE model.
struct CraigBamptonBasis {
  std::vector<Index> boundary_dofs;  // the first n_b coordinates, in this order
  std::vector<Index> internal_dofs;  // every other DOF, ascending
  MatX transformation;             // T = [[I, 0], [Ψ_ib, Φ_ik]], N × (n_b + H), model DOF order
  VecX fixed_interface_eigenvalues;  // ω² of the H kept fixed-interface modes, ascending
  MatX reduced_stiffness;            // K̄ = Tᵀ K T
  MatX reduced_mass;                 // M̄ = Tᵀ M T
};

// Steps 2–5. K and M are the (symmetric) model matrices; K_ii must be positive definite (the
// boundary restrains every rigid motion), M_ii at least semi-definite with the H kept modes
// massive. Fixed-interface modes are mass-normalised (φᵀ M_ii φ = 1); H is mode_count, or one more
// when the count would keep only one mode of an equal pair (y and z bending). Throws InputError when
// mode_count is negative or exceeds the internal DOF count, LogicError on a bad boundary list or
// an unrestrained interior.
CraigBamptonBasis BuildCraigBamptonBasis(const SparseMat& stiffness, const SparseMat& mass,
                                         const std::vector<Index>& boundary_dofs, Index mode_count);

struct ReductionOptions {
  Index modes_per_body = 12;           // H fixed-interface modes
  double structural_damping = 0.0;   // ζ_s of D_ff = diag(2 ζ_s ω_j)
  std::vector<Index> interface_nodes;  // node indices; empty: the two end nodes {0, n}
};

// Steps 2–7: the floating-frame body. n_f = 6 n_interface − 6 + H. Throws InputError on bad
// options (H out of range, negative damping, bad interface node) and LogicError when the model
// does not have exactly six rigid-body modes.
ReducedBody Reduce(const fe::BodyFeModel& model, const ReductionOptions& options);

// The default interface (both end nodes): n_f = 6 + H.
ReducedBody Reduce(const fe::BodyFeModel& model, Index modes_per_body, double structural_damping);

}  // namespace drillflex::cms
