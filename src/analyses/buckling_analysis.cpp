#include "analyses/buckling_analysis.hpp"
#include "model/static_problem.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "core/error.hpp"
#include "solvers/buckling.hpp"
#include "solvers/eigen.hpp"
#include "solvers/newton.hpp"

namespace drillflex::analyses {
namespace {

struct Equilibrium {
  VecX q;
  bool converged = false;
};

// The static equilibrium under λ × the case's loads, from the reference placement.
Equilibrium SolveAt(const model::SystemModel& model, double load_factor) {
  if (load_factor == 0.0) return {model.ReferencePositions(), true};
  model::StaticModelProblem problem(model, load_factor);
  solvers::NewtonOptions options = DefaultNewtonOptions();
  options.throw_on_failure = false;
  const solvers::StaticResult result = solvers::SolveStatic(problem, model.ReferencePositions(), options);
  return {result.q, result.converged};
}

// The largest axial compression along the string at q (N, ≥ 0).
double MaxCompression(const model::SystemModel& model, const VecX& q, double load_factor) {
  double compression = 0.0;
  for (const StaticNodeResult& node : StaticNodeResults(model, q, load_factor)) {
    compression = std::max(compression, -node.axial_force);
  }
  return compression;
}

// The buckled mode per station (string frame, max |displacement| = 1).
void FillBuckledMode(const model::SystemModel& model, const VecX& q, const VecX& mode, BucklingResult& result) {
  const auto poses = model.Poses(q);
  double largest = 0.0;
  for (const Station& station : StringStations(model)) {
    const NodeVelocity node = MapToNode(model.bodies()[station.body], poses[station.body], mode, station.node);
    result.s.push_back(station.s);
    result.mode_displacement.push_back(node.translation);
    result.mode_rotation.push_back(node.rotation);
    largest = std::max(largest, node.translation.norm());
  }
  if (largest == 0.0) return;
  for (Vec3& d : result.mode_displacement) d /= largest;
  for (Vec3& r : result.mode_rotation) r /= largest;
}

// The eigenproblem with K_G from the equilibrium at λ_ref: (K_0 + μ K_G) x = 0,
// K_G = (K_T(q_ref, λ_ref) − K_0) / λ_ref.
struct LinearizedBuckling {
  bool converged = false;  // the static equilibrium at λ_ref was found
  double reference_factor = 0.0;
  VecX q;
  solvers::BucklingResult buckling;
  double multiplier() const { return buckling.multipliers.size() > 0 ? buckling.multipliers[0] : std::nan(""); }
};

LinearizedBuckling BucklingAt(const model::SystemModel& model, const SparseMat& unloaded, double reference_factor,
                              int count) {
  LinearizedBuckling result;
  result.reference_factor = reference_factor;
  const Equilibrium loaded = SolveAt(model, reference_factor);
  if (!loaded.converged) return result;
  result.converged = true;
  result.q = loaded.q;
  const SparseMat geometric =
      (SparseMat(Linearize(model, loaded.q, reference_factor).stiffness - unloaded) / reference_factor).pruned();
  result.buckling = solvers::SolveBuckling(unloaded, geometric, count);
  return result;
}

// (a) The linearized eigenproblem (header), with λ_ref iterated to μ by the secant method on
// g(λ_ref) = μ(λ_ref) − λ_ref.
void SolveEigenproblem(const model::SystemModel& model, const BucklingSettings& settings, BucklingResult& result) {
  const VecX reference = model.ReferencePositions();
  const SparseMat unloaded = Linearize(model, reference, 0.0).stiffness;
  const int count = std::max(settings.modes, 1);
  // The first reference state: λ_ref = 1, halved while the equilibrium cannot be found.
  LinearizedBuckling current = BucklingAt(model, unloaded, 1.0, count);
  while (!current.converged && current.reference_factor > 1.0 / 64.0) {
    current = BucklingAt(model, unloaded, 0.5 * current.reference_factor, count);
  }
  if (!current.converged) throw SolverError("buckling: no static equilibrium found even at 1/64 of the loads");
  result.reference_compression =
      MaxCompression(model, current.q, current.reference_factor) / current.reference_factor;
  if (std::isnan(current.multiplier())) {
    throw SolverError("buckling: the case's loads do not buckle the string (no positive load multiplier)");
  }
  LinearizedBuckling previous;
  constexpr int kSecantSteps = 12;
  constexpr double kTolerance = 1e-7;
  for (int step = 0; step < kSecantSteps; ++step) {
    const double g = current.multiplier() - current.reference_factor;
    if (std::abs(g) <= kTolerance * current.multiplier()) break;
    double next = current.multiplier();  // fixed-point step first, then secant
    if (previous.converged && !std::isnan(previous.multiplier())) {
      const double g_previous = previous.multiplier() - previous.reference_factor;
      if (g != g_previous) {
        next = current.reference_factor - g * (current.reference_factor - previous.reference_factor) / (g - g_previous);
      }
    }
    if (!(next > 0.0) || !std::isfinite(next)) break;
    LinearizedBuckling trial = BucklingAt(model, unloaded, next, count);
    // Beyond a limit point of a nonlinear prebuckling path: step back halfway.
    for (int cut = 0; cut < 4 && (!trial.converged || std::isnan(trial.multiplier())); ++cut) {
      next = 0.5 * (next + current.reference_factor);
      trial = BucklingAt(model, unloaded, next, count);
    }
    if (!trial.converged || std::isnan(trial.multiplier())) break;
    previous = std::move(current);
    current = std::move(trial);
  }
  const solvers::BucklingResult& buckling = current.buckling;
  result.reference_load_factor = current.reference_factor;
  result.load_factors.assign(buckling.multipliers.data(), buckling.multipliers.data() + buckling.multipliers.size());
  result.load_factor = result.load_factors.front();
  result.critical_load = result.load_factor * result.reference_compression;
  FillBuckledMode(model, current.q, buckling.modes.col(0), result);
}

// ω² (signed) of the lowest mode above the `rigid` rigid-body modes at λ, or NaN if no equilibrium.
FrequencyLoadPoint FrequencyAt(const model::SystemModel& model, double load_factor, int rigid, double& eigenvalue) {
  FrequencyLoadPoint point;
  point.load_factor = load_factor;
  const Equilibrium equilibrium = SolveAt(model, load_factor);
  eigenvalue = std::nan("");
  if (!equilibrium.converged) return point;
  const LinearizedSystem system = Linearize(model, equilibrium.q, load_factor);
  solvers::ModalResult modal;
  try {
    modal = LowestModes(system, rigid + 1);
  } catch (const SolverError&) {
    return point;  // no modes beyond buckling on a large model: the sample is dropped
  }
  eigenvalue = modal.eigenvalues[rigid];
  point.frequency_hz = std::sqrt(std::max(eigenvalue, 0.0)) / (2.0 * kPi);
  point.compression = MaxCompression(model, equilibrium.q, load_factor);
  return point;
}

// The root of ω²(λ) = 0 from the points nearest the current estimate: a quadratic through three
// (the root nearest the secant root of the last two), a line through two.
double ExtrapolateRoot(std::vector<std::pair<double, double>> points, double estimate) {
  std::sort(points.begin(), points.end(), [estimate](const auto& a, const auto& b) {
    return std::abs(a.first - estimate) < std::abs(b.first - estimate);
  });
  const auto& [x0, y0] = points[0];
  const auto& [x1, y1] = points[1];
  const double secant = x0 - y0 * (x1 - x0) / (y1 - y0);
  if (points.size() < 3) return secant;
  const auto& [x2, y2] = points[2];
  // Newton's divided differences: y = y0 + d1 (x − x0) + d2 (x − x0)(x − x1).
  const double d01 = (y1 - y0) / (x1 - x0), d12 = (y2 - y1) / (x2 - x1);
  const double d2 = (d12 - d01) / (x2 - x0);
  if (std::abs(d2) < 1e-14 * std::abs(d01) / std::max(std::abs(x0), 1e-300)) return secant;
  // In powers of u = x − x0: d2 u² + (d01 + d2 (x0 − x1)) u + y0 = 0.
  const double b = d01 + d2 * (x0 - x1);
  const double discriminant = b * b - 4.0 * d2 * y0;
  if (discriminant < 0.0) return secant;
  const double root_a = x0 + (-b + std::sqrt(discriminant)) / (2.0 * d2);
  const double root_b = x0 + (-b - std::sqrt(discriminant)) / (2.0 * d2);
  return std::abs(root_a - secant) < std::abs(root_b - secant) ? root_a : root_b;
}

// Successive f² → 0 estimates that agree to this (relative) count as converged.
constexpr double kFrequencyTolerance = 1e-4;

// (b) f² → 0 (header).
void SolveByFrequencies(const model::SystemModel& model, const BucklingSettings& settings, BucklingResult& result) {
  const VecX reference = model.ReferencePositions();
  const int rigid = CountRigidBodyModes(model, reference, Linearize(model, reference, 0.0));
  std::vector<std::pair<double, double>> samples;  // (λ, ω²)
  auto sample = [&](double load_factor) {
    double eigenvalue = 0.0;
    const FrequencyLoadPoint point = FrequencyAt(model, load_factor, rigid, eigenvalue);
    if (std::isnan(eigenvalue)) return false;
    result.frequency_table.push_back(point);
    samples.emplace_back(load_factor, eigenvalue);
    return true;
  };
  const double range = result.load_factor > 0.0 ? result.load_factor : 1.0;
  const int count = std::max(settings.frequency_points, 2);
  for (int i = 0; i < count; ++i) sample(range * i / count);
  if (samples.size() < 2) return;
  result.unloaded_frequency_hz = result.frequency_table.front().frequency_hz;
  double estimate = ExtrapolateRoot(samples, samples.back().first);
  // Refinement just below the estimate, where ω² is still far above its round-off (the stiff
  // couplings put ~1e-4 ω₀² of noise on ω² near zero for long soft strings): at 0.9, 0.97 and
  // 0.99 of it, re-extrapolating through the three samples nearest each time.
  for (double fraction : {0.9, 0.97, 0.99}) {
    if (!std::isfinite(estimate) || estimate <= 0.0 || !sample(fraction * estimate)) break;
    const double next = ExtrapolateRoot(samples, estimate);
    result.frequency_method_converged = std::abs(next - estimate) <= kFrequencyTolerance * std::abs(estimate);
    estimate = next;
  }
  if (std::isfinite(estimate) && estimate > 0.0) {
    result.frequency_load_factor = estimate;
    result.frequency_critical_load = estimate * result.reference_compression;
  }
  std::sort(result.frequency_table.begin(), result.frequency_table.end(),
            [](const auto& a, const auto& b) { return a.load_factor < b.load_factor; });
}

}  // namespace

BucklingResult RunBuckling(const model::BuiltModel& built, const BucklingSettings& settings) {
  BucklingResult result;
  SolveEigenproblem(built.system, settings, result);
  if (settings.frequency_method) SolveByFrequencies(built.system, settings, result);
  return result;
}

}  // namespace drillflex::analyses
