// Forced response against RPM (analyses/vibration_analysis.hpp), the sweep alone about the static
// equilibrium, which is solved once before the timed loop (pipeline::RunCaseStatic and
// pipeline::RunCaseVibration, the stages `drillflex vibration` chains). Never a timed test: build in Release and run by hand,
//   build/bench/vibration_bench --benchmark_filter=Example
// The sweep of the issue: 231 RPM values (20–250 rpm, step 1) with three excitations: an imbalance
// (0.02 kg·m at 40 ft, 1×), the bit (500 lbf lateral, 1000 lbf axial, 3×) and a mud motor (5 lobes,
// rotor at 150 rpm, 200 lbf at 20 ft: a fixed frequency, solved once). Goals: the bundled example
// (examples/rotary-bha-build, 1872 coordinates) under 1 s; 3 km of string under 10 s, about the
// equilibrium of bench/cases/three-km-3d-not-rotating.yaml (17 370 coordinates; the rotating case's
// static solve converges since 2026-12-03, the sweep keeps the case its figures were measured on).
// The fluid of both cases is
// viscous (frequency-dependent annulus). The default
// method is the reduced sweep (solvers/projected_harmonic.hpp); BM_Example_Sweep_Direct times the
// full sparse solve at every frequency on the same case. OMP_NUM_THREADS sets the threads.
#include <benchmark/benchmark.h>

#include <exception>
#include <string>

#include "bench_support.hpp"
#include "io/case.hpp"
#include "pipeline/case_run.hpp"
#include "vibration_sweep.hpp"

namespace {

using namespace drillflex;
using bench::PeakMemoryMb;
using bench::SourcePath;

void Sweep(benchmark::State& state, const std::string& path, bool static_equilibrium,
           analyses::VibrationMethod method = analyses::VibrationMethod::Reduced) {
  const io::Case c = io::ReadCase(path);
  pipeline::CaseModel case_model = pipeline::BuildCaseModel(c);
  const model::BuiltModel& built = case_model.built;
  VecX q = built.system.ReferencePositions();
  if (static_equilibrium) {
    try {
      q = pipeline::RunCaseStatic(c, case_model).q;
    } catch (const std::exception& error) {
      state.SkipWithError(error.what());
      return;
    }
  }
  const analyses::VibrationSettings settings = bench::ThreeExcitationSweep(method);
  analyses::VibrationResult result;
  for (auto _ : state) {
    result = pipeline::RunCaseVibration(c, case_model, q, settings);
    benchmark::DoNotOptimize(result.rotary_speeds.data());
  }
  state.counters["coordinates"] = built.system.num_velocities();
  state.counters["rpm_values"] = static_cast<double>(result.rotary_speeds.size());
  state.counters["closed_contacts"] = result.closed_contacts;
  state.counters["critical_rpms"] = static_cast<double>(result.critical_rotary_speeds.size());
  state.counters["peak_MB"] = PeakMemoryMb();
  state.counters["basis_size"] = result.basis_size;
  state.counters["check_error"] = result.reduced_check_error;
  state.counters["band_modes"] = result.band_modes;
  state.counters["reduced"] = result.method == analyses::VibrationMethod::Reduced ? 1.0 : 0.0;
}

void BM_Example_Sweep(benchmark::State& state) { Sweep(state, SourcePath("examples/rotary-bha-build/case.yaml"), true); }
void BM_ThreeKm3D_Sweep(benchmark::State& state) {
  Sweep(state, SourcePath("bench/cases/three-km-3d-not-rotating.yaml"), true);
}

// The reference: a sparse LU of the full system at every frequency (analyses.vibration.method: direct).
void BM_Example_Sweep_Direct(benchmark::State& state) {
  Sweep(state, SourcePath("examples/rotary-bha-build/case.yaml"), true, analyses::VibrationMethod::Direct);
}

BENCHMARK(BM_Example_Sweep)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Example_Sweep_Direct)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ThreeKm3D_Sweep)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
