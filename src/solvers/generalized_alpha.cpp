#include "solvers/generalized_alpha.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "solvers/serial_eigen.hpp"

namespace drillflex::solvers {

GeneralizedAlphaParameters GeneralizedAlphaParameters::FromSpectralRadius(double rho_infinity) {
  if (!(rho_infinity >= 0.0 && rho_infinity <= 1.0)) {
    throw LogicError(fmt::format("generalized-α: the spectral radius ρ∞ must lie in [0, 1], got {}", rho_infinity));
  }
  // Chung & Hulbert (1993), eq. 25 (α_m, α_f in the form of Arnold & Brüls 2007) and eq. 17.
  GeneralizedAlphaParameters p;
  p.alpha_m = (2.0 * rho_infinity - 1.0) / (rho_infinity + 1.0);
  p.alpha_f = rho_infinity / (rho_infinity + 1.0);
  p.gamma = 0.5 + p.alpha_f - p.alpha_m;
  p.beta = 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5);
  return p;
}

GeneralizedAlphaIntegrator::GeneralizedAlphaIntegrator(const Problem& problem, const GeneralizedAlphaOptions& options)
    : problem_(problem),
      options_(options),
      parameters_(GeneralizedAlphaParameters::FromSpectralRadius(options.rho_infinity)),
      lu_(IterationMatrixLuOptions{options.dense_limit, options.band_storage_limit}) {
  if (options_.block_tridiagonal) lu_.SetBlocks(problem_.CoordinateBlocks());
  if (!(options_.initial_step > 0.0) || !(options_.min_step > 0.0) || !(options_.max_step >= options_.min_step)) {
    throw LogicError("generalized-α: the step sizes must satisfy 0 < min_step ≤ max_step and initial_step > 0");
  }
  if (!(options_.relative_tolerance >= 0.0) || !(options_.absolute_tolerance > 0.0)) {
    throw LogicError("generalized-α: the absolute tolerance must be positive and the relative one non-negative");
  }
  step_ = std::clamp(options_.initial_step, options_.min_step, options_.max_step);
}

void GeneralizedAlphaIntegrator::Initialize(double time, const VecX& q, const VecX& v) {
  const Index n = problem_.num_velocities();
  if (q.size() != problem_.num_positions() || v.size() != n) {
    throw LogicError("generalized-α: the initial q or v has the wrong size");
  }
  const VecX zero = VecX::Zero(n);
  const VecX residual = problem_.Residual(time, q, v, zero);
  ++statistics_.residual_evaluations;
  if (!residual.allFinite()) {
    throw SolverError(fmt::format("transient: the residual at the start (t = {:.6g} s) is not finite", time));
  }
  // The consistent acceleration: R is linear in v̇ with ∂R/∂v̇ = M(q), so M v̇ = −R(t, q, v, 0).
  SparseLinearSolver mass_solver;
  try {
    mass_solver.Factorize(problem_.IterationMatrix(time, q, v, zero, 0.0, 0.0, 1.0));
  } catch (const SolverError& e) {
    throw SolverError(fmt::format("transient: no consistent initial acceleration at t = {:.6g} s ({})", time, e.what()));
  }
  GeneralizedAlphaState state;
  state.time = time;
  state.q = q;
  state.v = v;
  state.acceleration = -mass_solver.Solve(residual);
  state.pseudo_acceleration = state.acceleration;
  Initialize(state);
}

void GeneralizedAlphaIntegrator::Initialize(const GeneralizedAlphaState& state) {
  const Index n = problem_.num_velocities();
  if (state.q.size() != problem_.num_positions() || state.v.size() != n || state.acceleration.size() != n ||
      state.pseudo_acceleration.size() != n) {
    throw LogicError("generalized-α: the initial state has the wrong sizes");
  }
  state_ = state;
  accumulated_ = VecX::Zero(n);
  scale_ = VecX::Zero(n);
  UpdateWeights();
  has_factorization_ = false;
  contraction_ = 1.0;
  step_ceiling_ = std::numeric_limits<double>::infinity();
  stale_failures_ = 0;
  previous_acceleration_.resize(0);
  initialized_ = true;
}

double GeneralizedAlphaIntegrator::WeightedNorm(const VecX& increment) const {
  if (increment.size() == 0) return 0.0;
  return std::sqrt(increment.cwiseProduct(weights_).squaredNorm() / static_cast<double>(increment.size()));
}

void GeneralizedAlphaIntegrator::UpdateWeights() {
  weights_ = (options_.absolute_tolerance + options_.relative_tolerance * scale_.array()).inverse().matrix();
}

