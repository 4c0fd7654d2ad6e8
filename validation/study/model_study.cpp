// drillflex_model_study: the model study of validation.md V1 (docs/model-study.md).
// The V1 cantilever through model::BuildSystemModel, errors of the first four bending frequencies
// and three static tip deflections against Euler–Bernoulli theory as the number of bodies, elements
// per body, fixed-interface modes per body and the coupling factor vary; the highest natural
// frequency of the coupled model (explicit step limit 2/ω_max) against the coupling factor; the
// FE mass (consistent or lumped) and bending rotary inertia. Prints Markdown; --svg writes a plot.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "model/builder.hpp"
#include "study_model.hpp"
#include "svg_chart.hpp"

namespace drillflex::study {
namespace {

struct SweepPoint {
  std::string label;
  ModelConfig config;
  Measurement result;
};

// The paper's model (4 bodies × 10 elements × 12 flexible coordinates) at the default coupling factor.
ModelConfig PaperModel() { return ModelConfig{}; }
const double kDefaultCoupling = PaperModel().coupling_factor;

// Measures `base` with one parameter set to each of `values` by `set`.
template <typename T>
std::vector<SweepPoint> Sweep(const ModelConfig& base, const std::vector<T>& values,
                              const std::function<void(ModelConfig&, T)>& set, cms::ReductionCache& cache) {
  std::vector<SweepPoint> points;
  for (const T& value : values) {
    SweepPoint point{fmt::format("{:g}", static_cast<double>(value)), base, {}};
    set(point.config, value);
    point.result = Measure(point.config, cache);
    points.push_back(point);
  }
  return points;
}

// A relative error as a signed percentage with three significant digits.
std::string Percent(double relative) { return fmt::format("{:+#.3g}", 100.0 * relative); }

void PrintErrorTable(const std::string& title, const std::string& parameter, const std::vector<SweepPoint>& points) {
  fmt::print("\n### {}\n\n", title);
  fmt::print("| {} | coordinates | f₁ | f₂ | f₃ | f₄ | tip force | uniform load | tip moment |\n", parameter);
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const SweepPoint& p : points) {
    const Measurement& m = p.result;
    fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", p.label, m.coordinates,
               Percent(m.frequency_error[0]), Percent(m.frequency_error[1]), Percent(m.frequency_error[2]),
               Percent(m.frequency_error[3]), Percent(m.static_error[kTipForce]),
               Percent(m.static_error[kUniformLoad]), Percent(m.static_error[kTipMoment]));
  }
  for (const SweepPoint& p : points) {
    if (p.result.plane_split > 1e-7) {
      fmt::print("\n{} = {}: the x-y and x-z bending frequencies differ by up to {:.3g} % (a y/z pair of "
                 "fixed-interface modes is cut); the table gives the larger |error|.\n",
                 parameter, p.label, 100.0 * p.result.plane_split);
    }
  }
}

void PrintTimeStepTable(const std::vector<SweepPoint>& points) {
  fmt::print("\n### (b) Highest natural frequency and stable explicit step against the coupling factor c\n\n");
  fmt::print("4 bodies × 10 elements × 6 modes. Δt_crit = 2/ω_max (central differences, undamped); ");
  fmt::print("clamped: the V1 cantilever (its clamp is {:g}× stiffer than a coupling); free: the same string ",
             model::kSupportStiffnessFactor);
  fmt::print("without the clamp (couplings only). One free-free body alone (c-independent): ω_max = {:.4g} rad/s.\n\n",
             points.front().result.body_omega_max);
  fmt::print("| c | max \\|f error\\| % | max \\|static error\\| % | ω_max clamped (rad/s) | Δt_crit clamped (s) "
             "| ω_max free (rad/s) | Δt_crit free (s) |\n");
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const SweepPoint& p : points) {
    const Measurement& m = p.result;
    fmt::print("| {} | {:#.3g} | {:#.3g} | {:.4g} | {:.3e} | {:.4g} | {:.3e} |\n", p.label, 100.0 * m.MaxFrequencyError(),
               100.0 * m.MaxStaticError(), m.omega_max, m.CriticalTimeStep(), m.omega_max_free, m.CriticalTimeStepFree());
  }
}

