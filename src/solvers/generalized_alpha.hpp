// Implicit time integration of R(t, q, v, v̇) = 0 (solvers/problem.hpp) by the generalized-α method
// of Chung & Hulbert (J. Appl. Mech. 60, 1993) in the Lie-group form of Arnold & Brüls (Multibody
// Syst. Dyn. 18, 2007) and Brüls, Cardona & Arnold (Mech. Mach. Theory 48, 2012). Per step h, with
// v̇ the true acceleration and a an auxiliary ("pseudo") acceleration:
//   q_{n+1} = q_n ⊕ (h v_n + h² (½ − β) a_n + h² β a_{n+1})     (rotation-aware: Problem::Increment)
//   v_{n+1} = v_n + h (1 − γ) a_n + h γ a_{n+1}
//   (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) v̇_{n+1} + α_f v̇_n
//   R(t_{n+1}, q_{n+1}, v_{n+1}, v̇_{n+1}) = 0,
// with α_m = (2ρ∞ − 1)/(ρ∞ + 1), α_f = ρ∞/(ρ∞ + 1), γ = ½ + α_f − α_m, β = ¼ (γ + ½)² (Chung &
// Hulbert eq. 25 and 17): second order, unconditionally stable for linear problems, with the
// spectral radius ρ∞ ∈ [0, 1] at ωh → ∞ (ρ∞ = 1: no numerical damping, the trapezoidal rule).
//
// Newton on v̇_{n+1}: a correction Δv̇ changes a by β'' Δv̇, v by γ h β'' Δv̇ and the position
// increment by β h² β'' Δv̇ (β'' = (1 − α_f)/(1 − α_m)), so the iteration matrix is, divided by
// β h² β'', S = K + γ/(β h) D + (1 − α_m)/((1 − α_f) β h²) M (Problem::IterationMatrix; the tangent
// operator of the Lie-group increment is taken as the identity, as Brüls et al. do: it changes only
// the convergence rate, O(h)). S is factorized by a dense LU (small problems), block tridiagonal on
// the problem's coordinate blocks (a string's bodies), LAPACK's banded LU or SparseLinearSolver
// (solvers/iteration_matrix_lu.hpp), and is kept factorized across iterations and steps while
// Newton converges fast (modified Newton), a matrix of an earlier state used in that state's
// coordinates (Problem::TransportCoordinates: a spinning string's bodies turned back); it is
// refactorized at the current iterate when a correction is more than `reuse_contraction` (dense)
// or `reuse_contraction_factored` times the one before (slow, linear convergence), when Newton
// fails with a matrix of an earlier step, or when h has changed by more than `refactor_step_ratio`.
// Without reuse it is refactorized at every iterate (full Newton). Output times are met in equal
// steps (AdvanceTo).
//
// Convergence and error are measured in a weighted RMS norm of position increments:
// ‖x‖ = sqrt(mean((x_i / (atol + rtol · s_i))²)), s_i the largest |q_i − q_i(start)| so far
// (accumulated in the tangent space), capped at position_scale (so that a body spinning thousands
// of radians is still integrated to rtol · 1 rad, not rtol times its total turn). Newton stops when
// a correction times θ/(1 − θ) is below newton_tolerance in this norm, θ the contraction measured
// in this step (Hairer & Wanner, "Solving ODEs II", §IV.8); at the first iteration θ is the last
// step's, inflated, when ρ∞ < 1 and the matrix is the same (else the correction itself must be
// below the tolerance); a correction that stops shrinking below a tenth of the norm is round-off.
// The local error estimate is Zienkiewicz & Xie's (Earthquake Eng.
// Struct. Dyn. 20, 1991) for Newmark-type schemes, e = (β − 1/6) h² (a_{n+1} − a_n); adaptive steps
// accept e ≤ 1 and take h ← h · clamp(0.9 e^(−1/3), 0.2, 2). A step whose Newton iterations fail
// (too many iterations, divergence, a non-finite residual, a singular matrix) is rejected and
// retried at h/4; below min_step the integrator throws a SolverError naming the time and reason.
// After such a failure at h the adaptive steps are held below failure_ceiling · h, a ceiling that
// grows by ceiling_growth per accepted step: where Newton's reach, not the error, limits the step
// (regularized friction near its knee, contacts closing), regrowing at once by 2× per step fails
// again two steps later; measured on the bundled example's spin-up (bench/rotary_transient_bench),
// 121 of 404 attempts failed so, and the 2× step changes refactorized the matrix at nearly every
// step (refactor_step_ratio), while the gradual regrowth keeps it. When the attempt with an earlier
// step's matrix has failed stale_failure_limit steps in a row (the matrix changes too much from step
// to step: wall contacts opening and closing, at k = 1e8 N/m above the inertia term), the steps
// factorize at their predictor straight away and try the old matrix again every
// stale_probe_interval steps: the failed attempts cost two residuals and a restart each (on the
// bundled example's spin-up, 420 of 738 steps).
#pragma once

