// Transient speed on the bundled example: bench/cases/rotary-bha-rotating.yaml (the example's
// well, string and model: 104 bodies, 1876 coordinates, 1013 wall contacts), turned from its static
// equilibrium on bottom to 120 rpm by the top drive (ramp 2 s) under the case's WOB and TOB, for
// 10 s of simulated time at the default adaptive steps (tolerance 1e-4, ρ∞ = 0.8). Timed:
// analyses::RunTransient only (the start equilibrium is solved once, outside the loop), on 1 and 2
// OpenMP threads; with `limits` 1, the string's limits read at every output sample as `drillflex transient`
// reads them (analyses::LimitsRecorder, issue 37), their own time counted apart (limits_s). Goal (issue 6):
// at least real time on 2 cores. Never a timed test: build in
// Release and run by hand,
//   build/bench/rotary_transient_bench
//   DRILLFLEX_BENCH_DURATION=0.5 build/bench/rotary_transient_bench   (a shorter run, s)
// Counters: the real-time factor (simulated over wall time; ≥ 1 is faster than real time), the
// process CPU time over all threads (the machine is shared: wall time alone says little), steps,
// rejected steps, Newton iterations, factorizations, residual evaluations, and the end state (bit
// rpm, WOB) so that a faster run that changed the answer shows.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <optional>
#include <string>

#include "io/case.hpp"
#include "pipeline/case_run.hpp"

namespace {

using namespace drillflex;

double BenchDuration() {
  const char* text = std::getenv("DRILLFLEX_BENCH_DURATION");
  return text ? std::atof(text) : 10.0;
}

void RotatingBundledExample(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  const bool read_limits = state.range(1) != 0;
  const int previous_threads = omp_get_max_threads();
  omp_set_num_threads(threads);
  io::Case c = io::ReadCase(std::string(DRILLFLEX_SOURCE_DIR "/bench/cases/rotary-bha-rotating.yaml"));
  c.analyses.transient->duration = BenchDuration();
  analyses::TransientResult result;
  double wall = 0.0, cpu = 0.0, limits_wall = 0.0;
  try {
    // As the command line does (pipeline::PrepareTransient): the start equilibrium on the case's model
    // at rest, the run on the model with the drives, carrying the drilling fluid
    // (model/fluid_inertia.hpp), its annulus terms at the default frequency
    // (analyses::TransientFluidFrequency: the lowest lateral mode at the start).
    pipeline::CaseModel case_model = pipeline::BuildCaseModel(c);
    const pipeline::TransientSetup setup = pipeline::PrepareTransient(c, case_model, nullptr, {});
    state.counters["fluid_hz"] = setup.fluid_frequency / (2.0 * kPi);
    for (auto _ : state) {
      std::optional<analyses::LimitsRecorder> limits;
      analyses::TransientSampleObserver observer;
      if (read_limits) {
        limits.emplace(c.input, setup.moving, c.limits.design_factor);
        observer = [&limits, &limits_wall](double time, const VecX& q, const VecX&) {
          const auto start = std::chrono::steady_clock::now();
          limits->Read(time, q);
          limits_wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        };
      }
      const std::clock_t cpu_start = std::clock();  // the process's CPU time, all threads
      const auto wall_start = std::chrono::steady_clock::now();
      result = analyses::RunTransient(setup.moving, setup.start, setup.settings, {}, observer);
      wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      cpu += static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
      benchmark::DoNotOptimize(result.final_q.data());
    }
  } catch (const std::exception& error) {
    omp_set_num_threads(previous_threads);
    state.SkipWithError(error.what());
    return;
  }
  omp_set_num_threads(previous_threads);
  const double runs = static_cast<double>(state.iterations());
  const auto& stats = result.statistics;
  state.counters["threads"] = threads;
  const double duration = c.analyses.transient->duration;
  state.counters["simulated_s"] = duration;
  state.counters["wall_s"] = wall / runs;
  state.counters["limits_s"] = limits_wall / runs;
  state.counters["samples"] = static_cast<double>(result.samples.size());
  state.counters["cpu_s"] = cpu / runs;
  state.counters["real_time_factor"] = duration * runs / wall;
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["rejected"] = static_cast<double>(stats.error_rejections + stats.newton_failures);
  state.counters["newton_iterations"] = static_cast<double>(stats.newton_iterations);
  state.counters["factorizations"] = static_cast<double>(stats.factorizations);
  state.counters["residuals"] = static_cast<double>(stats.residual_evaluations);
  state.counters["bit_rpm"] = result.samples.back().bit_speed * 30.0 / kPi;
  state.counters["wob_klbf"] = result.samples.back().weight_on_bit / 4448.2216152605;
}
BENCHMARK(RotatingBundledExample)
    ->ArgsProduct({{1, 2}, {0, 1}})
    ->ArgNames({"threads", "limits"})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
