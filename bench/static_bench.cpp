// Static analysis of a string in a well, end to end through the pipeline as `drillflex static`
// runs it (pipeline/case_run.hpp): io::ReadCase, then pipeline::RunCase (the model input, the model
// with a fresh reduction cache, analyses::RunStaticInWell), without writing files. Never a timed test: build in
// Release and run by hand, one filter at a time to attribute the peak memory,
//   build/bench/static_bench --benchmark_filter=Example
// Goals: the bundled example (examples/rotary-bha-build, 104 bodies) under 0.5 s; 3 km of string
// in a 3-D well (bench/cases/three-km-3d.yaml: the example's BHA below 2.9 km of 5 in drill pipe
// with tool joints, 965 bodies, 17 370 coordinates) under 5 s: on bottom before the rotary starts
// (three-km-3d-not-rotating.yaml) and rotating at 120 rpm (three-km-3d.yaml). peak_MB is the process's peak
// resident size so far (getrusage ru_maxrss).
#include <benchmark/benchmark.h>

#include <exception>
#include <string>
#include <utility>

#include "bench_support.hpp"
#include "io/case.hpp"
#include "pipeline/case_run.hpp"

namespace {

using namespace drillflex;
using bench::PeakMemoryMb;
using bench::SourcePath;

// Read, build and solve one case, as the command line does (without writing files).
analyses::StaticResult SolveCase(const std::string& path, int& bodies, int& coordinates) {
  const io::Case c = io::ReadCase(path);
  pipeline::CaseResults results = pipeline::RunCase(c, pipeline::AnalysisRequest::Only(pipeline::Analysis::Static));
  bodies = static_cast<int>(results.model.built.system.bodies().size());
  coordinates = results.model.built.system.num_velocities();
  return std::move(*results.static_result);
}

void EndToEnd(benchmark::State& state, const std::string& path) {
  analyses::StaticResult result;
  int bodies = 0, coordinates = 0;
  double bit_side_force = 0.0;
  for (auto _ : state) {
    try {
      result = SolveCase(path, bodies, coordinates);
    } catch (const std::exception& error) {
      state.SkipWithError(error.what());
      break;
    }
    benchmark::DoNotOptimize(result.q.data());
    bit_side_force = result.bit ? result.bit->side_force : 0.0;
  }
  state.counters["bodies"] = bodies;
  state.counters["coordinates"] = coordinates;
  state.counters["newton_iterations"] = result.iterations;
  state.counters["load_steps"] = result.load_steps;
  state.counters["contacts_loaded"] = static_cast<double>(result.contacts.size());
  state.counters["bit_side_force_N"] = bit_side_force;
  state.counters["peak_MB"] = PeakMemoryMb();
}

// The model alone (read, reduce, assemble the system), to separate it from the solve.
void BuildOnly(benchmark::State& state, const std::string& path) {
  int coordinates = 0;
  for (auto _ : state) {
    const pipeline::CaseModel case_model = pipeline::BuildCaseModel(io::ReadCase(path));
    coordinates = case_model.built.system.num_velocities();
    benchmark::DoNotOptimize(coordinates);
  }
  state.counters["coordinates"] = coordinates;
  state.counters["peak_MB"] = PeakMemoryMb();
}

void BM_Example_Static(benchmark::State& state) { EndToEnd(state, SourcePath("examples/rotary-bha-build/case.yaml")); }
void BM_Example_Build(benchmark::State& state) { BuildOnly(state, SourcePath("examples/rotary-bha-build/case.yaml")); }
void BM_ThreeKm3D_Static(benchmark::State& state) { EndToEnd(state, SourcePath("bench/cases/three-km-3d.yaml")); }
void BM_ThreeKm3DNotRotating_Static(benchmark::State& state) {
  EndToEnd(state, SourcePath("bench/cases/three-km-3d-not-rotating.yaml"));
}
void BM_ThreeKm3D_Build(benchmark::State& state) { BuildOnly(state, SourcePath("bench/cases/three-km-3d.yaml")); }

BENCHMARK(BM_Example_Build)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Example_Static)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_ThreeKm3D_Build)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_ThreeKm3DNotRotating_Static)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_ThreeKm3D_Static)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
