#include "solvers/newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/profile.hpp"
#include "solvers/iteration_matrix_lu.hpp"
#include "solvers/linear_solver.hpp"

namespace drillflex::solvers {
namespace {

// What one Newton solve at a fixed load factor ended with.
struct StepOutcome {
  bool converged = false;
  VecX q;
  double residual_norm = 0.0;  // last finite |R|₂
  int iterations = 0;
  std::vector<double> history;
  std::string reason;  // why it failed
  std::string largest;  // the largest residual entry at residual_norm and where (LargestEntry)
};

// The largest entry of a residual and where it sits (StaticProblem::DescribeCoordinate).
std::string LargestEntry(const StaticProblem& problem, const VecX& residual) {
  if (residual.size() == 0 || !residual.allFinite()) return "no finite residual";
  Eigen::Index row = 0;
  const double largest = residual.cwiseAbs().maxCoeff(&row);
  return fmt::format("largest {:.3e} at {}", largest, problem.DescribeCoordinate(row));
}

// Newton iterations at the load factor currently set on the problem.
class NewtonStepper {
 public:
  NewtonStepper(const StaticProblem& problem, const NewtonOptions& options, double tolerance)
      : problem_(problem),
        options_(options),
        tolerance_(tolerance),
        zero_(VecX::Zero(problem.num_velocities())) {
    linear_solver_.SetBlocks(problem.CoordinateBlocks());
  }

  StepOutcome Run(const VecX& q_start);

 private:
  // The Newton correction dv cut to the trust radius (NewtonOptions::max_increment): a step that
  // makes |R| grow more than kTrustGrowth times is cut to a quarter until it does not (the
  // radius shrinks with it, down to kSmallestRadius of max_increment); after an accepted step the
  // radius grows back (×2, up to max_increment). The acceptance is non-monotone on purpose: a
  // contact that closes raises |R| for an iteration before the next step settles it, and a string
  // falling through its clearance raises it step after step until it lands (regrowing only on a
  // decrease of |R| took V4's load stepping from 39 iterations to 3285).
  LineSearchResult TrustRegionStep(const VecX& q, const VecX& residual, const VecX& dv, double& radius) const;

  // Factorizes K(q) + σ M(q); returns an empty string or the reason it failed.
  std::string Factorize(const VecX& q, double shift = 0.0);
  // At the top of an iteration with |R| = norm: true when the run ends here, converged or with its
  // reason (beyond the iterations allowed, or diverging from the first |R|).
  bool Finished(StepOutcome& out, double norm, double first_norm) const;
  // The iteration's line in the log (when there is one).
  void LogStep(const StepOutcome& out, double norm, const LineSearchResult& search, const VecX& dv, double shift,
               double radius) const;

  // NewtonOptions::mass_shift: the full step along dv if it is acceptable (the shift then lowered),
  // or nothing (the shift raised; `failure` says why when it cannot be raised further).
  // `least_norm`: the least |R| of this solve so far.
  std::optional<LineSearchResult> ShiftedStep(const VecX& q, const VecX& residual, const VecX& dv, double& shift,
                                              double& least_norm, std::string& failure);

  // NewtonOptions::end_game_residual: plain Newton from q, at most kEndGameIterations steps; its
  // outcome (converged or not, the steps it took).
  StepOutcome EndGame(const VecX& q, const VecX& residual);