void PrintMassTable(cms::ReductionCache& cache) {
  fmt::print("\n### (c) FE mass and bending rotary inertia (4 × 10 × 6, c = {:g}; errors against Euler–Bernoulli)\n\n",
             kDefaultCoupling);
  fmt::print("| FE mass | rotary inertia ρI | f₁ | f₂ | f₃ | f₄ | ω_max (rad/s) | Δt_crit (s) |\n");
  fmt::print("|---|---|---:|---:|---:|---:|---:|---:|\n");
  std::array<double, kFrequencyCount> consistent_shift{};  // ρI on − off, consistent mass
  for (const bool rotary : {false, true}) {
    for (const fe::MassKind mass : {fe::MassKind::kConsistent, fe::MassKind::kLumped}) {
      ModelConfig config = PaperModel();
      config.mass = mass;
      config.rotary_inertia = rotary;
      const Measurement m = Measure(config, cache);
      fmt::print("| {} | {} | {} | {} | {} | {} | {:.4g} | {:.3e} |\n",
                 mass == fe::MassKind::kConsistent ? "consistent" : "lumped", rotary ? "on" : "off",
                 Percent(m.frequency_error[0]), Percent(m.frequency_error[1]), Percent(m.frequency_error[2]),
                 Percent(m.frequency_error[3]), m.omega_max, m.CriticalTimeStep());
      if (mass == fe::MassKind::kConsistent) {
        for (int n = 0; n < kFrequencyCount; ++n) consistent_shift[n] += (rotary ? 1.0 : -1.0) * m.frequency_error[n];
      }
    }
  }
  fmt::print("\nShift by ρI (consistent mass, on − off), %: ");
  for (int n = 0; n < kFrequencyCount; ++n) fmt::print("{}{:+.5f}", n ? ", " : "", 100.0 * consistent_shift[n]);
  fmt::print("; Rayleigh beam (first order): ");
  for (int n = 0; n < kFrequencyCount; ++n) fmt::print("{}{:+.5f}", n ? ", " : "", 100.0 * RotaryInertiaShift(n));
  fmt::print(".\n");
}

// The model's own nonlinearity under a moderate end moment, against the exact elastica.
void PrintMomentArcTable(cms::ReductionCache& cache) {
  const double rotations[2] = {0.002, 0.02};  // tip deflection L/1000 and L/100
  fmt::print("\n### (d) Moderate deflection: tip moment M = EIφ/L against the exact elastica (a circular arc)\n\n");
  fmt::print("10 elements × 6 modes per body, c = {:g}. The elastica differs from linear theory by ", kDefaultCoupling);
  fmt::print("1 − (1 − cos φ)/(φ²/2) ≈ φ²/12: {:.2g} % at φ = {:g}, {:.2g} % at φ = {:g}.\n\n",
             100.0 * rotations[0] * rotations[0] / 12.0, rotations[0], 100.0 * rotations[1] * rotations[1] / 12.0,
             rotations[1]);
  fmt::print("| bodies | φ = {0:g} vs linear | φ = {0:g} vs elastica | φ = {1:g} vs linear | φ = {1:g} vs elastica |\n",
             rotations[0], rotations[1]);
  fmt::print("|---:|---:|---:|---:|---:|\n");
  for (const int bodies : {1, 2, 4, 8, 16}) {
    ModelConfig config = PaperModel();
    config.bodies = bodies;
    const MomentArcErrors small = MomentArcError(config, rotations[0], cache);
    const MomentArcErrors moderate = MomentArcError(config, rotations[1], cache);
    fmt::print("| {} | {} | {} | {} | {} |\n", bodies, Percent(small.linear), Percent(small.elastica),
               Percent(moderate.linear), Percent(moderate.elastica));
  }
}