#include <functional>
#include <limits>
#include <string>

#include "core/types.hpp"
#include "solvers/iteration_matrix_lu.hpp"
#include "solvers/problem.hpp"

namespace drillflex::solvers {

// The scheme's coefficients for a spectral radius ρ∞ at infinite frequency (Chung & Hulbert 1993).
struct GeneralizedAlphaParameters {
  double alpha_m = 0.5;
  double alpha_f = 0.5;
  double gamma = 0.5;
  double beta = 0.25;
  // Throws LogicError unless 0 ≤ ρ∞ ≤ 1.
  static GeneralizedAlphaParameters FromSpectralRadius(double rho_infinity);
};

struct GeneralizedAlphaOptions {
  double rho_infinity = 0.8;        // spectral radius at ωh → ∞ (1: no numerical damping)
  double initial_step = 1e-4;       // s
  double min_step = 1e-12;          // s; a step cut below this throws
  double max_step = std::numeric_limits<double>::infinity();  // s
  bool adaptive = true;             // false: steps of initial_step (cut only when Newton fails)
  double relative_tolerance = 1e-4; // rtol of the error norm (header)
  double absolute_tolerance = 1e-8; // atol, units of q's tangent (m, rad, modal coordinates)
  double position_scale = 1.0;      // cap of s_i in the error norm, same units
  double newton_tolerance = 1e-3;   // fraction of the error norm at which Newton stops
  int max_newton_iterations = 12;   // per attempt (a stale matrix gets one more attempt, fresh)
  bool reuse_iteration_matrix = true;
  bool extrapolate_acceleration = true;  // predictor v̇_{n+1} from v̇_n and v̇_{n−1} (else v̇_n)
  // Up to this many velocity coordinates the iteration matrix is factorized dense (partial-pivot
  // LU): for a 72-coordinate cantilever a solve takes ~2 µs against ~12 µs sparse.
  int dense_limit = 200;
  // Above it: block tridiagonal on the problem's CoordinateBlocks if the matrix has that shape;
  // otherwise a matrix whose LAPACK band storage ((2 kl + ku + 1) n values) is at most this many
  // times its entries banded (solvers/band_lu.hpp), any other by SparseLinearSolver
  // (solvers/iteration_matrix_lu.hpp).
  bool block_tridiagonal = true;
  double band_storage_limit = 4.0;
  // An iteration contracting less than this refactorizes: for a dense matrix (up to dense_limit,
  // a factorization costing about a residual) and for the others (a string's assembly and block LU,
  // 6–10 residuals). Measured back to back: the V1 cantilever's 1 s 293–306 ms at 0.3, 330–357 ms at
  // 0.5; the bundled example's 10 s on two threads 14.0 s at 0.3, 13.1 s at 0.5, 13.6 s at 0.65.
  double reuse_contraction = 0.3;
  double reuse_contraction_factored = 0.5;
  double refactor_step_ratio = 0.25;  // |h/h_factorized − 1| above this refactorizes
  long max_steps = 100'000'000;     // accepted plus rejected steps per AdvanceTo
  double failure_ceiling = 0.5;     // after a Newton failure at h, adaptive steps stay below this · h
  double ceiling_growth = 1.02;     // ... a ceiling that grows by this factor per accepted step
  int stale_failure_limit = 2;      // failed attempts with an earlier step's matrix in a row, then ...
  long stale_probe_interval = 8;    // ... fresh matrices, the old one tried every this many steps
};

struct GeneralizedAlphaState {
  double time = 0.0;     // s
  VecX q;                // positions (num_positions)
  VecX v;                // velocities (num_velocities)
  VecX acceleration;     // v̇, the true acceleration
  VecX pseudo_acceleration;  // a, the scheme's auxiliary acceleration
  double last_step = 0.0;    // the step that led here, s (0 at a start, where a = v̇)
};

struct GeneralizedAlphaStatistics {
  long steps = 0;                // accepted
  long error_rejections = 0;     // steps rejected by the error estimate
  long newton_failures = 0;      // steps rejected because Newton failed
  long newton_iterations = 0;    // over all attempts
  long factorizations = 0;
  long residual_evaluations = 0;
  double smallest_step = std::numeric_limits<double>::infinity();  // accepted, s
  double largest_step = 0.0;     // accepted, s
};

class GeneralizedAlphaIntegrator {
 public:
  GeneralizedAlphaIntegrator(const Problem& problem, const GeneralizedAlphaOptions& options);

