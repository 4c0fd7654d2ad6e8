// Backtracking line search along a Newton direction, q(α) = q ⊕ α·dv (Armijo condition with
// quadratic interpolation; Dennis & Schnabel, "Numerical Methods for Unconstrained Optimization
// and Nonlinear Equations", §6.3).
#pragma once

#include <functional>

#include "core/types.hpp"
#include "solvers/problem.hpp"

namespace drillflex::solvers {

// A merit of a trial state (q, R(q)) to decrease along the search direction.
using MeritFunction = std::function<double(const VecX& q, const VecX& residual)>;

struct LineSearchOptions {
  bool enabled = true;
  double sufficient_decrease = 1e-4;  // Armijo constant c in φ(α) ≤ φ(0) + c α φ'(0)
  double min_step = 1e-6;             // smallest step length α tried
  // Empty: φ = ½|R|², whose slope along the exact Newton direction is φ'(0) = −|R|².
  // Otherwise a potential Π whose gradient along the increment is R (e.g. the total potential
  // energy of a conservative problem), slope φ'(0) = Rᵀdv; where dv is not a descent direction
  // of Π (φ'(0) ≥ 0, e.g. near an unstable equilibrium) the search falls back to ½|R|².
  MeritFunction merit;
};

struct LineSearchResult {
  double step = 1.0;  // α taken
  VecX q;             // q ⊕ α·dv
  VecX residual;      // R at q
  bool sufficient_decrease = false;  // the Armijo condition holds at α
  bool decreased = false;            // the merit decreased at all (else the step is useless)
  int residual_evaluations = 0;
};

// Searches α in [min_step, 1] along q ⊕ α·dv for the static residual R(t, q, 0, 0). Returns the
// first α that satisfies the Armijo condition, else the trial with the lowest merit. A trial
// whose residual is not finite counts as an infinite merit. With options.enabled false returns
// the full step.
LineSearchResult BacktrackingLineSearch(const Problem& problem, double t, const VecX& q,
                                        const VecX& residual, const VecX& dv,
                                        const LineSearchOptions& options);

}  // namespace drillflex::solvers