// Frequency and static error (top) and the stable explicit step (bottom) against c.
Chart CouplingChart(const std::vector<SweepPoint>& points) {
  ChartSeries first{"|error| f₁", "#1f77b4", {}, {}};
  ChartSeries fourth{"|error| f₄", "#17becf", {}, {}};
  ChartSeries statics{"max |error| static", "#d62728", {}, {}};
  ChartSeries goal{"V1 goal 0.05 %", "#888888", {}, {}, true};
  ChartSeries clamped{"clamped (V1)", "#2ca02c", {}, {}};
  ChartSeries free{"free (couplings only)", "#9467bd", {}, {}};
  for (const SweepPoint& p : points) {
    const double c = p.config.coupling_factor;
    for (ChartSeries* s : {&first, &fourth, &statics, &goal, &clamped, &free}) s->x.push_back(c);
    first.y.push_back(100.0 * std::abs(p.result.frequency_error[0]));
    fourth.y.push_back(100.0 * std::abs(p.result.frequency_error[3]));
    statics.y.push_back(100.0 * p.result.MaxStaticError());
    goal.y.push_back(0.05);
    clamped.y.push_back(p.result.CriticalTimeStep());
    free.y.push_back(p.result.CriticalTimeStepFree());
  }
  Chart chart;
  chart.title = "V1 cantilever, 4 bodies × 10 elements × 6 modes: coupling factor c";
  chart.x_label = "coupling factor c";
  chart.panels = {{"error vs Euler–Bernoulli (%)", {first, fourth, statics, goal}},
                  {"explicit step 2/ω_max (s)", {clamped, free}}};
  chart.markers = {{kDefaultCoupling, fmt::format("default c = {:g}", kDefaultCoupling)}};
  return chart;
}

// Runs every study and prints it as Markdown.
std::vector<SweepPoint> RunStudies(cms::ReductionCache& cache) {
  const ModelConfig base = PaperModel();
  fmt::print("## V1 cantilever: errors in % against Euler–Bernoulli theory (rotary inertia off)\n\n");
  fmt::print("Exact: f = {:.4f}, {:.3f}, {:.3f}, {:.3f} Hz; static loads sized for a tip deflection of {:g} L.\n",
             ExactFrequencyHz(0), ExactFrequencyHz(1), ExactFrequencyHz(2), ExactFrequencyHz(3), kStaticDeflectionRatio);
  const std::string c = fmt::format("c = {:g}", kDefaultCoupling);
  PrintErrorTable(fmt::format("(a1) Number of bodies (10 elements, 6 modes per body, {})", c), "bodies",
                  Sweep<int>(base, {1, 2, 4, 8, 16}, [](ModelConfig& m, int n) { m.bodies = n; }, cache));
  PrintErrorTable(fmt::format("(a2) Elements per body (4 bodies, 6 modes, {})", c), "elements",
                  Sweep<int>(base, {2, 4, 6, 10, 20}, [](ModelConfig& m, int n) { m.elements_per_body = n; }, cache));
  PrintErrorTable(fmt::format("(a3) Fixed-interface modes per body (4 bodies × 10 elements, {})", c), "modes",
                  Sweep<int>(base, {0, 2, 4, 6, 8, 12}, [](ModelConfig& m, int n) { m.modes_per_body = n; }, cache));
  const auto coupling = Sweep<double>(base, {10, 30, 100, 300, 1000, 3000, 1e4, 1e5},
                                      [](ModelConfig& m, double f) { m.coupling_factor = f; }, cache);
  PrintErrorTable("(a4) Coupling factor c (4 bodies × 10 elements × 6 modes)", "c", coupling);
  PrintTimeStepTable(coupling);
  PrintMassTable(cache);
  PrintMomentArcTable(cache);
  return coupling;
}

}  // namespace
}  // namespace drillflex::study

int main(int argc, char** argv) {
  using namespace drillflex::study;
  CLI::App app{"drillflex model study: V1 cantilever accuracy and stable time step (docs/model-study.md)"};
  std::string svg_path;
  app.add_option("--svg", svg_path, "write the coupling-factor plot (SVG) to this file");
  CLI11_PARSE(app, argc, argv);

  const auto start = std::chrono::steady_clock::now();
  try {
    drillflex::cms::ReductionCache cache;
    const std::vector<SweepPoint> coupling = RunStudies(cache);
    if (!svg_path.empty()) {
      std::ofstream file(svg_path);
      file << RenderSvg(CouplingChart(coupling));
      if (!file) throw std::runtime_error("cannot write " + svg_path);
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "drillflex_model_study: %s\n", error.what());
    return 1;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "model study: %.1f s\n", seconds);
  return 0;
}
