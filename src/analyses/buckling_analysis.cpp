#include "analyses/buckling_analysis.hpp"
#include "model/static_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/static_minimum.hpp"
#include "analyses/wall_offsets.hpp"
#include "core/error.hpp"
#include "solvers/buckling.hpp"
#include "solvers/eigen.hpp"
#include "solvers/linear_solver.hpp"
#include "solvers/newton.hpp"

namespace drillflex::analyses {
namespace {

struct Equilibrium {
  VecX q;
  bool converged = false;
};

// The static equilibria under λ × the case's loads, by the path the static analysis takes: a string
// in a well (no case supports) by the energy's minimum (analyses/static_minimum.hpp), each from the
// equilibrium already found at the nearest λ (the first from the string resting on the wall); any
// other string by Newton's load stepping from the reference placement.
class EquilibriumSolver {
 public:
  // In a well the string at rest (a rotating string's friction left out: it buckles as it lies).
  EquilibriumSolver(const model::ModelInput& input, const model::BuiltModel& built, const StaticSettings& settings)
      : input_(input), built_(built), settings_(settings),
        in_well_(input.trajectory.has_value() && !input.hole.empty() && input.supports.empty()) {
    input_.static_sliding.reset();
  }

  const model::SystemModel& model() const { return built_.system; }
  bool in_well() const { return in_well_; }

  Equilibrium At(double load_factor) {
    const model::SystemModel& model = built_.system;
    if (load_factor == 0.0) return {model.ReferencePositions(), true};
    if (!in_well_) {
      model::StaticModelProblem problem(model, load_factor);
      solvers::NewtonOptions options = DefaultNewtonOptions();
      options.throw_on_failure = false;
      const solvers::StaticResult result = solvers::SolveStatic(problem, model.ReferencePositions(), options);
      return {result.q, result.converged};
    }
    const VecX* start = nullptr;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& [factor, q] : found_) {
      if (factor == load_factor) return {q, true};  // found already
      if (std::abs(factor - load_factor) < nearest) {
        nearest = std::abs(factor - load_factor);
        start = &q;
      }
    }
    const StaticMinimum minimum = SolveStaticMinimum(input_, built_, settings_, load_factor, start);
    if (!minimum.converged || minimum.at_rest_only) return {minimum.q, false};
    found_.emplace_back(load_factor, minimum.q);
    return {minimum.q, true};
  }

