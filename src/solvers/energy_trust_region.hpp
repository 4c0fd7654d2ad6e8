// Static equilibrium as a stable minimum of the total potential energy Π (../shared/spec/
// static-solver.md): a trust-region Newton method on Π itself (Nocedal & Wright, Numerical
// Optimization, 2nd ed., ch. 4), for problems whose static residual R = ∇Π
// (StaticProblem::EnergyChange) and whose tangent K = ∂R/∂dv.
//
// Each iteration minimizes the model m(p) = gᵀp + ½ pᵀHp (g = R(q), H = (K + Kᵀ)/2) over the
// ball ‖p‖ ≤ Δ of the mass norm ‖p‖² = pᵀMp / m̄ (M the problem's mass matrix, m̄ = trace(M)/3, so
// that ‖p‖ reads as a mass-weighted RMS displacement in metres: lateral, axial and rotational
// coordinates compare by their inertia), by Moré–Sorensen: p = −(H + σM)⁻¹g with σ ≥ 0 such that
// H + σM is positive definite (its Cholesky factorization succeeds) and ‖p‖ = Δ unless σ = 0 and the
// Newton step lies inside. Where H is indefinite and g has (almost) no part along the direction of
// negative curvature — the "hard case", a straight compressed string on the axis of a vertical
// hole — the step goes along that direction z (the lowest eigenvector of the pencil (H, M), by
// inverse iteration on the shifted factorization) to the boundary: this takes an unstable
// equilibrium onto its buckled branch.
//
// A step is judged by the energy it releases against what the model predicted,
// ρ = (Π(q) − Π(q ⊕ p)) / (m(0) − m(p)); Δ grows after ρ > 0.75 at the boundary and shrinks after
// ρ < 0.25. The stiff springs of a model (a string's couplings, 1e13 N/m) turn the second-order
// error of a linearized step (a body tilted by δθ shortens by ½δθ²ℓ) into energies far above the
// step's own: before a step is refused, a second-order correction p₂ = −(H + σM)⁻¹ R(q ⊕ p) with the
// same factorization (Fletcher's SOC, Nocedal & Wright §15.6) restores the stiff directions and the
// pair is judged together. Near the solution, where the predicted change is below the energy's
// resolution, an interior Newton step is judged by |R| instead.
//
// Converged when |R|₂ ≤ tolerance (the relative tolerance × the force scale, or the residual's
// round-off floor, solvers/problem.hpp) — or a full Newton step no longer than increment_tolerance —
// and H is positive definite (the equilibrium is stable). An equilibrium with a direction of
// negative curvature is not an answer: the solver steps along that direction and goes on.
// Monotone in Π: it cannot cycle (a contact opening and closing, a penalty's kink, lowers Π or is
// refused).
#pragma once

#include <functional>
#include <limits>
#include <string>

#include "core/types.hpp"
#include "solvers/problem.hpp"

namespace drillflex::solvers {

struct EnergyTrustRegionOptions {
  double residual_tolerance = 1e-8;  // on |R|₂ relative to the force scale
  double force_scale = 0.0;          // N; ≤ 0: StaticProblem::ForceScale(), else |R(q_start)|, else 1 N
  double increment_tolerance = 0.0;  // on |dv|∞ of a full Newton step (units of v); 0 = not used
  int max_iterations = 400;
  double initial_radius = 1e-3;      // Δ₀, m (the mass-weighted RMS displacement of a step)
  double max_radius = 10.0;          // m
  // The energy change (J) per newton of force scale below which two energies are not told apart
  // (a contact's ½ k δ² with δ from positions kilometres from the origin is known to ~1e-9 J); there
  // an interior Newton step is also taken when it lowers |R|.
  double energy_resolution = 1e-12;
  bool require_stable = true;  // false: a stationary point is an answer (no curvature check)
  double time = 0.0;           // t passed to Residual / IterationMatrix
  // One line per iteration (|R|, the energy released, ρ, Δ, σ, the kind of step); none when empty.
  std::function<void(const std::string&)> log;
};

struct EnergyTrustRegionResult {
  VecX q;                      // the equilibrium, or where the solve stopped
  bool converged = false;      // |R| within tolerance (and stable, when required)
  bool stable = false;         // H positive definite at q
  int iterations = 0;          // trust-region iterations (accepted or not)
  int factorizations = 0;      // Cholesky factorizations of H + σM, failed ones included
  int negative_curvature_steps = 0;  // steps along a direction of negative curvature
  int second_order_corrections = 0;  // steps accepted with their SOC
  double residual_norm = 0.0;  // |R|₂ at q, N
  double tolerance = 0.0;      // N
  double force_scale = 0.0;    // N
  double energy_released = 0.0;  // Π(q_start) − Π(q), J
  // The lowest eigenvalue of the pencil (H, M) (1/s²) met where H was indefinite (the most negative
  // over the solve); NaN if it never was.
  double lowest_curvature = std::numeric_limits<double>::quiet_NaN();
  std::string failure;  // why it stopped without converging (empty when converged)
};

// Minimizes Π from q_start at the problem's present load factor. Never throws on a failure to
// converge (see `failure`); throws LogicError on bad arguments or a problem without an energy.
EnergyTrustRegionResult MinimizeEnergy(StaticProblem& problem, const VecX& q_start,
                                       const EnergyTrustRegionOptions& options = {});

}  // namespace drillflex::solvers
