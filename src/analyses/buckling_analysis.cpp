#include "analyses/buckling_analysis.hpp"
#include "model/static_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analyses/linearization.hpp"
#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/static_minimum.hpp"
#include "analyses/wall_offsets.hpp"
#include "core/error.hpp"
#include "model/node_kinematics.hpp"
#include "model/string_above.hpp"
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

// The static equilibria along the buckling load path, by the path the static analysis takes: a
// string in a well (no case supports) by the energy's minimum (analyses/static_minimum.hpp), each
// from the equilibrium already found at the nearest multiplier (the first from the string resting on
// the wall); any other string by Newton's method from the nearest equilibrium found (the first from
// the reference placement). The path scales every load (load factor μ) or the WOB alone (the
// parameter block's WOB, μ × the case's): one model, the case's.
class EquilibriumSolver {
 public:
  // In a well the string at rest (a rotating string's friction left out: it buckles as it lies).
  EquilibriumSolver(const model::ModelInput& input, const model::BuiltModel& built, const StaticSettings& settings,
                    bool scale_wob)
      : input_(input), built_(built), settings_(settings), scale_wob_(scale_wob),
        in_well_(input.well && !input.well->hole.empty() && input.supports.empty()) {
    input_.static_sliding.reset();
  }

  bool in_well() const { return in_well_; }
  // Drops the equilibria found so far (the next starts from the string at rest).
  void Forget() { found_.clear(); }
  bool scale_wob() const { return scale_wob_; }
  const model::SystemModel& model() const { return built_.system; }
  const model::BuiltModel& built() const { return built_; }
  // The model and its load parameters at multiplier μ (at rest: no friction).
  const model::SystemModel& ModelAt(double /*multiplier*/) const { return built_.system; }
  model::LoadParameters LoadsAt(double multiplier) const {
    model::LoadParameters load(scale_wob_ ? 1.0 : multiplier, 0.0);
    load.sliding_mode = model::SlidingMode::kVelocities;
    if (scale_wob_) load.weight_on_bit = multiplier * input_.operation.weight_on_bit;
    return load;
  }

  // The multiplier at which the pipe above the model (model/string_above.hpp) reaches its own
  // sinusoidal load F_sin, its compression growing with the load: ∞ without one, or where it
  // stands at every multiplier up to 1000 (or lies buckled already at 1/1000 of the loads).
  double PipeAboveOnset() const {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    if (!built_.string_above) return kInfinity;
    const model::StringAboveElement& above = built_.Get(*built_.string_above);
    auto margin = [&](double multiplier) { return above.BucklingMargin(LoadsAt(multiplier)); };
    double low = 1e-3;
    if (!(margin(low) > 0.0)) return kInfinity;
    double high = low;
    while (margin(high) > 0.0) {
      low = high;
      high *= 2.0;
      if (high > 1e3) return kInfinity;
    }
    for (int i = 0; i < 60 && high - low > 1e-10 * high; ++i) {
      const double middle = 0.5 * (low + high);
      (margin(middle) > 0.0 ? low : high) = middle;
    }
    return high;
  }

  Equilibrium At(double multiplier) {
    const model::SystemModel& model = ModelAt(multiplier);
    if (multiplier == 0.0 && !scale_wob_) return {model.ReferencePositions(), true};
    const VecX* start = nullptr;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& [factor, q] : found_) {
      if (factor == multiplier) return {q, true};  // found already
      if (std::abs(factor - multiplier) < nearest) {
        nearest = std::abs(factor - multiplier);
        start = &q;
      }
    }
    Equilibrium result;
    if (!in_well_) {
      model::StaticModelProblem problem(model, LoadsAt(multiplier));
      solvers::NewtonOptions options = DefaultNewtonOptions();
      options.throw_on_failure = false;
      const VecX from = start != nullptr ? *start : model.ReferencePositions();
      const solvers::NewtonResult solved = solvers::SolveStatic(problem, from, options);
      result = {solved.q, solved.converged};
    } else {
      const StaticMinimum minimum =
          SolveStaticMinimum(input_, built_, settings_, LoadsAt(multiplier), start);
      result = {minimum.q, minimum.converged && !minimum.at_rest_only};
    }
    if (result.converged) found_.emplace_back(multiplier, result.q);
    return result;
  }

 private:
  model::ModelInput input_;
  const model::BuiltModel& built_;
  const StaticSettings& settings_;
  const bool scale_wob_;
  const bool in_well_;
  std::vector<std::pair<double, VecX>> found_;  // (μ, equilibrium) found so far
};