 private:
  model::ModelInput input_;
  const model::BuiltModel& built_;
  const StaticSettings& settings_;
  const bool in_well_;
  std::vector<std::pair<double, VecX>> found_;  // (λ, equilibrium) found so far
};

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

LinearizedBuckling BucklingAt(EquilibriumSolver& solver, const SparseMat& unloaded, double reference_factor,
                              int count) {
  const model::SystemModel& model = solver.model();
  LinearizedBuckling result;
  result.reference_factor = reference_factor;
  const Equilibrium loaded = solver.At(reference_factor);
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
void SolveEigenproblem(EquilibriumSolver& solver, const BucklingSettings& settings, BucklingResult& result) {
  const model::SystemModel& model = solver.model();
  const VecX reference = model.ReferencePositions();
  const SparseMat unloaded = Linearize(model, reference, 0.0).stiffness;
  const int count = std::max(settings.modes, 1);
  // The first reference state: λ_ref = 1, halved while the equilibrium cannot be found.
  LinearizedBuckling current = BucklingAt(solver, unloaded, 1.0, count);
  while (!current.converged && current.reference_factor > 1.0 / 64.0) {
    current = BucklingAt(solver, unloaded, 0.5 * current.reference_factor, count);
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
    LinearizedBuckling trial = BucklingAt(solver, unloaded, next, count);
    // Beyond a limit point of a nonlinear prebuckling path: step back halfway.
    for (int cut = 0; cut < 4 && (!trial.converged || std::isnan(trial.multiplier())); ++cut) {
      next = 0.5 * (next + current.reference_factor);
      trial = BucklingAt(solver, unloaded, next, count);
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

// (a) in a well: the string is held laterally only by its contacts, which the reference placement on
// the hole axis does not have (K_0 singular), so the problem is linearized about the case's own
// stable equilibrium q_a at λ_a instead (the string at rest): K_a = K_T(q_a, λ_a), positive definite
// (the static solve found a minimum), and K_G = dK_T/dλ along the equilibrium path with the contacts
// as they are, dK_T/dλ = ∂K_T/∂λ + ∂K_T/∂q · dq/dλ, dq/dλ = −K_a⁻¹ ∂R/∂λ (the path's tangent), by
// one difference over ε along it. (K_a + ν K_G) x = 0 gives μ = λ_a + ν; λ_a then moves halfway to
// μ, re-linearized there, until μ repeats to kInWellTolerance (contacts take up load on the way).
constexpr double kPathDifference = 1e-4;    // ε / λ_a of the difference along the path
constexpr double kInWellTolerance = 1e-3;   // relative change of μ that ends the iteration
constexpr int kInWellIterations = 8;

// dK_T/dλ at the equilibrium q of λ, contacts as they are (above); `tangent` = K_T(q, λ).
SparseMat PathStiffnessChange(const model::SystemModel& model, const VecX& q, double load_factor,
                              const SparseMat& tangent) {
  const VecX zero = VecX::Zero(model.num_velocities());
  const double epsilon = kPathDifference * load_factor;
  const model::LoadParameters here{load_factor, 0.0}, ahead{load_factor + epsilon, 0.0};
  const VecX load_rate = (model.Residual(0.0, q, zero, zero, ahead) - model.Residual(0.0, q, zero, zero, here)) / epsilon;
  solvers::SparseLinearSolver solver;
  solver.Factorize(tangent, solvers::MatrixSymmetry::kSymmetric);
  VecX path = -solver.Solve(load_rate);
  // The torque on bit twists the string by radians per unit load: its bodies turn about their axes
  // along the path, and their body-frame coordinates with them, which a stiffness of 1e13 N/m turns
  // into changes of 1e14 that are no stiffness at all. The twist is left out of the path: K_G is the
  // rate of the lateral and axial stiffness under the growing weight and WOB (the lateral buckling
  // an engineer asks about), the torque's own (Greenhill) softening not in it.
  for (const model::Body& body : model.bodies()) path[body.v_offset + 3] = 0.0;
  const VecX moved = model.IncrementKeepingShape(q, epsilon * path);
  SparseMat stiffness = Linearize(model, moved, ahead).stiffness;
  // A contact at its onset that the small move closes or opens would put its whole k_n a aᵀ / ε into
  // the difference: each is restored to the state it has at q (the contacts as they are).
  const std::vector<solvers::PenaltyTerm> before = model.PenaltyTerms(q, here);
  const std::vector<solvers::PenaltyTerm> after = model.PenaltyTerms(moved, ahead);
  for (std::size_t c = 0; c < before.size() && c < after.size(); ++c) {
    const bool touching = before[c].value > 0.0, touches = after[c].value > 0.0;
    if (touching == touches) continue;
    const solvers::PenaltyTerm& term = after[c];
    const double sign = touching ? 1.0 : -1.0;
    for (std::size_t i = 0; i < term.indices.size(); ++i) {
      for (std::size_t j = 0; j < term.indices.size(); ++j) {
        stiffness.coeffRef(term.indices[i], term.indices[j]) += sign * term.stiffness * term.gradient[i] * term.gradient[j];
      }
    }
  }
  const SparseMat change = (stiffness - tangent) / epsilon;
  return (0.5 * (change + SparseMat(change.transpose()))).pruned();
}

void SolveEigenproblemInWell(EquilibriumSolver& solver, const BucklingSettings& settings, BucklingResult& result) {
  const model::SystemModel& model = solver.model();
  const int count = std::max(settings.modes, 1);
  double reference = 1.0;
  Equilibrium at = solver.At(reference);
  if (!at.converged) throw SolverError("buckling: no static equilibrium found at the case's loads");
  result.reference_compression = MaxCompression(model, at.q, 1.0);
  double estimate = std::nan("");
  solvers::BucklingResult buckling;
  VecX mode_state = at.q;
  for (int iteration = 0; iteration < kInWellIterations; ++iteration) {
    // The string at rest: no rotating friction in its tangent.
    const SparseMat tangent = Linearize(model, at.q, {reference, 0.0}).stiffness;
    const SparseMat change = PathStiffnessChange(model, at.q, reference, tangent);
    // Lateral buckling: the bodies' turns about their own axes (the string's twist, held only by the
    // rotary table: 1e3 N·m/rad over hundreds of metres) are held, so that the twist, whose rate the
    // path leaves out, does not pass for a buckling mode.
    SparseMat held = tangent;
    const double stiff = tangent.diagonal().cwiseAbs().maxCoeff();
    SparseMat lateral = change;
    for (const model::Body& body : model.bodies()) {
      const int twist = body.v_offset + 3;
      held.coeffRef(twist, twist) += stiff;
      for (SparseMat::InnerIterator it(lateral, twist); it; ++it) it.valueRef() = 0.0;
    }
    lateral = SparseMat(lateral.transpose());
    for (const model::Body& body : model.bodies()) {
      for (SparseMat::InnerIterator it(lateral, body.v_offset + 3); it; ++it) it.valueRef() = 0.0;
    }
    solvers::BucklingResult trial = solvers::SolveBuckling(held, lateral.pruned(), count);
    if (trial.multipliers.size() == 0) break;  // the loads stiffen the string from here on
    const double next = reference + trial.multipliers[0];
    buckling = std::move(trial);
    mode_state = at.q;
    result.reference_load_factor = reference;
    const bool settled = std::isfinite(estimate) && std::abs(next - estimate) <= kInWellTolerance * next;
    estimate = next;
    if (settled) break;
    // Halfway to the estimate, from the equilibrium there (still below it: a stable one).
    const double closer = reference + 0.5 * (next - reference);
    const Equilibrium there = solver.At(closer);
    if (!there.converged) break;
    reference = closer;
    at = there;
  }
  if (!std::isfinite(estimate)) {
    throw SolverError("buckling: the case's loads do not buckle the string in its hole (no positive load multiplier "
                      "from its equilibrium: the loads stiffen it)");
  }
  result.load_factors.clear();
  for (Eigen::Index i = 0; i < buckling.multipliers.size(); ++i) {
    result.load_factors.push_back(result.reference_load_factor + buckling.multipliers[i]);
  }
  result.load_factor = estimate;
  result.critical_load = result.load_factor * result.reference_compression;
  FillBuckledMode(model, mode_state, buckling.modes.col(0), result);
}

// Dawson–Paslay's and Chen's loads along the case's equilibrium q (λ = 1) in a well (header).
SinusoidalBucklingScreen ScreenSinusoidalBuckling(const model::ModelInput& input, const model::BuiltModel& built,
                                                  const VecX& q) {
  const model::SystemModel& model = built.system;
  std::vector<StaticNodeResult> nodes = StaticNodeResults(model, q, 1.0);
  AddWallOffsets(built, q, nodes);
  SinusoidalBucklingScreen screen;
  double least = std::numeric_limits<double>::infinity();
  std::size_t b = 0;
  for (const StaticNodeResult& node : nodes) {
    const double compression = -node.axial_force;
    if (compression <= 0.0 || !node.has_wall) continue;
    while (b + 1 < model.bodies().size() && model.bodies()[b + 1].s_start <= node.s) ++b;
    const model::Body& body = model.bodies()[b];
    const double weight = std::abs(model::BuoyedWeightPerLength(body, input));
    const double inclination = input.trajectory->Inclination(node.md);
    const double clearance = std::max(node.hole_offset + node.clearance, 1e-6);  // r, m
    const double sinusoidal = 2.0 * std::sqrt(body.bending_rigidity * weight * std::sin(inclination) / clearance);
    const double factor = (sinusoidal / compression) * (sinusoidal / compression);
    screen.computed = true;
    // In a vertical hole F_sin = 0 (no weight holds the pipe to the wall): the ratio is left out.
    if (sinusoidal > 0.0) screen.largest_ratio = std::max(screen.largest_ratio, compression / sinusoidal);
    if (factor < least) {
      least = factor;
      screen.load_factor = factor;
      screen.s = node.s;
      screen.md = node.md;
      screen.compression = compression;
      screen.sinusoidal_load = sinusoidal;
      screen.helical_load = 2.0 * std::sqrt(2.0) * sinusoidal;
    }
  }
  return screen;
}

// ω² (signed) of the lowest mode above the `rigid` rigid-body modes at λ, or NaN if no equilibrium.
FrequencyLoadPoint FrequencyAt(EquilibriumSolver& solver, double load_factor, int rigid, double& eigenvalue) {
  const model::SystemModel& model = solver.model();
  FrequencyLoadPoint point;
  point.load_factor = load_factor;
  const Equilibrium equilibrium = solver.At(load_factor);
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
void SolveByFrequencies(EquilibriumSolver& solver, const BucklingSettings& settings, BucklingResult& result) {
  const model::SystemModel& model = solver.model();
  const VecX reference = model.ReferencePositions();
  const int rigid = CountRigidBodyModes(model, reference, Linearize(model, reference, 0.0));
  std::vector<std::pair<double, double>> samples;  // (λ, ω²)
  auto sample = [&](double load_factor) {
    double eigenvalue = 0.0;
    const FrequencyLoadPoint point = FrequencyAt(solver, load_factor, rigid, eigenvalue);
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

BucklingResult RunBuckling(const model::ModelInput& input, const model::BuiltModel& built,
                           const BucklingSettings& settings, const StaticSettings& static_settings) {
  EquilibriumSolver solver(input, built, static_settings);
  BucklingResult result;
  if (solver.in_well()) {
    SolveEigenproblemInWell(solver, settings, result);
    result.sinusoidal = ScreenSinusoidalBuckling(input, built, solver.At(1.0).q);
  } else {
    SolveEigenproblem(solver, settings, result);
  }
  // In a well the sweep from λ = 0 starts on the hole axis without contacts; the eigenproblem about the
  // equilibrium is the answer there.
  if (settings.frequency_method && !solver.in_well()) SolveByFrequencies(solver, settings, result);
  return result;
}

}  // namespace drillflex::analyses
