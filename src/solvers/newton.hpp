// Static equilibrium R(q) = 0 (v = a = 0) by Newton's method with a backtracking line search and
// adaptive load stepping (continuation in the load factor λ from 0 to 1).
//
// Per load step: q ← q ⊕ α dv with K(q) dv = −R(q), K = IterationMatrix(t, q, 0, 0, 1, 0, 0).
// Converged when |R|₂ ≤ residual_tolerance · force scale, or the residual's round-off floor where
// the state cannot resolve that (the change of R when every coordinate moves by one rounding unit,
// StaticProblem::StateResolution, with random signs: 3–5 times the RMS of the rounding itself, a
// coordinate being off by at most half a unit) (or, if increment_tolerance > 0, when
// the Newton correction |dv|∞ ≤ increment_tolerance). A step that fails (iteration limit,
// divergence, non-finite residual, singular matrix, no decrease along dv) is halved and retried
// from the last converged state; below min_step the solver throws a SolverError that says where
// (load factor reached) and why (reason, residual norm, iterations). A step that converges in at
// most fast_iterations iterations lets the next one grow by growth_factor.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "solvers/line_search.hpp"
#include "solvers/problem.hpp"

namespace drillflex::solvers {

struct LoadSteppingOptions {
  bool enabled = true;          // false: one Newton solve at λ = 1, no step cutting
  double initial_step = 1.0;    // first Δλ (1: try the full load first)
  double min_step = 1e-4;       // smallest Δλ before giving up
  double max_step = 1.0;        // largest Δλ
  double growth_factor = 2.0;   // Δλ ← min(growth·Δλ, max_step) after a fast step
  int fast_iterations = 4;      // a step that converges within this many iterations is "fast"
};

struct NewtonOptions {
  double residual_tolerance = 1e-8;  // on |R|₂ relative to the force scale
  // Force scale (N) of the tolerance. ≤ 0: StaticProblem::ForceScale(), and if that is ≤ 0 too,
  // |R| of the start state at full load (λ = 1); 1 N if that is zero as well.
  double force_scale = 0.0;
  double increment_tolerance = 0.0;  // on |dv|∞ (units of v); 0 = not used
  // Largest StaticProblem::StepLength of one Newton step (by default |dv|∞ in units of v; for the
  // string model the largest node translation in m); a longer step is scaled down to it (a trust
  // radius: e.g. a fraction of the hole clearance, so that contacts close gradually). 0 = none.
  // The radius adapts: a step that makes |R| grow more than 4 times is cut to a quarter (down to
  // 1e-3 max_increment) and retried along the same direction; an accepted step doubles it again,
  // up to max_increment. With a trust radius the line search is not used.
  double max_increment = 0.0;
  // Mass-shifted Newton (pseudo-transient continuation, Kelley & Keyes, SIAM J. Numer. Anal. 35,
  // 1998, with a Levenberg–Marquardt schedule): (K + σ M) dv = −R, M the mass matrix
  // (IterationMatrix with cM = σ). σ starts at 0. A step that is not acceptable (longer than
  // max_increment, if set, or |R| above 4 times both the current and the least |R| of the solve;
  // a step under 1e-3 max_increment is always taken) is not taken: it is solved again with σ
  // raised (first to 1e-4 of the largest K_ii / M_ii, then ×10 each time, failing beyond 1e4 of
  // it); an accepted step that lowers |R| lowers σ by 0.3, and below 1e-12 of that scale σ is 0
  // again (Newton's quadratic end game). The increment tolerance counts only at σ = 0. Unlike a
  // step cut to a trust radius, which shortens every component of dv alike, the shift damps the
  // directions K barely resists (a long string's free top in a vertical hole, a pipe lifting off
  // the wall) while the stiff ones still converge. Every solve, accepted or not, is an iteration.
  bool mass_shift = false;
  // With the mass shift: once an accepted step brings |R| to or below this (N; 0 = never), plain
  // Newton steps (σ = 0, full steps, no acceptance test) are tried from there, at most
  // kEndGameIterations of them; if they converge, the solve ends, else it goes on shifted from where
  // the end game began (and tries it again only below half that |R|). The shift's acceptance rule
  // can cycle near the solution (σ lowered, a step that overshoots along a direction K barely
  // resists, σ raised again) where Newton itself converges in a few steps.
  double end_game_residual = 0.0;
  // Modified Newton: > 0 keeps the factorization of the iteration matrix from one iteration to the
  // next while each step lowers |R| to at most this fraction of what it was, and factorizes anew after
  // a step that does not (a solve from a nearby equilibrium: one factorization, then residuals and
  // back-substitutions). 0: a new factorization every iteration (unless the problem's matrix is
  // reusable, StaticProblem::CanReuseIterationMatrix).
  double reuse_contraction = 0.0;
  int max_iterations = 25;           // per load step
  // Over all load steps: the solve stops (fails) once it has used more (0 = no limit), so that a
  // hopeless continuation ends with a message instead of running for minutes.
  int max_total_iterations = 0;
  double divergence_factor = 1e8;    // a step fails when |R| exceeds this × its first |R|
  double time = 0.0;                 // t passed to Residual / IterationMatrix (s)
  LineSearchOptions line_search;
  LoadSteppingOptions load_stepping;
  bool throw_on_failure = true;  // false: return converged = false with the last converged state
  // Called with one line per Newton iteration (|R|, step length, trust radius); none when empty.
  std::function<void(const std::string&)> log;
};

// What a static solve found, whoever found it: the state and how far the search went. Newton's own
// result (NewtonResult) and the static analysis's (analyses::StaticOutcome, then analyses::StaticResult
// with the quantities derived from the state) extend it; none repeats its fields.
struct StaticSolution {
  bool converged = false;
  VecX q;                      // the equilibrium (or, if not converged, where the search stopped)
  int iterations = 0;          // iterations (Newton: over all load steps, failed ones included)
  int load_steps = 0;          // accepted load steps
  double residual_norm = 0.0;  // |R|₂ at q (N)
};

// Newton's raw result: the solution, and the solver's own account of it.
struct NewtonResult : StaticSolution {
  double force_scale = 0.0;   // the scale the tolerance was relative to (N)
  // The residual tolerance applied (N): residual_tolerance × force_scale, or the residual's
  // round-off floor where that is larger (StaticProblem::StateResolution).
  double tolerance = 0.0;
  double load_factor = 0.0;   // λ of q (1 when converged)
  int rejected_steps = 0;     // load steps that failed and were cut
  std::vector<double> residual_history;  // |R|₂ at each iteration of the last accepted step
};

// Finds q with R(q) = 0 at λ = 1, starting from q_start (an equilibrium at λ = 0 when load
// stepping, a guess otherwise). Sets the problem's load factor along the way (and leaves it at
// the last λ tried). Throws SolverError on failure (unless throw_on_failure is false) and never
// returns non-finite values. Uses CanReuseIterationMatrix(): a reusable matrix is factorized once
// per load step and refreshed only when a step along it makes no progress.
NewtonResult SolveStatic(StaticProblem& problem, const VecX& q_start,
                         const NewtonOptions& options = {});

}  // namespace drillflex::solvers
