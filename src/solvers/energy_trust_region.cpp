#include "solvers/energy_trust_region.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/profile.hpp"
#include "solvers/shifted_cholesky.hpp"

namespace drillflex::solvers {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Trust-region constants (Nocedal & Wright, Algorithm 4.1).
constexpr double kAcceptRatio = 1e-4;   // ρ above which a step is taken
constexpr double kShrinkRatio = 0.25;   // ρ below which Δ shrinks to a quarter of the step
constexpr double kGrowRatio = 0.75;     // ρ above which a step at the boundary doubles Δ
constexpr double kBoundaryFraction = 0.8;
// Moré–Sorensen: ‖p(σ)‖ within 10 % of Δ is on the boundary (Nocedal & Wright §4.3 use ~this).
constexpr double kBoundaryTolerance = 0.1;
constexpr int kSecularIterations = 10;
// The first shift tried when H is indefinite, × max H_ii / max M_ii (the bracket then grows ×10).
constexpr double kFirstShift = 1e-12;
constexpr int kBisections = 4;          // tightening the bracket of the positive-definite threshold
constexpr int kInverseIterations = 8;   // for the direction of most negative curvature
// A lowest eigenvalue of the pencil above −this × max H_ii / max M_ii is round-off, not instability.
constexpr double kNeutralCurvature = 1e-12;
constexpr double kSmallestRadius = 1e-12;  // m: a trust radius below this ends the solve
constexpr int kActiveSetRounds = 6;        // of ContactStep's active-set prediction
// σ_c of the second-order correction: at most this × the step's σ (and at most the geometric mean of
// that σ and the stiffness scale).
constexpr double kCorrectionShift = 1e3;

// a·p: a penalty term's gradient along p.
double Along(const PenaltyTerm& term, const VecX& p) {
  double sum = 0.0;
  for (Index j = 0; j < std::ssize(term.indices); ++j) sum += term.gradient[j] * p[term.indices[j]];
  return sum;
}

// The piecewise model of ContactStep along a step, m(t p) for t in [0, 1]:
//   m(tp) = t smoothᵀp + ½ t² pᵀ(K − Σ_touching k a aᵀ)p + Σ ½ k ⟨δ + t a·p⟩² − Σ_touching ½ k δ²,
// quadratic between the t where a contact opens or closes (Nocedal & Wright §16.7, the piecewise
// search of a projected method); `smooth_along` = smoothᵀp, `curvature` = pᵀKp, `constant` =
// −Σ_touching ½ k δ². Returns its least value on (0, 1] and where (`best_t`).
//
// Swept once along t: between two breakpoints the touching contacts are fixed and the model is
// the quadratic a0 + a1 t + ½ a2 t², whose sums change by one contact at each breakpoint (a
// contact's ½ k (δ + t a·p)² = ½ k δ² + k δ (a·p) t + ½ k (a·p)² t²): O(contacts + breakpoints ×
// log), where evaluating the model afresh at every candidate cost contacts × breakpoints (a fifth
// of a 740-body string's solve).
double PiecewiseModelMinimum(const std::vector<PenaltyTerm>& terms, const std::vector<char>& touching, double constant,
                             double smooth_along, double curvature, const VecX& p, double& best_t) {
  const std::size_t count = terms.size();
  struct Crossing {
    double t;
    std::size_t contact;
  };
  std::vector<Crossing> crossings;
  std::vector<double> moved(count);
  std::vector<char> on(count, 0);
  double a0 = constant, a1 = smooth_along, a2 = curvature;
  auto toggle = [&](std::size_t c, double sign) {
    const double stiffness = terms[c].stiffness, value = terms[c].value, m = moved[c];
    a0 += sign * 0.5 * stiffness * value * value;
    a1 += sign * stiffness * value * m;
    a2 += sign * stiffness * m * m;
  };
  for (std::size_t c = 0; c < count; ++c) {
    moved[c] = Along(terms[c], p);
    if (touching[c]) a2 -= terms[c].stiffness * moved[c] * moved[c];
    // Touching just beyond t = 0.
    on[c] = terms[c].value > 0.0 || (terms[c].value == 0.0 && moved[c] > 0.0);
    if (on[c]) toggle(c, 1.0);
    if (moved[c] != 0.0) {
      const double t = -terms[c].value / moved[c];
      if (t > 0.0 && t < 1.0) crossings.push_back({t, c});
    }
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
  auto value_at = [&](double t) { return a0 + t * (a1 + 0.5 * t * a2); };
  best_t = 1.0;
  double best = kInfinity;
  auto consider = [&](double t) {
    if (t <= 0.0) return;
    const double value = value_at(t);
    if (value < best) {
      best = value;
      best_t = t;
    }
  };
  double lo = 0.0;
  for (std::size_t i = 0; i <= crossings.size(); ++i) {
    const double hi = i < crossings.size() ? crossings[i].t : 1.0;
    if (hi > lo) {
      consider(lo);
      consider(hi);
      if (a2 > 0.0) consider(std::clamp(-a1 / a2, lo, hi));
    }
    if (i < crossings.size()) {
      const std::size_t c = crossings[i].contact;
      toggle(c, on[c] ? -1.0 : 1.0);
      on[c] = !on[c];
      lo = hi;
    }
  }
  return best;
}

struct Step {
  VecX p;
  double shift = 0.0;         // σ of the factorization p was solved with
  bool interior = false;      // the full Newton step (σ = 0) inside the region
  bool negative_curvature = false;
  double predicted = 0.0;     // m(0) − m(p) > 0, J
  std::string failure;        // no step could be formed
};

class Minimizer {
 public:
  Minimizer(StaticProblem& problem, const EnergyTrustRegionOptions& options)
      : problem_(problem), options_(options), zero_(VecX::Zero(problem.num_velocities())) {}

  EnergyTrustRegionResult Run(const VecX& q_start);

 private:
  VecX Residual(const VecX& q) const { return problem_.Residual(options_.time, q, zero_, zero_); }
  double MassNorm(const ShiftedCholesky& cholesky, const VecX& p) const {
    return std::sqrt(std::max(p.dot(cholesky.MetricTimes(p)), 0.0));
  }
  // The subproblem min m(p), ‖p‖_M ≤ radius (unscaled mass norm), by Moré–Sorensen. `shift_hint` > 0:
  // a shift near the answer (the previous active-set round's): tried first, and where H + σM is
  // positive definite there and p(σ) is not inside the region the secular iteration goes on from it.
  Step Subproblem(ShiftedCholesky& cholesky, const VecX& g, double radius, EnergyTrustRegionResult& result,
                  double shift_hint = 0.0);
  // The second-order correction at the trial point q (changed in place): a Newton step on the stiff
  // directions, −(H(q) + σ_c M)⁻¹ R(q) with σ_c = min(√(σ k̄), 10³ σ) (σ the step's shift, k̄ the
  // stiffness scale max H_ii / max M_ii), so that a spring stretched by the step's second-order error
  // (k/m ≫ σ_c: couplings, and the wall where a contact slid around the curved hole and went in by
  // t²/2ρ) is closed again while the soft motions stay as the step left them (k/m ≪ σ_c). The
  // tangent at the trial point, not the old one: a spring the step turned must close along its new
  // direction.
  // False when no correction could be formed.
  bool SecondOrderCorrection(const VecX& residual, double shift, VecX& q, EnergyTrustRegionResult& result);
  // The step over a model that knows the wall contacts (StaticProblem::PenaltyTerms): the smooth
  // part of Π (the contacts touching at q taken out of g and H) plus every contact's ½ k ⟨δ + a·p⟩²,
  // piecewise quadratic. Minimized within the region by active-set rounds (a primal–dual active set,
  // Hintermüller, Ito & Kunisch 2002): with the set A the model is quadratic (H + Σ_A k a aᵀ), its
  // step predicts which contacts touch, and that is the next A, until the set repeats. Without
  // terms, Subproblem on `plain` (H at q).
  Step ContactStep(const SparseMat& k, ShiftedCholesky& plain, const VecX& g, double radius,
                   const std::vector<PenaltyTerm>& terms, EnergyTrustRegionResult& result);
  // The tangent H at q assembled into assembled_, the metric M (the mass matrix at the first call, its
  // trace / 3 into mass_scale), the shift's scale max H_ii / max M_ii, and tangent_ holding H and M.
  void PrepareTangent(const VecX& q, double& mass_scale);
  // The trial point of a step from q, with its second-order correction where that releases more.
  struct Trial {
    VecX q, residual;
    double released = 0.0;  // Π(q) − Π(trial), J (−∞ where the trial's residual is not finite)
    double ratio = 0.0;     // released / predicted
    double norm = 0.0;      // |R| at the trial (∞ where not finite)
    bool corrected = false;
  };
  Trial TryStep(const VecX& q, const Step& step, EnergyTrustRegionResult& result);
  // Whether the trial is taken; `judged` names the test ("energy", "|R|" or "noise").
  static bool Acceptable(const Step& step, const Trial& trial, double norm, double energy_noise, const char*& judged);
  // The lowest eigenpair of (H, M) by inverse iteration on the factorization held (shift σ > −λ₁).
  std::pair<double, VecX> LowestMode(ShiftedCholesky& cholesky) const;
  // p + τz on the boundary ‖p + τz‖_M = radius, τ of the sign that lowers the model more.
  VecX ToBoundary(const ShiftedCholesky& cholesky, const VecX& g, const VecX& p, const VecX& z, double radius) const;
  double Predicted(const ShiftedCholesky& cholesky, const VecX& g, const VecX& p) const {
    return -(g.dot(p) + 0.5 * p.dot(cholesky.StiffnessTimes(p)));
  }
  void Log(const std::string& line) const {
    if (options_.log) options_.log(line);
  }

  StaticProblem& problem_;
  const EnergyTrustRegionOptions& options_;
  const VecX zero_;
  double shift_scale_ = 0.0;  // max H_ii / max M_ii
  double last_shift_ = 0.0;   // σ of the previous indefinite subproblem, a start for the next
  int rounds_ = 0;            // active-set rounds of the last ContactStep (for the log)
  double current_lowest_ = std::numeric_limits<double>::quiet_NaN();  // λ₁ of the last subproblem's H (NaN: positive definite)
  SparseMat metric_;          // M at the start
  SparseMat assembled_;       // the last tangent assembled (its storage reused from call to call)
  // H + σM at the iterate, kept across iterations (and H + σ_c M at a trial point for the correction)
  std::unique_ptr<ShiftedCholesky> tangent_;
};

std::pair<double, VecX> Minimizer::LowestMode(ShiftedCholesky& cholesky) const {
  const Eigen::Index n = problem_.num_velocities();
  // A fixed start with every coordinate present (xorshift32, Marsaglia 2003).
  VecX z(n);
  std::uint32_t state = 2463534242u;
  for (Eigen::Index j = 0; j < n; ++j) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    z[j] = static_cast<double>(state) / 4294967296.0 - 0.5;
  }
  for (int k = 0; k < kInverseIterations; ++k) {
    z = cholesky.Solve(cholesky.MetricTimes(z));
    const double norm = MassNorm(cholesky, z);
    if (!(norm > 0.0) || !std::isfinite(norm)) break;
    z /= norm;
  }
  const double mass = z.dot(cholesky.MetricTimes(z));
  const double curvature = mass > 0.0 ? z.dot(cholesky.StiffnessTimes(z)) / mass : 0.0;
  return {curvature, z};
}

bool Minimizer::SecondOrderCorrection(const VecX& residual, double shift, VecX& q,
                                      EnergyTrustRegionResult& result) {
  const profile::Scope scope("solver: second-order correction");
  // The iterate's factorization is no longer needed once the step is formed: its object (and its
  // analysis of the pattern) takes the trial point's tangent.
  problem_.IterationMatrixInto(assembled_, options_.time, q, zero_, zero_, 1.0, 0.0, 0.0);
  tangent_->SetStiffness(assembled_);
  ShiftedCholesky& cholesky = *tangent_;
  const int factorized_before = cholesky.factorizations();
  const double step_shift = std::max(shift, kFirstShift * shift_scale_);
  double sigma = std::min(std::sqrt(step_shift * shift_scale_), kCorrectionShift * step_shift);
  bool positive = false;
  // Where the tangent at the trial point is indefinite (a buckling string), σ_c grows by decades until
  // H + σ_c M is positive definite: the correction must still close the stiff springs.
  for (int attempt = 0; attempt < 16 && !(positive = cholesky.Factorize(sigma)); ++attempt) sigma *= 10.0;
  result.factorizations += cholesky.factorizations() - factorized_before;
  if (!positive) return false;
  q = problem_.Increment(q, -cholesky.Solve(residual));
  return true;
}

VecX Minimizer::ToBoundary(const ShiftedCholesky& cholesky, const VecX& g, const VecX& p, const VecX& z,
                           double radius) const {
  const VecX mz = cholesky.MetricTimes(z);
  const double a = z.dot(mz), b = 2.0 * p.dot(mz), c = p.dot(cholesky.MetricTimes(p)) - radius * radius;
  if (!(a > 0.0)) return p;
  const double root = std::sqrt(std::max(b * b - 4.0 * a * c, 0.0));
  const VecX plus = p + ((-b + root) / (2.0 * a)) * z;
  const VecX minus = p + ((-b - root) / (2.0 * a)) * z;
  return Predicted(cholesky, g, plus) >= Predicted(cholesky, g, minus) ? plus : minus;
}

Step Minimizer::Subproblem(ShiftedCholesky& cholesky, const VecX& g, double radius,
                           EnergyTrustRegionResult& result, double shift_hint) {
  Step step;
  current_lowest_ = std::numeric_limits<double>::quiet_NaN();
  double lower = 0.0;        // σ at or below which H + σM is not (known) positive definite / p too long
  double upper = kInfinity;  // σ above which p is too short
  double threshold = 0.0;    // −λ₁ when H is indefinite: σ must exceed it
  bool indefinite = false;
  VecX z;
  double sigma = 0.0;
  // A boundary step's shift changes little from one active-set round to the next: from the previous
  // round's, one factorization often ends the search (else the secular iteration starts there, σ only
  // growing). Where p(σ_hint) falls inside the region the answer is a smaller shift: the full search.
  bool from_hint = false;
  if (shift_hint > 0.0 && cholesky.Factorize(shift_hint)) {
    step.p = -cholesky.Solve(g);
    const double norm = MassNorm(cholesky, step.p);
    if (norm >= radius * (1.0 - kBoundaryTolerance)) {
      sigma = shift_hint;
      lower = norm > radius ? shift_hint : lower;
      from_hint = true;
    }
  }
  if (from_hint) {
    // the secular iteration below, from σ_hint
  } else if (cholesky.Factorize(0.0)) {
    step.p = -cholesky.Solve(g);
    if (MassNorm(cholesky, step.p) <= radius) {
      step.interior = true;
      step.predicted = Predicted(cholesky, g, step.p);
      return step;
    }
  } else {
    // Bracket the threshold of positive definiteness from below by decades, then tighten it.
    indefinite = true;
    double failed = 0.0;
    sigma = std::max(last_shift_, kFirstShift * shift_scale_);
    while (!cholesky.Factorize(sigma)) {
      failed = sigma;
      sigma *= 10.0;
      if (!std::isfinite(sigma) || sigma > 1e30 * std::max(shift_scale_, 1.0)) {
        step.failure = "H + σM is not positive definite for any shift (a non-finite or unbounded tangent)";
        return step;
      }
    }
    double good = sigma;
    for (int k = 0; k < kBisections && failed > 0.0; ++k) {
      const double middle = std::sqrt(failed * good);
      if (cholesky.Factorize(middle)) {
        good = middle;
      } else {
        failed = middle;
      }
    }
    if (!cholesky.has_factorization() || cholesky.shift() != good) cholesky.Factorize(good);
    sigma = good;
    double lowest = 0.0;
    std::tie(lowest, z) = LowestMode(cholesky);
    current_lowest_ = lowest;
    result.lowest_curvature = std::isnan(result.lowest_curvature) ? lowest : std::min(result.lowest_curvature, lowest);
    threshold = std::max({-lowest, failed, 0.0});
    lower = threshold;
    step.p = -cholesky.Solve(g);
    // The hard case: even at the threshold the step stays inside; go along z to the boundary.
    if (MassNorm(cholesky, step.p) <= radius && lowest < 0.0) {
      step.p = ToBoundary(cholesky, g, step.p, z, radius);
      step.shift = sigma;
      step.negative_curvature = true;
      step.predicted = Predicted(cholesky, g, step.p);
      last_shift_ = sigma;
      return step;
    }
  }
  // Secular iterations on φ(σ) = 1/Δ − 1/‖p(σ)‖ (Nocedal & Wright, Algorithm 4.3, in the M-norm:
  // d‖p‖²/dσ = −2 pᵀM (H + σM)⁻¹ M p), safeguarded by the bracket [lower, upper].
  for (int k = 0; k < kSecularIterations; ++k) {
    const double norm = MassNorm(cholesky, step.p);
    if (std::abs(norm - radius) <= kBoundaryTolerance * radius) break;
    if (norm > radius) {
      lower = std::max(lower, sigma);
    } else {
      upper = std::min(upper, sigma);
    }
    const VecX w = cholesky.Solve(cholesky.MetricTimes(step.p));
    const double slope = step.p.dot(cholesky.MetricTimes(w));
    double next = slope > 0.0 ? sigma + (norm * norm / slope) * (norm - radius) / radius : kInfinity;
    if (!(next > lower && next < upper)) {
      next = std::isfinite(upper) ? (lower > 0.0 ? std::sqrt(lower * upper) : 0.5 * upper)
                                  : 10.0 * std::max({lower, sigma, kFirstShift * shift_scale_});
    }
    while (!cholesky.Factorize(next)) {
      lower = next;
      next = std::isfinite(upper) ? 0.5 * (lower + upper) : 10.0 * next;
    }
    sigma = next;
    step.p = -cholesky.Solve(g);
    if (indefinite && MassNorm(cholesky, step.p) < radius && sigma <= threshold * (1.0 + 1e-3)) {
      step.p = ToBoundary(cholesky, g, step.p, z, radius);
      step.negative_curvature = true;
      break;
    }
  }
  // Still outside after the iterations: cut back to the boundary along p (a descent direction, since
  // H + σM is positive definite). Still inside with H indefinite: σ is at the threshold, whatever the
  // inverse iteration estimated it to be (near-double eigenvalues converge slowly): the hard case.
  const double norm = MassNorm(cholesky, step.p);
  if (norm > radius * (1.0 + kBoundaryTolerance)) {
    step.p *= radius / norm;
  } else if (indefinite && !step.negative_curvature && norm < radius * (1.0 - kBoundaryTolerance)) {
    step.p = ToBoundary(cholesky, g, step.p, z, radius);
    step.negative_curvature = true;
  }
  step.shift = sigma;
  if (indefinite) last_shift_ = sigma;
  step.predicted = Predicted(cholesky, g, step.p);
  return step;
}

Step Minimizer::ContactStep(const SparseMat& k, ShiftedCholesky& plain, const VecX& g,
                            double radius, const std::vector<PenaltyTerm>& terms, EnergyTrustRegionResult& result) {
  const profile::Scope scope("solver: trust-region subproblem");
  if (terms.empty()) return Subproblem(plain, g, radius, result);
  const std::size_t count = terms.size();
  auto add = [](const PenaltyTerm& term, double scale, VecX& v) {
    for (Index j = 0; j < std::ssize(term.indices); ++j) v[term.indices[j]] += scale * term.gradient[j];
  };
  std::vector<char> touching(count), active(count);
  VecX smooth = g;  // g without the touching contacts' k δ a
  double constant = 0.0;  // −Σ_touching ½ k δ²: the model is 0 at p = 0
  for (std::size_t c = 0; c < count; ++c) {
    touching[c] = terms[c].value > 0.0;
    if (!touching[c]) continue;
    add(terms[c], -terms[c].stiffness * terms[c].value, smooth);
    constant -= 0.5 * terms[c].stiffness * terms[c].value * terms[c].value;
  }
  auto search = [&](const VecX& p, double& best_t) {
    return PiecewiseModelMinimum(terms, touching, constant, smooth.dot(p), p.dot(plain.TangentTimes(k, p)), p, best_t);
  };
  // Active-set rounds; each round's step is scored by the piecewise model (at its best length along
  // it) and the best is kept, so that a set that cycles (a few contacts in and out) costs rounds, not
  // the step.
  active = touching;
  Step best;
  double best_model = kInfinity, best_t = 1.0;
  double shift_hint = 0.0;  // the previous round's shift
  for (int round = 0; round < kActiveSetRounds; ++round) {
    rounds_ = round + 1;
    Step step;
    if (active == touching) {
      plain.RestoreStiffness();
      step = Subproblem(plain, g, radius, result, shift_hint);
    } else {
      // H + Σ_A k a aᵀ on the same pattern: the contacts whose state differs from q's switched.
      plain.RestoreStiffness();
      VecX gradient = smooth;
      for (std::size_t c = 0; c < count; ++c) {
        const PenaltyTerm& term = terms[c];
        if (active[c]) add(term, term.stiffness * term.value, gradient);
        if (active[c] != touching[c]) plain.AddOuterProduct(term.indices, term.gradient, (active[c] ? 1.0 : -1.0) * term.stiffness);
      }
      step = Subproblem(plain, gradient, radius, result, shift_hint);
    }
    if (!step.failure.empty()) return round == 0 ? step : best;
    shift_hint = step.interior || step.negative_curvature ? 0.0 : step.shift;
    std::vector<char> predicted(count);
    for (std::size_t c = 0; c < count; ++c) predicted[c] = terms[c].value + Along(terms[c], step.p) > 0.0;
    double t = 1.0;
    const double model = search(step.p, t);
    if (model < best_model) {
      best_model = model;
      best_t = t;
      best = std::move(step);
    }
    if (predicted == active) break;  // settled: this set's step is its own prediction
    active = std::move(predicted);
  }
  if (best_t < 1.0) {
    best.p *= best_t;
    best.interior = false;
  }
  best.predicted = -best_model;
  return best;
}

void Minimizer::PrepareTangent(const VecX& q, double& mass_scale) {
  problem_.IterationMatrixInto(assembled_, options_.time, q, zero_, zero_, 1.0, 0.0, 0.0);
  const SparseMat& k = assembled_;
  // The metric: the mass matrix at the start (only the norm of a step and the shift's scale; its
  // slight change with the state does not matter, and it is not assembled again).
  if (metric_.size() == 0) {
    metric_ = problem_.IterationMatrix(options_.time, q, zero_, zero_, 0.0, 0.0, 1.0);
    mass_scale = metric_.diagonal().sum() / 3.0;
  }
  const SparseMat& m = metric_;
  const double largest_mass = m.diagonal().cwiseAbs().maxCoeff();
  shift_scale_ = largest_mass > 0.0 ? k.diagonal().cwiseAbs().maxCoeff() / largest_mass : 0.0;
  if (!(mass_scale > 0.0) || !(shift_scale_ > 0.0) || !std::isfinite(shift_scale_)) {
    throw LogicError("MinimizeEnergy: the problem has no positive mass matrix (IterationMatrix with cM = 1), or "
                     "its tangent is zero or not finite");
  }
  if (!tangent_) {
    tangent_ = std::make_unique<ShiftedCholesky>(k, m, problem_.CoordinateBlocks());
  } else {
    tangent_->SetStiffness(k);
  }
}

Minimizer::Trial Minimizer::TryStep(const VecX& q, const Step& step, EnergyTrustRegionResult& result) {
  Trial trial;
  trial.q = problem_.Increment(q, step.p);
  trial.residual = Residual(trial.q);
  double released = trial.residual.allFinite() ? -problem_.EnergyChange(q, trial.q) : -kInfinity;
  if (!std::isfinite(released)) released = -kInfinity;
  trial.released = released;
  trial.ratio = step.predicted > 0.0 ? released / step.predicted : -kInfinity;
  // Every step with its second-order correction, the better of the two taken: a step the energy
  // accepts still leaves its stiff directions strained by its second-order error (|R| of 1e5–1e6 N
  // from a few joules released), which the next iteration would otherwise spend on.
  if (trial.residual.allFinite()) {
    VecX corrected_q = trial.q;
    if (SecondOrderCorrection(trial.residual, step.shift, corrected_q, result)) {
      VecX corrected_residual = Residual(corrected_q);
      const double corrected_released =
          corrected_residual.allFinite() ? -problem_.EnergyChange(q, corrected_q) : -kInfinity;
      if (std::isfinite(corrected_released) && corrected_released > trial.released) {
        trial.q = std::move(corrected_q);
        trial.residual = std::move(corrected_residual);
        trial.released = corrected_released;
        trial.ratio = trial.released / step.predicted;
        trial.corrected = true;
      }
    }
  }
  trial.norm = trial.residual.allFinite() ? trial.residual.norm() : kInfinity;
  return trial;
}

bool Minimizer::Acceptable(const Step& step, const Trial& trial, double norm, double energy_noise,
                           const char*& judged) {
  if (step.interior && step.predicted < energy_noise) {
    // Near the energy's resolution: a full Newton step is taken when it lowers |R|, or when the
    // energy it released still agrees with the model (a ratio that noise would not give).
    judged = "|R|";
    return trial.norm < norm || (trial.ratio > kShrinkRatio && trial.ratio < 1.0 / kShrinkRatio);
  }
  if (step.predicted < energy_noise) {
    judged = "noise";
    return trial.released > -energy_noise && trial.norm < kInfinity;
  }
  judged = "energy";
  return trial.ratio > kAcceptRatio;
}

EnergyTrustRegionResult Minimizer::Run(const VecX& q_start) {
  EnergyTrustRegionResult result;
  result.q = q_start;
  VecX residual = Residual(result.q);
  if (!residual.allFinite()) {
    result.failure = "the residual of the start state is not finite (NaN or Inf)";
    return result;
  }
  result.force_scale = options_.force_scale > 0.0 ? options_.force_scale : problem_.ForceScale();
  if (!(result.force_scale > 0.0)) result.force_scale = residual.norm() > 0.0 ? residual.norm() : 1.0;
  result.tolerance = std::max(options_.residual_tolerance * result.force_scale,
                              ResidualRoundoffFloor(problem_, q_start, options_.time));
  const double energy_noise = options_.energy_resolution * result.force_scale;
  double mass_scale = 0.0;  // m̄ = trace(M)/3
  double radius = options_.initial_radius;
  bool full_newton_small = false;  // the last accepted step was a full Newton step within the increment tolerance
  bool leaving_saddle = false;     // at a stationary point that is not a minimum, stepping off it
  while (true) {
    const double norm = residual.norm();
    result.residual_norm = norm;
    PrepareTangent(result.q, mass_scale);
    const SparseMat& k = assembled_;
    const SparseMat& m = metric_;
    ShiftedCholesky& cholesky = *tangent_;
    const int counted = cholesky.factorizations();  // before this iteration
    rounds_ = 0;
    const bool small = norm <= result.tolerance || full_newton_small;
    if (small) {
      const bool positive = cholesky.Factorize(0.0);
      if (positive || !options_.require_stable) {
        result.converged = true;
        result.stable = positive;
        result.factorizations += cholesky.factorizations() - counted;
        return result;
      }
      // Stationary but not a minimum: unless the lowest curvature is round-off, step off along it,
      // from at least the first radius (once: a refused step shrinks it as any other).
      if (!leaving_saddle) radius = std::max(radius, options_.initial_radius);
      leaving_saddle = true;
    } else {
      leaving_saddle = false;
    }
    if (result.iterations >= options_.max_iterations) {
      result.factorizations += cholesky.factorizations() - counted;
      result.failure = fmt::format("no stable equilibrium within {} trust-region iterations", options_.max_iterations);
      return result;
    }
    ++result.iterations;
    const double scaled_radius = radius * std::sqrt(mass_scale);
    Step step = ContactStep(k, cholesky, residual, scaled_radius, problem_.PenaltyTerms(result.q), result);
    if (!step.failure.empty()) {
      result.factorizations += cholesky.factorizations() - counted;
      result.failure = step.failure;
      return result;
    }
    if (small && !std::isnan(current_lowest_) && current_lowest_ > -kNeutralCurvature * shift_scale_) {
      // The factorization failed on round-off of a positive semidefinite H: a neutral equilibrium.
      result.factorizations += cholesky.factorizations() - counted;
      result.converged = true;
      result.stable = true;
      return result;
    }
    const double step_length = std::sqrt(std::max(step.p.dot(m * step.p), 0.0) / mass_scale);
    const int step_factorizations = cholesky.factorizations() - counted;
    result.factorizations += cholesky.factorizations() - counted;
    Trial tried = TryStep(result.q, step, result);
    VecX& trial = tried.q;
    VecX& trial_residual = tried.residual;
    const double released = tried.released, ratio = tried.ratio, trial_norm = tried.norm;
    const bool corrected = tried.corrected;
    const char* judged = "energy";
    const bool accept = Acceptable(step, tried, norm, energy_noise, judged);
    if (!accept || (ratio < kShrinkRatio && !step.interior)) {
      radius = kShrinkRatio * std::min(radius, step_length);
    } else if (ratio > kGrowRatio && step_length >= kBoundaryFraction * radius) {
      radius = std::min(2.0 * radius, options_.max_radius);
    }
    Log(fmt::format("  trust region {:3d}: |R| {:.4e} -> {:.4e} N, released {:.4e} J of {:.4e} ({} rho {:.3f}), "
                    "step {:.3e} m {}{}{}, radius {:.3e} m ({} active-set rounds, {} factorizations){}",
                    result.iterations, norm, trial_norm, released, step.predicted, judged, ratio, step_length,
                    step.interior ? "Newton" : step.negative_curvature ? "negative curvature" : "boundary",
                    step.shift > 0.0 ? fmt::format(" sigma {:.3e}", step.shift) : std::string(),
                    corrected ? " +SOC" : "", radius, rounds_, step_factorizations, accept ? "" : "; refused"));
    full_newton_small = false;
    if (accept) {
      result.q = std::move(trial);
      residual = std::move(trial_residual);
      result.energy_released += released;
      if (step.negative_curvature) ++result.negative_curvature_steps;
      if (corrected) ++result.second_order_corrections;
      full_newton_small = step.interior && options_.increment_tolerance > 0.0 &&
                          step.p.lpNorm<Eigen::Infinity>() <= options_.increment_tolerance;
    }
    if (radius < kSmallestRadius) {
      result.residual_norm = residual.norm();
      result.failure = fmt::format("the trust radius fell below {:.0e} m (no step releases energy; |R| {:.4g} N)",
                                   kSmallestRadius, result.residual_norm);
      return result;
    }
  }
}

}  // namespace

EnergyTrustRegionResult MinimizeEnergy(StaticProblem& problem, const VecX& q_start,
                                       const EnergyTrustRegionOptions& options) {
  if (q_start.size() != problem.num_positions() || !q_start.allFinite()) {
    throw LogicError("MinimizeEnergy: q_start has the wrong size or is not finite");
  }
  if (!(options.residual_tolerance > 0.0) || options.max_iterations < 1 || !(options.initial_radius > 0.0) ||
      !(options.max_radius >= options.initial_radius)) {
    throw LogicError("MinimizeEnergy: invalid options");
  }
  if (std::isnan(problem.EnergyChange(q_start, q_start))) {
    throw LogicError("MinimizeEnergy: the problem has no energy (StaticProblem::EnergyChange)");
  }
  const profile::Scope scope("static: energy trust region");
  Minimizer minimizer(problem, options);
  return minimizer.Run(q_start);
}

}  // namespace drillflex::solvers