void GeneralizedAlphaIntegrator::PrepareStep(double h) {
  const GeneralizedAlphaParameters& p = parameters_;
  // a_n − v̇_n ≈ (α_m − α_f) h_n v̈ (a lags v̇ by a fraction of the step): after a change of step
  // size it is rescaled to the new step, or the scheme drops to first order (Arnold, Brüls &
  // Cardona, Numer. Math. 129, 2015, on variable steps).
  step_pseudo_ = state_.pseudo_acceleration;
  if (state_.last_step > 0.0 && h != state_.last_step) {
    step_pseudo_ = state_.acceleration + (h / state_.last_step) * (state_.pseudo_acceleration - state_.acceleration);
  }
  // Predictor: v̇ extrapolated linearly from the last two steps (the constant v̇_n at a start): its
  // error O(h² v⃛) leaves a first Newton correction that is often already below the tolerance.
  trial_acceleration_ = state_.acceleration;
  if (options_.extrapolate_acceleration && state_.last_step > 0.0 && previous_acceleration_.size() == state_.acceleration.size()) {
    trial_acceleration_ += (h / state_.last_step) * (state_.acceleration - previous_acceleration_);
  }
  base_increment_ = h * state_.v + h * h * (0.5 - p.beta) * step_pseudo_;
  UpdateStepState(h);
}

void GeneralizedAlphaIntegrator::UpdateStepState(double h) {
  const GeneralizedAlphaParameters& p = parameters_;
  // (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) v̇_{n+1} + α_f v̇_n (header).
  trial_pseudo_ = ((1.0 - p.alpha_f) * trial_acceleration_ + p.alpha_f * state_.acceleration -
                   p.alpha_m * step_pseudo_) /
                  (1.0 - p.alpha_m);
  increment_ = base_increment_ + h * h * p.beta * trial_pseudo_;
  trial_q_ = problem_.Increment(state_.q, increment_);
  trial_v_ = state_.v + h * (1.0 - p.gamma) * step_pseudo_ + h * p.gamma * trial_pseudo_;
}

bool GeneralizedAlphaIntegrator::Factorize(double h, std::string& reason) {
  const GeneralizedAlphaParameters& p = parameters_;
  // S = K + γ/(β h) D + (1 − α_m)/((1 − α_f) β h²) M: ∂R/∂v̇ divided by β h² (1 − α_f)/(1 − α_m).
  const double cD = p.gamma / (p.beta * h);
  const double cM = (1.0 - p.alpha_m) / ((1.0 - p.alpha_f) * p.beta * h * h);
  try {
    const SparseMat matrix = problem_.IterationMatrix(state_.time + h, trial_q_, trial_v_, trial_acceleration_, 1.0, cD, cM);
    lu_.Factorize(matrix);
  } catch (const SolverError& e) {
    reason = fmt::format("the iteration matrix could not be factorized ({})", e.what());
    has_factorization_ = false;
    return false;
  }
  ++statistics_.factorizations;
  has_factorization_ = true;
  factorized_step_ = h;
  factorized_displacement_ = accumulated_ + increment_;
  return true;
}

