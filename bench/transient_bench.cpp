// Transient speed: 1 s of free vibration of the V1 cantilever (validation/v8-transient: 4 bodies,
// 72 coordinates, released from its 100 N static tip deflection) at a fixed step of 1e-4 s (10 000
// steps), ρ∞ = 0.8 (the default: the stiff joint modes damped, the first mode at ωh = 1.3e-3
// untouched), the default tolerance 1e-4, samples every 2 ms. Timed: analyses::RunTransient
// only (the start equilibrium is solved once, outside the loop). Goal: 0.2 s at a period error
// within 0.2 % (Exudyn / Chrono take about 1 s for this). Never a timed test: build in Release and
// run by hand,
//   build/bench/transient_bench
// The counters: steps, Newton iterations and factorizations per run, the energy drift, and the
// period of one swing (between the tip's first two downward zero crossings) against 1/f₁
// (f₁ = 2.1434 Hz, Euler–Bernoulli): the release excites higher modes whose beating moves single
// crossings by about ±0.8 %, so this is not the integrator's period error ((ωh)²/12 = 1.5e-7 here;
// the 100-period mean of validation V8 is +0.011 %).
#include <benchmark/benchmark.h>

#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "pipeline/case_run.hpp"

namespace {

using namespace drillflex;

// f₁ = (β₁L)²/(2πL²) sqrt(EI/ρA) of the V1 rod (validation.md V1).
double FirstCantileverFrequency() {
  const double length = 5.08, diameter = 0.0762, youngs = 2.1e11, density = 7800.0;
  const double inertia = kPi * std::pow(diameter, 4) / 64.0, area = kPi * diameter * diameter / 4.0;
  return std::pow(1.8751041, 2) / (2.0 * kPi * length * length) * std::sqrt(youngs * inertia / (density * area));
}

// The period between the first and the last downward zero crossing of the tip (probe 1, z), s.
double TipPeriod(const analyses::TransientResult& result) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < result.samples.size(); ++i) {
    const double before = result.samples[i - 1].probes[0].lateral_z, after = result.samples[i].probes[0].lateral_z;
    if (before > 0.0 && after <= 0.0) {
      const double t0 = result.samples[i - 1].time, t1 = result.samples[i].time;
      crossings.push_back(t0 + (t1 - t0) * before / (before - after));
    }
  }
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

void CantileverFreeVibration(benchmark::State& state) {
  io::Case c = io::ReadCase(std::string(DRILLFLEX_SOURCE_DIR "/validation/v8-transient/free-vibration.yaml"));
  analyses::TransientSettings& settings = *c.analyses.transient;
  settings.duration = 1.0;
  settings.time_step = 1e-4;
  settings.tolerance = 1e-4;
  settings.rho_infinity = 0.8;
  settings.output_interval = 2e-3;
  settings.probes = {5.08};
  analyses::TransientResult result;
  int coordinates = 0;
  try {
    // The transient's model and start as the command line sets them up (pipeline::PrepareTransient).
    pipeline::CaseModel case_model = pipeline::BuildCaseModel(c);
    const pipeline::TransientSetup setup = pipeline::PrepareTransient(c, case_model, nullptr, {});
    coordinates = setup.moving.system.num_velocities();
    for (auto _ : state) {
      result = analyses::RunTransient(setup.moving, setup.start, setup.settings);
      benchmark::DoNotOptimize(result.final_q.data());
    }
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
    return;
  }
  state.counters["coordinates"] = coordinates;
  state.counters["steps"] = static_cast<double>(result.statistics.steps);
  state.counters["newton_iterations"] = static_cast<double>(result.statistics.newton_iterations);
  state.counters["factorizations"] = static_cast<double>(result.statistics.factorizations);
  state.counters["one_swing_period_pct"] = 100.0 * (TipPeriod(result) * FirstCantileverFrequency() - 1.0);
  state.counters["energy_drift"] = result.energy_drift;
}
BENCHMARK(CantileverFreeVibration)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
