#include "solvers/line_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drillflex::solvers {
namespace {

struct Trial {
  double step = 0.0;
  VecX q;
  VecX residual;
  double merit = std::numeric_limits<double>::infinity();
};

}  // namespace

LineSearchResult BacktrackingLineSearch(const Problem& problem, double t, const VecX& q,
                                        const VecX& residual, const VecX& dv,
                                        const LineSearchOptions& options) {
  const VecX zero = VecX::Zero(problem.num_velocities());
  auto half_square = [](const VecX&, const VecX& r) { return 0.5 * r.squaredNorm(); };
  // Slope of the merit at α = 0 (see the header) and the merit itself.
  MeritFunction merit = half_square;
  double slope = -residual.squaredNorm();
  if (options.merit) {
    const double energy_slope = residual.dot(dv);
    if (energy_slope < 0.0) {
      merit = options.merit;
      slope = energy_slope;
    }
  }
  const double merit0 = merit(q, residual);

  LineSearchResult result;
  Trial best;
  double step = 1.0;
  while (true) {
    Trial trial;
    trial.step = step;
    trial.q = problem.Increment(q, step * dv);
    trial.residual = problem.Residual(t, trial.q, zero, zero);
    ++result.residual_evaluations;
    if (trial.residual.allFinite()) trial.merit = merit(trial.q, trial.residual);
    if (!std::isfinite(trial.merit)) trial.merit = std::numeric_limits<double>::infinity();
    const bool armijo = trial.merit <= merit0 + options.sufficient_decrease * step * slope;
    if (trial.merit < best.merit || best.q.size() == 0) best = trial;
    if (!options.enabled || armijo) {
      result.sufficient_decrease = armijo;
      best = std::move(trial);
      break;
    }
    if (step <= options.min_step) break;
    // Minimiser of the quadratic through φ(0), φ'(0), φ(α), kept in [0.1 α, 0.5 α].
    double next = 0.5 * step;
    if (std::isfinite(trial.merit)) {
      const double curvature = trial.merit - merit0 - slope * step;
      if (curvature > 0.0) next = -slope * step * step / (2.0 * curvature);
      next = std::clamp(next, 0.1 * step, 0.5 * step);
    } else {
      next = 0.1 * step;
    }
    step = std::max(next, options.min_step);
  }
  result.step = best.step;
  result.q = std::move(best.q);
  result.residual = std::move(best.residual);
  result.decreased = best.merit < merit0;
  return result;
}

}  // namespace drillflex::solvers