GeneralizedAlphaIntegrator::Attempt GeneralizedAlphaIntegrator::Iterate(double h, bool fresh_matrix) {
  const GeneralizedAlphaParameters& p = parameters_;
  const double stale_ratio = has_factorization_ ? std::abs(h / factorized_step_ - 1.0) : 0.0;
  // The iteration whose iterate the matrix was factorized at: 0 = this step's predictor, −1 = an
  // earlier step's state.
  int factorized_at = -1;
  Attempt attempt;
  if (fresh_matrix || !has_factorization_ || !options_.reuse_iteration_matrix ||
      stale_ratio > options_.refactor_step_ratio) {
    if (!Factorize(h, attempt.reason)) return attempt;
    factorized_at = 0;
  }
  // A position correction δ = −S⁻¹ R changes v̇ by δ / (β h² (1 − α_f)/(1 − α_m)) (header).
  const double acceleration_per_position = (1.0 - p.alpha_m) / ((1.0 - p.alpha_f) * p.beta * h * h);
  double previous_norm = 0.0;
  const double stagnation_limit = 0.1;  // in the error norm: a tenth of the local error tolerance
  // θ/(1 − θ) (Hairer & Wanner, §IV.8): this step's once measured; at the first iteration the last
  // step's, inflated as in RADAU5 (η^0.8), if it was measured with this matrix and numerical damping
  // is on. With ρ∞ = 1 the unresolved stiff modes keep their accelerations, which flip sign every
  // step, and with them the inertia terms of the iteration matrix: a carried θ is then wrong every
  // other step, and stopping on it left 2.6 % of the energy of a free vibration in 10 000 steps.
  // With fixed steps, "the same step" to round-off: an interval split in equal pieces (AdvanceTo)
  // gives steps that differ in the last bits, and an exact comparison lost the carried θ of the V1
  // cantilever (1.95 Newton iterations a step instead of 1.5). Adaptive steps keep the exact
  // comparison: carried between the equal pieces of their intervals, θ let Newton stop at its first
  // iteration more often and the error estimate then rejected and shortened more steps (bundled
  // example, 10 s: 3 431 steps and 12 476 iterations against 3 019 and 11 133).
  const bool same_step = options_.adaptive ? h == factorized_step_
                                           : std::abs(h - factorized_step_) <= 1e-9 * factorized_step_;
  const bool carry = options_.rho_infinity < 1.0 && factorized_at < 0 && same_step;
  double contraction_estimate = carry ? std::pow(std::max(contraction_, 1e-16), 0.8) : 1.0;
  for (int iteration = 1; iteration <= options_.max_newton_iterations; ++iteration) {
    const VecX residual = problem_.Residual(state_.time + h, trial_q_, trial_v_, trial_acceleration_);
    ++statistics_.residual_evaluations;
    ++statistics_.newton_iterations;
    if (!residual.allFinite()) {
      attempt.reason = "the residual is not finite";
      return attempt;
    }
    VecX correction;
    try {
      // With the matrix of an earlier state, in that state's coordinates (Problem::TransportCoordinates).
      correction = -residual;
      moved_ = accumulated_ + increment_ - factorized_displacement_;
      problem_.TransportCoordinates(moved_, correction, false);
      lu_.SolveInPlace(correction);
      problem_.TransportCoordinates(moved_, correction, true);
      if (!correction.allFinite()) throw SolverError("the correction is not finite");
    } catch (const SolverError& e) {
      attempt.reason = fmt::format("the linear solve failed ({})", e.what());
      return attempt;
    }
    trial_acceleration_ += acceleration_per_position * correction;
    UpdateStepState(h);
    const double norm = WeightedNorm(correction);
    if (!std::isfinite(norm)) {
      attempt.reason = "the Newton correction is not finite";
      return attempt;
    }
    if (iteration > 1) {
      const double theta = norm / previous_norm;
      if (theta >= 1.0) {
        // Stagnation below the error tolerance itself: the iterate is as accurate as the residual's
        // round-off allows (stiff springs, k ~ 1e12 N/m, amplify its noise); take it.
        if (norm <= stagnation_limit) {
          contraction_ = 1.0;
          attempt.outcome = Outcome::kConverged;
          return attempt;
        }
        attempt.reason = fmt::format("Newton diverges (correction grows {:.3g} times)", theta);
        return attempt;
      }
      contraction_estimate = theta / std::max(1.0 - theta, 1e-3);
    }
    // Converged when the estimated remaining error θ/(1 − θ)·‖δ‖ is small, or ‖δ‖ is at round-off.
    if (norm <= 1e-3 * options_.newton_tolerance || contraction_estimate * norm <= options_.newton_tolerance) {
      contraction_ = contraction_estimate;
      attempt.outcome = Outcome::kConverged;
      return attempt;
    }
    // Too slow with a matrix of an earlier iterate (the iteration matrix depends on the state, e.g.
    // through the accelerations of stiff modes): refactorize at this one. Without reuse, always.
    const double keep = lu_.method() == IterationMatrixLu::Method::kDense ? options_.reuse_contraction
                                                                           : options_.reuse_contraction_factored;
    const bool slow = iteration > 1 && norm > keep * previous_norm;
    if ((slow || !options_.reuse_iteration_matrix) && factorized_at < iteration) {
      if (!Factorize(h, attempt.reason)) return attempt;
      factorized_at = iteration;
      contraction_estimate = 1.0;  // not yet measured with the new matrix
    }
    previous_norm = norm;
  }
  attempt.reason = fmt::format("Newton did not converge in {} iterations (last correction {:.3g} of the tolerance)",
                               options_.max_newton_iterations, previous_norm / options_.newton_tolerance);
  return attempt;
}

GeneralizedAlphaIntegrator::Attempt GeneralizedAlphaIntegrator::TryStep(double h) {
  PrepareStep(h);
  const bool had_matrix = has_factorization_ && options_.reuse_iteration_matrix;
  // After stale_failure_limit steps in a row whose attempt with an earlier step's matrix failed, the
  // steps start with a fresh one, trying the old one again every stale_probe_interval steps (header).
  const bool skip_stale = had_matrix && stale_failures_ >= options_.stale_failure_limit &&
                          statistics_.steps % options_.stale_probe_interval != 0;
  Attempt attempt = Iterate(h, skip_stale);
  if (attempt.outcome == Outcome::kConverged) {
    if (had_matrix && !skip_stale) stale_failures_ = 0;
    return attempt;
  }
  if (!had_matrix || skip_stale) return attempt;
  // A stale matrix may be the reason: retry once from the predictor with a fresh one.
  ++stale_failures_;
  PrepareStep(h);
  return Iterate(h, true);
}