// The largest axial compression along the string at q (N, ≥ 0).
double MaxCompression(const model::BuiltModel& built, const VecX& q, const model::LoadParameters& load) {
  double compression = 0.0;
  for (const StaticNodeResult& node : StaticNodeResults(built, q, load)) {
    compression = std::max(compression, -node.axial_force);
  }
  return compression;
}

// The buckled mode per station (string frame, max |displacement| = 1).
void FillBuckledMode(const model::SystemModel& model, const VecX& q, const VecX& mode, BucklingResult& result) {
  const auto poses = model.Poses(q);
  double largest = 0.0;
  for (const Station& station : StringStations(model)) {
    const model::NodeRates node =
        model::ComputeStringFrameNodeRates(model.bodies()[station.body], poses[station.body], mode, station.node);
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
      MaxCompression(solver.built(), current.q, current.reference_factor) / current.reference_factor;
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

// About the case's equilibrium (a string in a well, or the WOB scaled alone): the multiplier μ at
// which the lowest lateral natural frequency of the string at rest about its equilibrium reaches
// zero, i.e. where the tangent stiffness K_T(q(μ), μ) of the loaded static state stops being positive
// definite (the paper's Figure 5 route, from the loaded state instead of from the unloaded string:
// in a well nothing but the contacts and the tension above holds the string laterally, so K at no
// load is singular). Samples: μ = 1, then 1 + kFirstStep, then steps toward the root of ω²(μ)
// extrapolated through the three samples nearest it (ExtrapolateRoot), each kApproach of the way,
// until the estimate repeats to kAboutTolerance. While ω² does not yet fall (a string on the wall
// pressed harder by the load) the samples march up (kMarch) first. A string that lies buckled at the
// case's loads (ω² ≤ 0 there, or a frequency that rises all the way up the march, or until it breaks,
// from an equilibrium compressed beyond Dawson–Paslay's load: the post-buckled string stiffens as it is
// pressed) has its onset below them: the search starts again from a fraction of the loads on a fresh
// path (OnsetSearch::FromBelow). The pipe above the model (model/string_above.hpp) caps the search
// where its own compression reaches F_sin (OnsetSearch::AtCeiling).
// ω² is of the mode whose kinetic energy is mostly lateral (SplitKineticEnergy), with the bodies'
// turns about their own axes held (the string's twist, held only by the rotary table, is no buckling
// mode). Each equilibrium is warm-started from the nearest one (the string stays in the same state of
// contact up to the onset).
double ExtrapolateRoot(std::vector<std::pair<double, double>> points, double estimate);

constexpr double kFirstStep = 0.05;
constexpr double kApproach = 0.7;
constexpr double kAboutTolerance = 1e-3;
constexpr int kAboutSamples = 14;
// Where to look next while ω² does not yet fall (× the loads).
constexpr std::array<double, 6> kMarch = {1.5, 2.0, 3.0, 4.0, 6.0, 8.0};
// Below the loads of a string buckled at them: the first sample at this fraction of the multiplier
// where Dawson–Paslay's check first reaches F_sin, then the march at these fractions of the way to 1.
constexpr double kBelowStart = 0.5;
constexpr std::array<double, 4> kBelowMarch = {0.25, 0.5, 0.75, 0.9};

struct LateralSample {
  double multiplier = 0.0;
  double eigenvalue = 0.0;   // ω², rad²/s²
  double compression = 0.0;  // N
  VecX q, mode;
};

// The lowest mostly-lateral mode about the equilibrium at μ; false if no equilibrium is found.
bool SampleLateralMode(EquilibriumSolver& solver, double multiplier, LateralSample& sample) {
  const Equilibrium equilibrium = solver.At(multiplier);
  if (!equilibrium.converged) return false;
  const model::SystemModel& model = solver.ModelAt(multiplier);
  LinearizedSystem system = Linearize(model, equilibrium.q, solver.LoadsAt(multiplier));
  const double stiff = system.stiffness.diagonal().cwiseAbs().maxCoeff();
  for (const model::Body& body : model.bodies()) system.stiffness.coeffRef(body.v_offset + 3, body.v_offset + 3) += stiff;
  solvers::ModalResult modal;
  try {
    modal = LowestModes(system, 6);
  } catch (const SolverError&) {
    return false;
  }
  const auto poses = model.Poses(equilibrium.q);
  for (Eigen::Index i = 0; i < modal.eigenvalues.size(); ++i) {
    const EnergySplit split = SplitKineticEnergy(model, poses, modal.vectors.col(i));
    const double total = split.axial + split.torsional + split.lateral;
    if (total <= 0.0 || split.lateral < 0.5 * total) continue;
    sample.multiplier = multiplier;
    sample.eigenvalue = modal.eigenvalues[i];
    sample.compression = MaxCompression(solver.built(), equilibrium.q, solver.LoadsAt(multiplier));
    sample.q = equilibrium.q;
    sample.mode = modal.vectors.col(i);
    return true;
  }
  return false;
}

// The samples of one path of equilibria and the onset found along it (header of this part).
class OnsetSearch {
 public:
  OnsetSearch(EquilibriumSolver& solver, BucklingResult& result)
      : solver_(solver), result_(result), ceiling_(solver.PipeAboveOnset()) {}

  // From the case's loads upward; `screen` (computed or not) tells a string buckled at them.
  void FromCaseLoads(const SinusoidalBucklingScreen& screen) {
    if (!Take(1.0)) {
      throw SolverError("buckling: no stable equilibrium (or no lateral mode about it) at the case's loads");
    }
    result_.reference_compression = samples_.front().compression;
    result_.unloaded_frequency_hz = result_.frequency_table.front().frequency_hz;
    if (samples_.front().eigenvalue <= 0.0) return FromBelow(screen, "its lowest lateral natural frequency is not positive");
    if (ceiling_ <= 1.0) {
      return FromBelow(screen, "the pipe above the model is compressed beyond its sinusoidal load F_sin");
    }
    if (ceiling_ <= 1.0 + kFirstStep) return Approach(1.0, ceiling_, ceiling_);
    if (!Take(1.0 + kFirstStep)) throw SolverError("buckling: no equilibrium just above the case's loads");
    if (samples_.back().eigenvalue <= 0.0) return Approach(1.0, 1.0 + kFirstStep, TrendRoot());
    // A string lying on the wall may first stiffen as the load grows (its contacts press harder):
    // march up until ω² falls.
    bool at_ceiling = false;  // the march reached where the pipe above buckles
    for (const double multiplier : kMarch) {
      if (std::isfinite(TrendRoot())) break;
      if (multiplier >= ceiling_) {
        at_ceiling = true;
        break;
      }
      if (!Take(multiplier)) break;
      if (samples_.back().eigenvalue <= 0.0) {
        const double below = samples_[samples_.size() - 2].multiplier;
        return Approach(below, multiplier, TrendRoot());
      }
    }
    const double below = samples_.back().multiplier;  // the largest multiplier sampled, ω² > 0
    const double estimate = TrendRoot();
    if (std::isfinite(estimate) && estimate > below) return Approach(below, kInfinity, estimate);
    // The frequency rose all the way (to the pipe above's onset, or until the march broke) from an
    // equilibrium compressed beyond Dawson–Paslay's load: the post-buckled string stiffens as it is
    // pressed, and the onset lies below.
    if (screen.computed && screen.load_factor < 1.0) {
      return FromBelow(screen, fmt::format("its compression {:.6g} N at MD {:.6g} m exceeds Dawson–Paslay's sinusoidal "
                                           "load{} ({:.6g} N), and its lowest lateral frequency rises with the load up "
                                           "to × {:g}",
                                           screen.compression, screen.md,
                                           screen.sinusoidal_load > 0.0 ? "" : " of a vertical hole",
                                           screen.sinusoidal_load, below));
    }
    if (at_ceiling) return AtCeiling();  // the pipe above buckles first, the modelled string standing
    // Every multiplier of the march sampled, each equilibrium stable, and ω² not falling at the end: no
    // onset up to it, a finished answer (the largest multiplier is a lower bound; BucklingResult::lower_bound).
    if (below == kMarch.back()) return LowerBound();
    throw SolverError(fmt::format("buckling: the string's lowest lateral frequency does not fall as the {} grows from "
                                  "the case's loads up to × {:g} ({:.6g} Hz at × 1, {:.6g} Hz at × {:g}), and the next "
                                  "step found no equilibrium or no lateral mode; give analyses.buckling.scale: {}",
                                  solver_.scale_wob() ? "WOB" : "load", below, result_.frequency_table[0].frequency_hz,
                                  result_.frequency_table.back().frequency_hz, below,
                                  solver_.scale_wob() ? "all" : "wob (with a WOB)"));
  }

 private:
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

  bool Take(double multiplier) {
    LateralSample sample;
    if (!SampleLateralMode(solver_, multiplier, sample)) return false;
    samples_.push_back(std::move(sample));
    FrequencyLoadPoint point;
    point.load_factor = multiplier;
    point.compression = samples_.back().compression;
    point.frequency_hz = std::sqrt(std::max(samples_.back().eigenvalue, 0.0)) / (2.0 * kPi);
    result_.frequency_table.push_back(point);
    return true;
  }

  // The secant root of the last two samples: where the local trend of ω² reaches zero (NaN while it
  // does not fall).
  double TrendRoot() const {
    if (samples_.size() < 2) return std::nan("");
    const LateralSample& a = samples_[samples_.size() - 2];
    const LateralSample& b = samples_.back();
    if (!(b.eigenvalue < a.eigenvalue)) return std::nan("");
    return b.multiplier - b.eigenvalue * (b.multiplier - a.multiplier) / (b.eigenvalue - a.eigenvalue);
  }

  std::vector<std::pair<double, double>> Points() const {
    std::vector<std::pair<double, double>> xy;
    for (const LateralSample& sample : samples_) {
      if (sample.eigenvalue > 0.0) xy.emplace_back(sample.multiplier, sample.eigenvalue);
    }
    return xy;
  }

  // The string lies buckled at the case's loads (`why`): a fresh path of equilibria from
  // kBelowStart × the multiplier where Dawson–Paslay's check first reaches F_sin (the WOB scaled: ≥ 0,
  // every load: ≥ 0.1, below which nothing holds the string to the wall), marching toward 1 until
  // ω² falls, then the approach below 1.
  void FromBelow(const SinusoidalBucklingScreen& screen, const std::string& why) {
    const double top = std::min(1.0, ceiling_);  // a multiplier past the onset
    const double floor = solver_.scale_wob() ? 0.0 : 0.1;
    const double start = std::min(
        std::clamp(screen.computed ? kBelowStart * screen.load_factor : kBelowStart, floor, kBelowStart), kBelowStart * top);
    auto fail = [&](const std::string& what) {
      return SolverError(fmt::format("buckling: the string lies buckled already at the case's loads ({}), and {}; "
                                     "lower the WOB to below the onset",
                                     why, what));
    };
    solver_.Forget();  // the equilibria found so far lie buckled
    samples_.clear();
    // The table is the path that finds the onset: the samples from the case's loads lay on the
    // post-buckled branch (the × 1 frequency stays in unloaded_frequency_hz).
    result_.frequency_table.clear();
    result_.buckled_at_case_loads = true;
    if (!Take(start) || samples_.back().eigenvalue <= 0.0) {
      throw fail(fmt::format("no stable equilibrium was found at × {:.3g} of the {}", start,
                             solver_.scale_wob() ? "WOB" : "loads"));
    }
    double below = start;
    for (const double fraction : kBelowMarch) {
      const double multiplier = start + fraction * (top - start);
      const double last = samples_.back().eigenvalue;
      if (!Take(multiplier) || samples_.back().eigenvalue <= 0.0 || samples_.back().eigenvalue > last) {
        // Past the onset: no equilibrium, an unstable one, or one lying buckled and stiffer.
        if (!samples_.empty() && samples_.back().multiplier == multiplier) samples_.pop_back();
        const double estimate = TrendRoot();
        return Approach(below, multiplier, std::isfinite(estimate) && estimate > below ? estimate : multiplier);
      }
      below = multiplier;
      if (std::isfinite(TrendRoot()) && TrendRoot() > below && TrendRoot() < top) break;
    }
    const double estimate = TrendRoot();
    if (!std::isfinite(estimate) || !(estimate > below)) {
      if (ceiling_ <= 1.0) return AtCeiling();  // the model stands up to where the pipe above buckles
      throw fail(fmt::format("the lowest lateral frequency does not fall on the way up from × {:.3g} to × {:.3g}",
                             start, below));
    }
    Approach(below, top, estimate);
  }

  // The onset between `below` (ω² > 0 there) and `above` (a multiplier past it, or ∞), from the
  // first estimate: each step kApproach of the way to it (at most halfway to `above`), each estimate
  // extrapolated through the three samples nearest it.
  void Approach(double below, double above, double estimate) {
    above = std::min(above, ceiling_);
    estimate = std::min(estimate, above);
    // The samples past the onset are no points of the stable branch's ω²(μ).
    std::erase_if(samples_, [](const LateralSample& sample) { return !(sample.eigenvalue > 0.0); });
    for (int taken = 2; taken < kAboutSamples; ++taken) {
      const double target = std::min(below + kApproach * (estimate - below), 0.5 * (below + above));
      const double last_eigenvalue = samples_.back().eigenvalue;  // at `below`
      if (!Take(target) || samples_.back().eigenvalue <= 0.0 || samples_.back().eigenvalue > last_eigenvalue) {
        // Past the onset (no equilibrium, or one that lies buckled and stiffer): the root is below it.
        if (samples_.back().multiplier == target) samples_.pop_back();
        above = target;
        continue;
      }
      below = target;
      const std::vector<std::pair<double, double>> points = Points();
      const double next = points.size() >= 2 ? ExtrapolateRoot(points, estimate) : std::nan("");
      const bool settled = std::abs(next - estimate) <= kAboutTolerance * estimate && next - below < 0.05 * next;
      // The model's own onset lies at or beyond where the pipe above buckles.
      if (std::isfinite(next) && next >= ceiling_ * (1.0 - kAboutTolerance)) return AtCeiling();
      if (std::isfinite(next) && next > below) estimate = std::min(next, above);
      if (settled) {
        result_.frequency_method_converged = true;
        break;
      }
    }
    Finish(estimate);
  }

  // The onset is where the pipe above the model reaches its sinusoidal load (ceiling_), the model
  // standing up to it.
  void AtCeiling() {
    std::erase_if(samples_, [](const LateralSample& sample) { return !(sample.eigenvalue > 0.0); });
    if (samples_.empty()) throw LogicError("buckling: no stable sample below the pipe above's onset");
    result_.onset_above_model = true;
    result_.frequency_method_converged = true;
    Finish(ceiling_);
  }

  // The onset at `multiplier` from the nearest stable sample below it (samples_ ascend in μ, the last
  // one the nearest): its mode, and the compression extrapolated along the nearest two samples
  // (prebuckling is linear).
  void Finish(double multiplier) {
    const LateralSample& near = samples_.back();
    const LateralSample& other = samples_[samples_.size() > 1 ? samples_.size() - 2 : 0];
    const double slope = other.multiplier != near.multiplier
                             ? (near.compression - other.compression) / (near.multiplier - other.multiplier)
                             : 0.0;
    result_.load_factor = result_.frequency_load_factor = multiplier;
    result_.load_factors = {multiplier};
    result_.reference_load_factor = near.multiplier;
    result_.critical_load = result_.frequency_critical_load = near.compression + slope * (multiplier - near.multiplier);
    FillBuckledMode(solver_.ModelAt(near.multiplier), near.q, near.mode, result_);
    std::sort(result_.frequency_table.begin(), result_.frequency_table.end(),
              [](const auto& a, const auto& b) { return a.load_factor < b.load_factor; });
  }

  void LowerBound() {
    const LateralSample& last = samples_.back();
    result_.lower_bound = true;
    result_.load_factor = last.multiplier;
    result_.load_factors = {last.multiplier};
    result_.reference_load_factor = last.multiplier;
    result_.frequency_load_factor = last.multiplier;
    result_.critical_load = result_.frequency_critical_load = last.compression;
    FillBuckledMode(solver_.ModelAt(last.multiplier), last.q, last.mode, result_);
  }

  EquilibriumSolver& solver_;
  BucklingResult& result_;
  const double ceiling_;  // the multiplier at which the pipe above buckles (∞: none)
  std::vector<LateralSample> samples_;
};

// Dawson–Paslay's and Chen's loads along the case's equilibrium q (λ = 1) in a well (header).
SinusoidalBucklingScreen ScreenSinusoidalBuckling(const model::ModelInput& input, const model::BuiltModel& built,
                                                  const VecX& q, bool scale_wob) {
  const model::SystemModel& model = built.system;
  std::vector<StaticNodeResult> nodes = StaticNodeResults(built, q, 1.0);
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
    const double inclination = input.well->trajectory.Inclination(node.md);
    const double clearance = std::max(node.hole_offset + node.clearance, 1e-6);  // r, m
    const double sinusoidal = 2.0 * std::sqrt(body.bending_rigidity * weight * std::sin(inclination) / clearance);
    // Every load × λ: F ∝ λ, F_sin ∝ √λ. The WOB × μ: F grows by (μ − 1) WOB, F_sin stays.
    const double factor = scale_wob ? 1.0 + (sinusoidal - compression) / input.operation.weight_on_bit
                                    : (sinusoidal / compression) * (sinusoidal / compression);
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
  point.compression = MaxCompression(solver.built(), equilibrium.q, load_factor);
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
  const double wob = input.operation.weight_on_bit;
  const bool has_wob = wob != 0.0 && !(input.bit_rock && input.bit_rock->law == model::BitRockLaw::Detournay);
  bool scale_wob = false;
  switch (settings.scale) {
    case BucklingScale::Automatic: scale_wob = has_wob; break;
    case BucklingScale::Wob:
      if (!has_wob) throw LogicError("buckling: scale wob without a weight on bit (the case reader checks it)");
      scale_wob = true;
      break;
    case BucklingScale::AllLoads: break;
  }
  EquilibriumSolver solver(input, built, static_settings, scale_wob);
  BucklingResult result;
  result.scaled_wob = scale_wob;
  // A torque twists the string by radians before it buckles (Greenhill's rod by 2.86 π EI/GJ ≈ 11.7 rad
  // clamped): (a)'s K_T(q_ref) − K_0 then holds the turn of every body's lateral coordinates, not a
  // geometric stiffness, so torque goes the way of (c) too.
  bool torque = input.operation.torque_on_bit != 0.0 && !input.bit_rock;
  for (const model::Load& load : input.loads) torque = torque || load.moment.x() != 0.0 || load.moment_per_length.x() != 0.0;
  if (solver.in_well() || scale_wob || torque) {
    result.about_equilibrium = true;
    if (solver.in_well()) {
      const Equilibrium loaded = solver.At(1.0);
      if (loaded.converged) result.sinusoidal = ScreenSinusoidalBuckling(input, built, loaded.q, scale_wob);
    }
    OnsetSearch(solver, result).FromCaseLoads(result.sinusoidal);
  } else {
    SolveEigenproblem(solver, settings, result);
    if (settings.frequency_method) SolveByFrequencies(solver, settings, result);
  }
  if (has_wob) result.critical_wob = wob * result.load_factor;
  return result;
}

}  // namespace drillflex::analyses