  // Starts at (t, q, v) with the consistent acceleration v̇ = −M(q)⁻¹ R(t, q, v, 0) and a = v̇.
  // Throws SolverError if M is singular or the residual is not finite.
  void Initialize(double time, const VecX& q, const VecX& v);
  // Starts from a full state (e.g. to continue a run); sizes are checked.
  void Initialize(const GeneralizedAlphaState& state);

  // Integrates until state().time == end_time exactly (the last step is shortened to land on it).
  // Throws SolverError (with the time and the reason) when a step cannot be completed.
  void AdvanceTo(double end_time);

  const GeneralizedAlphaState& state() const { return state_; }
  const GeneralizedAlphaStatistics& statistics() const { return statistics_; }
  const GeneralizedAlphaParameters& parameters() const { return parameters_; }
  // The step size the next step will try (s).
  double step_size() const { return step_; }
  // The local error estimate of the last accepted step in the error norm (≤ 1 when adaptive).
  double last_error() const { return last_error_; }
  // Called after every accepted step; none when empty.
  std::function<void(const GeneralizedAlphaState&)> on_step;

 private:
  enum class Outcome { kConverged, kFailed };
  struct Attempt {
    Outcome outcome = Outcome::kFailed;
    std::string reason;
  };
  Attempt TryStep(double h);
  Attempt Iterate(double h, bool fresh_matrix);
  void PrepareStep(double h);
  void UpdateStepState(double h);
  bool Factorize(double h, std::string& reason);
  double WeightedNorm(const VecX& increment) const;
  void UpdateWeights();  // weights_ from scale_
  double StepErrorEstimate(double h) const;
  void AcceptStep(double h);

  const Problem& problem_;
  GeneralizedAlphaOptions options_;
  GeneralizedAlphaParameters parameters_;
  GeneralizedAlphaState state_;
  GeneralizedAlphaStatistics statistics_;
  IterationMatrixLu lu_;
  bool has_factorization_ = false;
  double factorized_step_ = 0.0;
  VecX factorized_displacement_;  // Σ increments from the start to the state factorized at
  VecX moved_;                    // ... and from that state to the present iterate
  double step_ = 0.0;
  double step_ceiling_ = std::numeric_limits<double>::infinity();  // after Newton failures (header)
  int stale_failures_ = 0;  // steps in a row whose attempt with an earlier step's matrix failed
  double last_error_ = 0.0;
  bool initialized_ = false;
  // Workspace of the step being attempted (the trial state at t_{n+1}).
  VecX trial_q_, trial_v_, trial_acceleration_, trial_pseudo_, increment_, base_increment_;
  VecX step_pseudo_;  // a_n rescaled to the step being tried (PrepareStep)
  VecX previous_acceleration_;
  double contraction_ = 1.0;  // θ/(1 − θ) of the last converged Newton solve (Iterate)  // v̇_{n−1}, for the predictor (empty at a start)
  VecX accumulated_, scale_;
  VecX weights_;  // 1/(atol + rtol s_i) of the error norm  // Σ increments since the start, and its running largest |·|
};

}  // namespace drillflex::solvers