double GeneralizedAlphaIntegrator::StepErrorEstimate(double h) const {
  // Zienkiewicz & Xie (1991): the local position error of a Newmark-type step,
  // e = (β − 1/6) h² (a_{n+1} − a_n), from the third-order term of the Taylor expansion.
  const double coefficient = std::abs(parameters_.beta - 1.0 / 6.0) * h * h;
  return WeightedNorm(coefficient * (trial_pseudo_ - step_pseudo_));
}

void GeneralizedAlphaIntegrator::AcceptStep(double h) {
  state_.time += h;
  previous_acceleration_ = state_.acceleration;
  std::swap(state_.q, trial_q_);
  std::swap(state_.v, trial_v_);
  std::swap(state_.acceleration, trial_acceleration_);
  std::swap(state_.pseudo_acceleration, trial_pseudo_);
  accumulated_ += increment_;
  scale_ = scale_.cwiseMax(accumulated_.cwiseAbs().cwiseMin(options_.position_scale));
  UpdateWeights();
  state_.last_step = h;
  ++statistics_.steps;
  statistics_.smallest_step = std::min(statistics_.smallest_step, h);
  statistics_.largest_step = std::max(statistics_.largest_step, h);
}

void GeneralizedAlphaIntegrator::AdvanceTo(double end_time) {
  if (!initialized_) throw LogicError("generalized-α: AdvanceTo before Initialize");
  // The dense LU and solves on one thread (solvers/serial_eigen.hpp): the problem's own assembly
  // keeps its threads.
  const SerialEigenProducts serial;
  long attempts = 0;
  while (state_.time < end_time) {
    if (++attempts > options_.max_steps) {
      throw SolverError(fmt::format("transient: more than {} steps before t = {:.6g} s (stopped at t = {:.6g} s, "
                                    "step {:.3g} s)",
                                    options_.max_steps, end_time, state_.time, step_));
    }
    // The end time (an output time) is met in equal steps: the rest split in as many pieces as the
    // step size asks (a piece up to 10 % longer than it rather than one more piece). Not one full
    // step and then a sliver: the step after a sliver is h/h_n times longer, and both the rescaled
    // pseudo-acceleration and the extrapolated predictor grow with that ratio (PrepareStep); in the
    // bundled example's 10 s of rotation every Newton failure followed a sliver at an output time.
    // Equal steps also keep the iteration matrix's step, so it can be reused.
    const double remaining = end_time - state_.time;
    const double pieces = std::max(1.0, std::ceil(remaining / step_ - 0.1));
    const double h = remaining / pieces;
    const bool clipped = h < step_;
    const Attempt attempt = TryStep(h);
    if (attempt.outcome == Outcome::kFailed) {
      ++statistics_.newton_failures;
      has_factorization_ = false;
      step_ = 0.25 * h;
      // Remember where Newton gave up: the steps regrow only slowly back toward it (header).
      step_ceiling_ = options_.failure_ceiling * h;
      if (step_ < options_.min_step) {
        throw SolverError(fmt::format("transient: the step from t = {:.9g} s failed ({}); the step cannot be cut "
                                      "below the minimum {:.3g} s",
                                      state_.time, attempt.reason, options_.min_step));
      }
      continue;
    }
    const double error = StepErrorEstimate(h);
    // Error-per-step control of a third-order local error: h ← h · 0.9 e^(−1/3), within [0.2, 2].
    const double factor = error > 0.0 ? std::clamp(0.9 * std::cbrt(1.0 / error), 0.2, 2.0) : 2.0;
    if (options_.adaptive && error > 1.0) {
      ++statistics_.error_rejections;
      step_ = h * factor;
      if (step_ < options_.min_step) {
        throw SolverError(fmt::format("transient: the local error at t = {:.9g} s stays above the tolerance "
                                      "({:.3g} times) down to the minimum step {:.3g} s",
                                      state_.time, error, options_.min_step));
      }
      continue;
    }
    last_error_ = error;
    AcceptStep(h);
    if (options_.adaptive) {
      // A step shortened to meet the end time keeps step_ unless its error asks for less (h·factor
      // is the controller's proposal wherever h lies, but the factor's clamp would otherwise shrink
      // it).
      const double next = std::min({h * factor, options_.max_step, step_ceiling_});
      const double unclamped = error > 0.0 ? 0.9 * std::cbrt(1.0 / error) : std::numeric_limits<double>::infinity();
      const double proposal = std::min({h * unclamped, options_.max_step, step_ceiling_});
      step_ = clipped ? std::max(next, std::min(step_, proposal)) : next;
      step_ceiling_ *= options_.ceiling_growth;
    } else {
      step_ = std::min(2.0 * step_, std::min(options_.initial_step, options_.max_step));  // regrow after a cut
    }
    if (on_step) on_step(state_);
  }
}

}  // namespace drillflex::solvers