  const StaticProblem& problem_;
  const NewtonOptions& options_;
  const double tolerance_;
  const VecX zero_;
  bool stale_ = false;  // the factorization held is to be renewed (NewtonOptions::reuse_contraction)
  // The LU of K + σM: block tridiagonal on the problem's coordinate blocks where the matrix has that
  // shape (a string's bodies), else banded or sparse (solvers/iteration_matrix_lu.hpp).
  IterationMatrixLu linear_solver_;
  SparseLinearSolver sparse_;   // when linear_solver_ refuses a nearly singular matrix
  bool by_sparse_lu_ = false;
  bool factorized_ = false;
  SparseMat assembled_;  // the last iteration matrix (its storage reused from call to call)
  VecX Solve(const VecX& rhs) {
    if (by_sparse_lu_) return sparse_.Solve(rhs);
    VecX x = rhs;
    linear_solver_.SolveInPlace(x);
    if (!x.allFinite()) throw SolverError("the solution of the linearized equations is not finite");
    return x;
  }
  double shift_scale_ = 0.0;  // max K_ii / max M_ii, once a shift is needed
  int extra_iterations_ = 0;  // look-ahead solves of ShiftedStep (each counts as an iteration)
};

std::string NewtonStepper::Factorize(const VecX& q, double shift) {
  factorized_ = false;
  SparseMat& k = assembled_;
  try {
    problem_.IterationMatrixInto(k, options_.time, q, zero_, zero_, 1.0, 0.0, shift);
    linear_solver_.Factorize(k);
    factorized_ = true;
    by_sparse_lu_ = false;
    return {};
  } catch (const SolverError&) {
    // A nearly singular matrix (a string not yet held by its loads at a small load factor: its
    // lateral motion free but for round-off) that the block and band LUs refuse by their pivot
    // threshold: the sparse LU with partial pivoting takes it, as the solver did before them, and the
    // trust radius cuts the long step along the free direction.
  }
  try {
    sparse_.Factorize(k, MatrixSymmetry::kUnsymmetric);
    factorized_ = true;
    by_sparse_lu_ = true;
  } catch (const SolverError& error) {
    return fmt::format("the iteration matrix cannot be factorized ({})", error.what());
  }
  return {};
}

constexpr double kTrustGrowth = 4.0;
constexpr int kEndGameIterations = 6;
constexpr double kEndGameDivergence = 1e3;  // an end game whose |R| grows this much is given up
constexpr double kSmallestRadius = 1e-3;

LineSearchResult NewtonStepper::TrustRegionStep(const VecX& q, const VecX& residual, const VecX& dv,
                                                double& radius) const {
  const double norm = residual.norm();
  const double length = problem_.StepLength(q, dv);
  LineSearchResult result;
  while (true) {
    result.step = length > radius ? radius / length : 1.0;
    result.q = problem_.Increment(q, result.step * dv);
    result.residual = problem_.Residual(options_.time, result.q, zero_, zero_);
    ++result.residual_evaluations;
    const double trial = result.residual.allFinite() ? result.residual.norm() : std::numeric_limits<double>::infinity();
    result.decreased = trial < norm;
    const bool acceptable = trial <= kTrustGrowth * norm;
    if (acceptable || radius <= kSmallestRadius * options_.max_increment || length <= radius * 0.25) {
      if (acceptable) radius = std::min(2.0 * radius, options_.max_increment);
      result.decreased = result.decreased || acceptable;
      return result;
    }
    radius = std::max(0.25 * std::min(radius, length), kSmallestRadius * options_.max_increment);
  }
}

StepOutcome NewtonStepper::EndGame(const VecX& q, const VecX& residual) {
  StepOutcome out;
  out.q = q;
  VecX current = residual;
  while (out.iterations < kEndGameIterations) {
    if (!Factorize(out.q).empty()) return out;
    VecX dv;
    try {
      dv = -Solve(current);
    } catch (const SolverError&) {
      return out;
    }
    ++out.iterations;
    const double length = problem_.StepLength(out.q, dv);
    out.q = problem_.Increment(out.q, dv);
    current = problem_.Residual(options_.time, out.q, zero_, zero_);
    if (!current.allFinite()) return out;
    out.residual_norm = current.norm();
    if (out.residual_norm > kEndGameDivergence * residual.norm()) return out;
    out.history.push_back(out.residual_norm);
    if (options_.log) {
      options_.log(fmt::format("  Newton end game {}: |R| {:.4e} N, step {:.3e}", out.iterations, out.residual_norm,
                               length));
    }
    if (out.residual_norm <= tolerance_ ||
        (options_.increment_tolerance > 0.0 && dv.lpNorm<Eigen::Infinity>() <= options_.increment_tolerance)) {
      out.converged = true;
      return out;
    }
  }
  return out;
}

// The mass shift's schedule (NewtonOptions::mass_shift).
constexpr double kFirstShift = 1e-4;    // × max K_ii / max M_ii
constexpr double kShiftRaise = 10.0;
constexpr double kShiftLower = 0.3;
constexpr double kSmallestShift = 1e-12;  // × max K_ii / max M_ii: below it, σ = 0
constexpr double kLargestShift = 1e4;     // × max K_ii / max M_ii: beyond it, the solve fails

std::optional<LineSearchResult> NewtonStepper::ShiftedStep(const VecX& q, const VecX& residual, const VecX& dv,
                                                           double& shift, double& least_norm, std::string& failure) {
  LineSearchResult result;
  result.step = 1.0;
  result.q = problem_.Increment(q, dv);
  result.residual = problem_.Residual(options_.time, result.q, zero_, zero_);
  result.residual_evaluations = 1;
  const double norm = residual.norm();
  const double trial = result.residual.allFinite() ? result.residual.norm() : std::numeric_limits<double>::infinity();
  const double length = problem_.StepLength(q, dv);
  const bool short_enough = options_.max_increment <= 0.0 || length <= options_.max_increment;
  // A step shorter than the smallest trust radius is taken whatever |R| does: near the solution
  // |R| is round-off of the stiff couplings and may rise.
  const bool tiny = options_.max_increment > 0.0 && length <= kSmallestRadius * options_.max_increment;
  // A rise of |R| is taken (a contact that closes raises it for an iteration) up to kTrustGrowth
  // times the current and the least |R| of this solve, so that it cannot creep up step by step.
  const bool bounded = trial <= kTrustGrowth * std::min(norm, least_norm);
  auto accept = [&](LineSearchResult& taken, double taken_norm) {
    taken.decreased = true;
    least_norm = std::min(least_norm, taken_norm);
    if (taken_norm < norm) shift *= kShiftLower;
    if (shift < kSmallestShift * shift_scale_) shift = 0.0;
  };
  if (short_enough && (bounded || tiny)) {
    accept(result, trial);
    return result;
  }
  // The watchdog (Chamberlain, Powell, Lemaréchal & Pedersen, Math. Prog. Study 16, 1982): a step
  // that raises |R| too much is judged by the Newton step after it. A twist of the string that
  // turns its bent bodies about their axes raises |R| by 1e5 for one iteration (second-order terms
  // in the stiff couplings) and the next step settles it. Measured on 3 km of string: from the state
  // where the shifted steps zigzag at |R| ≈ 50 N, plain Newton steps reach the round-off floor
  // (~5 N) in 4 iterations; this look-ahead alone does not yet make that case converge.
  if (short_enough && result.residual.allFinite()) {
    if (std::string failed = Factorize(result.q, shift); failed.empty()) {
      try {
        const VecX second = -Solve(result.residual);
        const double second_length = problem_.StepLength(result.q, second);
        LineSearchResult look_ahead;
        look_ahead.step = 1.0;
        look_ahead.q = problem_.Increment(result.q, second);
        look_ahead.residual = problem_.Residual(options_.time, look_ahead.q, zero_, zero_);
        look_ahead.residual_evaluations = 2;
        ++extra_iterations_;
        const double ahead = look_ahead.residual.allFinite() ? look_ahead.residual.norm()
                                                             : std::numeric_limits<double>::infinity();
        if (ahead < norm && (options_.max_increment <= 0.0 || second_length <= options_.max_increment)) {
          accept(look_ahead, ahead);
          return look_ahead;
        }
      } catch (const SolverError&) {
        // no look-ahead step: raise the shift below
      }
    }
  }
  if (shift_scale_ <= 0.0) {  // the stiffness-to-mass scale, once
    const SparseMat k = problem_.IterationMatrix(options_.time, q, zero_, zero_, 1.0, 0.0, 0.0);
    const SparseMat m = problem_.IterationMatrix(options_.time, q, zero_, zero_, 0.0, 0.0, 1.0);
    const double largest_mass = m.diagonal().cwiseAbs().maxCoeff();
    shift_scale_ = largest_mass > 0.0 ? k.diagonal().cwiseAbs().maxCoeff() / largest_mass : 0.0;
    if (!(shift_scale_ > 0.0) || !std::isfinite(shift_scale_)) {
      failure = "the step is not acceptable and the problem has no mass matrix to shift the iteration matrix by";
      return std::nullopt;
    }
  }
  shift = shift > 0.0 ? kShiftRaise * shift : kFirstShift * shift_scale_;
  if (shift > kLargestShift * shift_scale_) {
    failure = fmt::format("no acceptable step even with the iteration matrix shifted by {:.3g} × the mass matrix",
                          shift / kShiftRaise);
    return std::nullopt;
  }
  return std::nullopt;
}

bool NewtonStepper::Finished(StepOutcome& out, double norm, double first_norm) const {
  if (norm <= tolerance_) {
    out.converged = true;
    return true;
  }
  if (out.iterations >= options_.max_iterations) {
    out.reason = fmt::format("no convergence within {} iterations", options_.max_iterations);
    return true;
  }
  if (norm > options_.divergence_factor * std::max(first_norm, tolerance_)) {
    out.reason = fmt::format("diverging (|R| grew {:.3g} times)", norm / first_norm);
    return true;
  }
  return false;
}

void NewtonStepper::LogStep(const StepOutcome& out, double norm, const LineSearchResult& search, const VecX& dv,
                            double shift, double radius) const {
  if (!options_.log) return;
  options_.log(fmt::format("  Newton {:3d}: |R| {:.4e} N -> {:.4e} N, step {:.3e}{}; {}", out.iterations, norm,
                           search.residual.allFinite() ? search.residual.norm() : -1.0,
                           search.step * problem_.StepLength(out.q, dv),
                           options_.mass_shift ? fmt::format(" (shift {:.3e})", shift)
                           : options_.max_increment > 0.0 ? fmt::format(" (trust radius {:.3e})", radius)
                                                          : "",
                           LargestEntry(problem_, search.residual)));
}

StepOutcome NewtonStepper::Run(const VecX& q_start) {
  StepOutcome out;
  out.q = q_start;
  VecX residual = problem_.Residual(options_.time, out.q, zero_, zero_);
  const bool reuse = problem_.CanReuseIterationMatrix() || options_.reuse_contraction > 0.0;
  double end_game_below = options_.end_game_residual;  // |R| at or below which the end game is tried
  bool fresh = false;  // the factorization belongs to the current q
  double first_norm = -1.0;
  double radius = options_.max_increment;
  double shift = 0.0;  // σ of NewtonOptions::mass_shift
  double least_norm = std::numeric_limits<double>::infinity();
  while (true) {
    if (!residual.allFinite()) {
      out.reason = "the residual became non-finite (NaN or Inf)";
      return out;
    }
    const double norm = residual.norm();
    out.residual_norm = norm;
    out.largest = LargestEntry(problem_, residual);
    out.history.push_back(norm);
    if (first_norm < 0.0) first_norm = norm;
    if (Finished(out, norm, first_norm)) return out;
    if (options_.mass_shift || !reuse || !factorized_ || out.iterations == 0 || stale_) {
      stale_ = false;
      if (std::string failure = Factorize(out.q, shift); !failure.empty()) {
        out.reason = std::move(failure);
        return out;
      }
      fresh = true;
    }
    VecX dv;
    try {
      dv = -Solve(residual);
    } catch (const SolverError& error) {
      out.reason = fmt::format("the Newton correction cannot be computed ({})", error.what());
      return out;
    }
    ++out.iterations;
    LineSearchResult search;
    if (options_.mass_shift) {
      const double tried = shift;
      std::string failure;
      std::optional<LineSearchResult> shifted = ShiftedStep(out.q, residual, dv, shift, least_norm, failure);
      out.iterations += extra_iterations_;
      extra_iterations_ = 0;
      if (!shifted) {
        if (!failure.empty()) {
          out.reason = std::move(failure);
          return out;
        }
        if (options_.log) {
          options_.log(fmt::format("  Newton {:3d}: |R| {:.4e} N, step {:.3e} not acceptable with shift {:.3e}; "
                                   "shift {:.3e}", out.iterations, norm, problem_.StepLength(out.q, dv), tried, shift));
        }
        out.history.pop_back();
        continue;
      }
      search = std::move(*shifted);
    } else if (options_.max_increment > 0.0) {
      search = TrustRegionStep(out.q, residual, dv, radius);
    } else {
      search = BacktrackingLineSearch(problem_, options_.time, out.q, residual, dv, options_.line_search);
    }
    if (options_.line_search.enabled && !search.decreased) {
      if (reuse && !fresh) {  // an old matrix: refresh it at q and try again
        if (std::string failure = Factorize(out.q); !failure.empty()) {
          out.reason = std::move(failure);
          return out;
        }
        fresh = true;
        out.history.pop_back();
        continue;
      }
      out.reason = fmt::format(
          "no decrease of the merit along the Newton direction (step length down to {:.3g})",
          search.step);
      return out;
    }
    LogStep(out, norm, search, dv, shift, radius);
    fresh = false;
    out.q = std::move(search.q);
    residual = std::move(search.residual);
    // A kept factorization that no longer contracts well enough is renewed.
    if (options_.reuse_contraction > 0.0 && !(residual.norm() <= options_.reuse_contraction * norm)) stale_ = true;
    if (options_.mass_shift && residual.allFinite() && residual.norm() <= end_game_below) {
      end_game_below = 0.5 * residual.norm();
      StepOutcome finished = EndGame(out.q, residual);
      if (finished.converged) {
        finished.iterations += out.iterations;
        return finished;
      }
      out.iterations += finished.iterations;  // spent: the shifted steps go on from out.q
    }
    // (A step shortened by a mass shift says nothing about convergence.)
    if (options_.increment_tolerance > 0.0 && residual.allFinite() && shift == 0.0 &&
        search.step * dv.lpNorm<Eigen::Infinity>() <= options_.increment_tolerance) {
      out.residual_norm = residual.norm();
      out.history.push_back(out.residual_norm);
      out.converged = true;
      return out;
    }
  }
}

double DetermineForceScale(StaticProblem& problem, const VecX& q_start,
                           const NewtonOptions& options) {
  if (options.force_scale > 0.0) return options.force_scale;
  if (problem.ForceScale() > 0.0) return problem.ForceScale();
  const VecX zero = VecX::Zero(problem.num_velocities());
  problem.SetLoadFactor(1.0);
  const VecX residual = problem.Residual(options.time, q_start, zero, zero);
  if (!residual.allFinite()) {
    throw SolverError(
        "static Newton solver: the residual of the start state at full load is not finite "
        "(NaN or Inf)");
  }
  const double norm = residual.norm();
  return norm > 0.0 ? norm : 1.0;
}

void CheckArguments(const StaticProblem& problem, const VecX& q_start,
                    const NewtonOptions& options) {
  if (q_start.size() != problem.num_positions()) {
    throw LogicError(fmt::format("SolveStatic: q_start has size {}, the problem {}",
                                 q_start.size(), problem.num_positions()));
  }
  if (!q_start.allFinite()) throw LogicError("SolveStatic: q_start is not finite");
  const LoadSteppingOptions& stepping = options.load_stepping;
  if (!(options.residual_tolerance > 0.0) || options.max_iterations < 1 ||
      !(stepping.min_step > 0.0) || stepping.max_step < stepping.min_step ||
      !(stepping.initial_step > 0.0) || !(stepping.growth_factor >= 1.0)) {
    throw LogicError("SolveStatic: invalid options (tolerance, iterations or load steps)");
  }
}

// Where the failure happened, for the message.
struct FailurePlace {
  double load_factor_tried = 1.0;
  double load_factor_converged = 0.0;
  double step = 1.0;
  int rejected_steps = 0;
  bool after_converged_step = false;  // the budget ran out right after a step that converged
  bool budget_spent = false;          // the budget ran out in a step (not the step cut too small)
};

std::string FailureMessage(const StepOutcome& outcome, const FailurePlace& place,
                           const NewtonOptions& options, double scale, double tolerance, int total_iterations) {
  if (place.after_converged_step) {
    // Not a step that failed: the continuation was still converging its steps when it ran out.
    return fmt::format(
        "static Newton solver stopped at load factor {:.6g}, the last it converged (load step {:.3g}, {} "
        "cuts so far): {}; that step ended at a residual norm of {:.4g} N within its tolerance {:.4g} N "
        "(force scale {:.4g} N) after {} iterations, {} in all",
        place.load_factor_converged, place.step, place.rejected_steps, outcome.reason, outcome.residual_norm,
        tolerance, scale, outcome.iterations, total_iterations);
  }
  std::string where;
  if (options.load_stepping.enabled) {
    where = place.budget_spent
                ? fmt::format("at load factor {:.6g} (last converged {:.6g}; load step {:.3g}, {} cuts so far)",
                              place.load_factor_tried, place.load_factor_converged, place.step, place.rejected_steps)
                : fmt::format("at load factor {:.6g} (last converged {:.6g}; load step {:.3g} cut below the minimum "
                              "{:.3g} after {} cuts)",
                              place.load_factor_tried, place.load_factor_converged, place.step,
                              options.load_stepping.min_step, place.rejected_steps);
  } else {
    where = "at load factor 1 (load stepping off)";
  }
  return fmt::format(
      "static Newton solver failed {}: {}; residual norm {:.4g} N against the tolerance {:.4g} N "
      "(force scale {:.4g} N{}) after {} iterations in this step, {} in all",
      where, outcome.reason, outcome.residual_norm, tolerance, scale,
      outcome.largest.empty() ? std::string() : fmt::format("; {}", outcome.largest), outcome.iterations, total_iterations);
}

}  // namespace

NewtonResult SolveStatic(StaticProblem& problem, const VecX& q_start,
                         const NewtonOptions& options) {
  const profile::Scope scope("static: Newton");
  CheckArguments(problem, q_start, options);
  NewtonResult result;
  result.force_scale = DetermineForceScale(problem, q_start, options);
  // The tolerance, but never below the residual's round-off floor: a residual at the floor is as
  // small as the state can make it.
  const double asked = options.residual_tolerance * result.force_scale;
  problem.SetLoadFactor(1.0);
  result.tolerance = std::max(asked, ResidualRoundoffFloor(problem, q_start, options.time));
  if (options.log && result.tolerance > asked) {
    options.log(fmt::format("  Newton tolerance {:.4g} N: the residual's round-off floor (the relative tolerance "
                            "asks {:.4g} N)", result.tolerance, asked));
  }
  NewtonStepper stepper(problem, options, result.tolerance);
  const LoadSteppingOptions& stepping = options.load_stepping;

  VecX q = q_start;
  double load_factor = 0.0;  // of the last converged state
  double step = std::clamp(stepping.initial_step, stepping.min_step, stepping.max_step);
  FailurePlace place;
  StepOutcome last_failure;
  bool failed = false;
  while (!failed) {
    // With stepping off, a single solve at λ = 1.
    double trial = stepping.enabled ? load_factor + std::min(step, 1.0 - load_factor) : 1.0;
    if (1.0 - trial < 1e-12) trial = 1.0;
    const double trial_step = trial - load_factor;
    problem.SetLoadFactor(trial);
    StepOutcome outcome = stepper.Run(q);
    result.iterations += outcome.iterations;
    if (outcome.converged) {
      q = std::move(outcome.q);
      load_factor = trial;
      result.residual_norm = outcome.residual_norm;
      result.residual_history = std::move(outcome.history);
      ++result.load_steps;
      if (load_factor >= 1.0) break;
      if (options.max_total_iterations > 0 && result.iterations >= options.max_total_iterations) {
        last_failure = std::move(outcome);
        last_failure.converged = false;
        last_failure.reason = fmt::format("the budget of {} iterations in all is spent", options.max_total_iterations);
        place = {load_factor, load_factor, step, result.rejected_steps, true};
        failed = true;
        break;
      }
      if (outcome.iterations <= stepping.fast_iterations) {
        step = std::min(step * stepping.growth_factor, stepping.max_step);
      }
      continue;
    }
    ++result.rejected_steps;
    place = {trial, load_factor, trial_step, result.rejected_steps};
    step = 0.5 * trial_step;
    const bool over_budget = options.max_total_iterations > 0 && result.iterations >= options.max_total_iterations;
    place.budget_spent = over_budget;
    if (over_budget) {
      outcome.reason = fmt::format("{}; the budget of {} iterations in all is spent", outcome.reason,
                                   options.max_total_iterations);
    }
    if (!stepping.enabled || step < stepping.min_step || over_budget) {
      last_failure = std::move(outcome);
      failed = true;
    }
  }
  result.q = q;
  result.load_factor = load_factor;
  result.converged = !failed;
  if (failed) {
    const std::string message =
        FailureMessage(last_failure, place, options, result.force_scale, result.tolerance, result.iterations);
    if (options.throw_on_failure) throw SolverError(message);
    problem.SetLoadFactor(load_factor);
    const VecX zero = VecX::Zero(problem.num_velocities());
    result.residual_norm = problem.Residual(options.time, q, zero, zero).norm();
  }
  return result;
}

}  // namespace drillflex::solvers
