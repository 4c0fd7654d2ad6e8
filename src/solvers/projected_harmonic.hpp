// Reduced-order harmonic response (method.md §9.2, the forced response of a sweep): the system of
// solvers/harmonic.hpp,
//   A(ω) X = F,   A(ω) = K − ω² M + iω (D + Ω G) + Σ_t (−ω² a_t + iω b_t) T_t,
// solved on a real basis V (n × r, r ≪ n): X ≈ V y with the Galerkin equations
//   (Vᵀ A(ω) V) y = Vᵀ F,
// an r × r dense complex system per frequency. Vᵀ K V, Vᵀ M V, … are formed once; a frequency then
// costs O(r²) (ProjectedHarmonicSolver) instead of a sparse factorization of A(ω).
//
// The basis (BuildKrylovBasis) spans the response to the loads over the band of the sweep; the
// solve works in the Ritz modes of the projected pencil (ProjectedHarmonicSolver).
#pragma once

#include <memory>
#include <vector>

#include "core/types.hpp"
#include "solvers/harmonic.hpp"

namespace drillflex::solvers {

// A rational Krylov basis of the response to the loads F (n × p) over a band of frequencies: the
// static block (K − σ₀M)⁻¹ F (σ₀ = 0, or −(10⁻² ω_hi)² when K is singular) and, at each of
// `shifts` expansion frequencies ω_j spread evenly over [ω_lo, ω_hi], the blocks
//   W_0 = (K − ω_j² M)⁻¹ F,   W_{k+1} = (K − ω_j² M)⁻¹ M W_k   (k < depth − 1),
// every column M-orthonormalized against those before it (dropped when its M-norm falls below
// 1e-8 of what it was: already in the span). The span of W_0 … W_{d−1} holds the undamped response
// at ω_j and its first d − 1 derivatives in ω²; the Galerkin projection of the symmetric pencil
// matches 2d of them (moment matching: Grimme 1997, "Krylov projection methods for model reduction", PhD thesis,
// Univ. of Illinois, ch. 3; Bai 2002, "Krylov subspace techniques for reduced-order modeling of
// large-scale dynamical systems", Appl. Numer. Math. 43:9), i.e. the load-dependent Ritz vectors of
// Wilson, Yuan & Dickens (1982, "Dynamic analysis by direct superposition of Ritz vectors",
// Earthq. Eng. Struct. Dyn. 10:813) taken about several shifts. Only the modes the loads excite
// enter, with no eigenproblem: J + 1 real sparse factorizations and J·d·p solves. K − ω_j²M is
// indefinite inside the spectrum (LDLT with the LU fallback of solvers/linear_solver.hpp).
//
// Load patterns with bands of their own (`pattern_bands`: an excitation that follows the rotary
// speed sees only its own multiple of the RPM range; a motor one frequency) are solved only at the
// shifts within one shift spacing of their band; every band's top (a single-frequency band's
// frequency) is an expansion frequency too (one more factorization each, shared when they
// coincide): the basis then holds no response of a load at frequencies it never sees (the bundled
// example's sweep: 134 vectors instead of 196 at the same accuracy, docs/validation.md "Reduced
// sweep"). The caller may add vectors of its own (`extra_vectors`, e.g. a fixed frequency's damped
// response).
struct FrequencyBand {
  double lowest = 0.0, highest = 0.0;  // rad/s
};

struct KrylovBasisOptions {
  double lowest_frequency = 0.0;   // ω_lo, rad/s
  double highest_frequency = 0.0;  // ω_hi, rad/s
  int shifts = 12;
  int depth = 2;
  std::vector<FrequencyBand> pattern_bands;  // one per load pattern; empty: every pattern at every shift
  // Vectors taken into the basis as they are (M-orthonormalized after the static block): e.g. the
  // exact damped response at a fixed excitation frequency, which no undamped shift spans.
  MatX extra_vectors;
};

struct KrylovBasis {
  MatX vectors;  // V (n × r), M-orthonormal columns
  std::vector<double> shifts;  // the expansion frequencies ω_j, rad/s
};

// Throws LogicError on bad sizes or options (0 ≤ ω_lo ≤ ω_hi, ω_hi > 0, shifts ≥ 1, depth ≥ 1),
// SolverError when a shifted matrix cannot be factorized.
KrylovBasis BuildKrylovBasis(const SparseMat& K, const SparseMat& M, const MatX& load_patterns,
                             const KrylovBasisOptions& options);

// The Galerkin projection of a LinearSystem and its frequency terms on a basis, solved in the Ritz
// modes of the projected undamped pencil (K_r, M_r + Σ_t a_t,ref T_t,r) with the terms' mass
// coefficients a_t,ref of a reference frequency: Ψ (r × r) diagonalizes it, Ψᵀ K_r Ψ = Λ,
// Ψᵀ M_ref,r Ψ = I. In those coordinates the matrix at ω is diagonal but for the damping and the
// change of the frequency terms from the reference, and only the Ritz modes near ω (|ω_j − ω| ≤
// near_window · ω) are strongly coupled. Each frequency is then solved by
//   z ← z + P⁻¹ (g − A z),   z₀ = P⁻¹ g,
// P the block of the near modes (exact, with its couplings to all the others) and the diagonal of
// the far ones: P⁻¹ r = [S⁻¹ (r_n − A_nf D_f⁻¹ r_f); D_f⁻¹ (r_f − A_fn z_n)], S = A_nn − A_nf D_f⁻¹
// A_fn (the Schur complement; iterative refinement with a block-diagonal-plus-coupling
// preconditioner), until ‖g − A z‖ ≤ 1e-10 ‖g‖ (the reduced equations solved, not approximated),
// with a dense LU of A when it does not converge in 30 steps or more than half the modes are near.
// A step costs O(r² m) against O(r³) for the LU.
struct ProjectedSolveOptions {
  double near_window = 0.25;  // relative half-width of the window of the near Ritz modes
};

class ProjectedHarmonicSolver {
 public:
  // `reference`: the terms' coefficients at the reference frequency (only their masses are used);
  // empty: none. Throws LogicError on sizes that do not match (as HarmonicSolver), SolverError when
  // the projected mass is not positive definite.
  ProjectedHarmonicSolver(const LinearSystem& system, const std::vector<SparseMat>& terms, MatX basis,
                          const std::vector<FrequencyTermCoefficients>& reference = {},
                          ProjectedSolveOptions options = {});

  // X ≈ V y, (Vᵀ A(ω) V) y = Vᵀ F with the coefficient pairs of the terms (one per term). Throws
  // SolverError when the reduced matrix is singular at ω (reciprocal condition number below
  // 1e-14: an undamped resonance) or the solution is not finite; LogicError as HarmonicSolver.
  ComplexMat Solve(double frequency, const ComplexMat& loads, double rotor_speed,
                   const std::vector<FrequencyTermCoefficients>& terms) const;

  Eigen::Index size() const { return basis_.rows(); }
  Eigen::Index basis_size() const { return basis_.cols(); }
  const VecX& ritz_eigenvalues() const { return ritz_eigenvalues_; }  // ω² of the Ritz modes, ascending

 private:
  Eigen::MatrixXcd Assemble(double frequency, double rotor_speed, const std::vector<FrequencyTermCoefficients>& terms) const;

  ProjectedSolveOptions options_;
  MatX basis_;                   // V Ψ: the Ritz modes
  VecX ritz_eigenvalues_;
  MatX stiffness_, mass_, damping_, gyroscopic_;  // Ψᵀ Vᵀ K V Ψ, …, r × r (empty D, G: zero)
  std::vector<MatX> terms_;
};

}  // namespace drillflex::solvers
