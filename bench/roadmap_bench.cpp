// Torque and drag at field speed (issue 32): a roadmap point (pick-up, slack-off, rotating off
// bottom and on bottom at one friction factor) of the bundled example at 7 400 ft and of the same
// BHA and pipe at 10 000 ft (bench/cases/ten-thousand-ft.yaml), the case's string stiff and the pipe
// above by the soft string (the default), the 7 400 ft point with the whole string stiff besides, the
// bundled roadmap (10 depths × 3 friction factors on two jobs), the soft-string roadmap, and the
// bundled BHA's static for the ratios
// docs/validation.md quotes. Each point reports its hook loads and torques against the figures
// drillflex gave before the issue (commit 4aebbde, the whole string stiff; `change_*_pct`), so that a speed
// figure comes with the accuracy it was bought at. Never a timed test: Release, one filter at a time,
//   build/bench/roadmap_bench --benchmark_filter=Point7400
// peak_MB is the process's peak resident size so far (getrusage ru_maxrss).
#include <benchmark/benchmark.h>

#include <exception>
#include <limits>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "io/case.hpp"
#include "pipeline/case_run.hpp"
#include "pipeline/roadmap.hpp"
#include "units/units.hpp"

namespace {

using namespace drillflex;
using bench::PeakMemoryMb;
using bench::SourcePath;

// The point drillflex gave before issue 32 (4aebbde, `drillflex roadmap CASE --from MD --friction
// 0.25`): hook loads in lbf, torques in ft·lbf.
struct Reference {
  double pick_up, slack_off, rotating, off_bottom_torque, on_bottom_torque;
};
constexpr Reference kAt7400{144100.8128, 128759.4859, 135728.6958, 2100.415362, 6591.168727};
constexpr Reference kAt10000{197036.8516, 159382.2844, 176403.4482, 5071.886749, 9344.110451};

double Percent(double si, units::Quantity quantity, double field) {
  return 100.0 * (units::FromSI(si, quantity, units::System::Field) / field - 1.0);
}

// `stiff_length` 0: the case's string stiff, the pipe above by the soft string (the default);
// infinity: the whole string stiff, as before issue 32's hybrid.
void Point(benchmark::State& state, const char* case_path, double bit_md_ft, const Reference& reference,
           double stiff_length = 0.0) {
  const io::Case c = io::ReadCase(SourcePath(case_path));
  const double md = units::ToSI(bit_md_ft, units::Quantity::Length, units::System::Field);
  analyses::RoadmapSettings request{md, 0.0, {0.25}};
  request.stiff_length = stiff_length;
  const analyses::RoadmapSettings settings = pipeline::CompleteRoadmapSettings(c, request);
  pipeline::RoadmapPoint point;
  for (auto _ : state) {
    const std::vector<pipeline::RoadmapPoint> points = pipeline::RunRoadmap(c, settings);
    point = points.front();
    if (point.failed()) {
      state.SkipWithError(point.message.c_str());
      break;
    }
  }
  using units::Quantity;
  state.counters["change_pick_up_pct"] = Percent(point.pick_up, Quantity::Force, reference.pick_up);
  state.counters["change_slack_off_pct"] = Percent(point.slack_off, Quantity::Force, reference.slack_off);
  state.counters["change_rotating_pct"] = Percent(point.rotating, Quantity::Force, reference.rotating);
  state.counters["change_off_bottom_torque_pct"] = Percent(point.off_bottom_torque, Quantity::Moment, reference.off_bottom_torque);
  state.counters["change_on_bottom_torque_pct"] = Percent(point.on_bottom_torque, Quantity::Moment, reference.on_bottom_torque);
  state.counters["peak_MB"] = PeakMemoryMb();
}

void BM_Point7400(benchmark::State& state) { Point(state, "examples/rotary-bha-build/case.yaml", 7400.0, kAt7400); }
void BM_Point10000(benchmark::State& state) { Point(state, "bench/cases/ten-thousand-ft.yaml", 10000.0, kAt10000); }
void BM_Point7400WholeStringStiff(benchmark::State& state) {
  Point(state, "examples/rotary-bha-build/case.yaml", 7400.0, kAt7400, std::numeric_limits<double>::infinity());
}

// The bundled roadmap as `drillflex roadmap examples/rotary-bha-build/case.yaml --jobs 2` runs it.
void BM_BundledRoadmap(benchmark::State& state) {
  const io::Case c = io::ReadCase(SourcePath("examples/rotary-bha-build/case.yaml"));
  const analyses::RoadmapSettings settings = pipeline::CompleteRoadmapSettings(c, {});
  int failed = 0;
  for (auto _ : state) {
    pipeline::RoadmapOptions options;
    options.jobs = 2;
    failed = 0;
    for (const pipeline::RoadmapPoint& point : pipeline::RunRoadmap(c, settings, options)) failed += point.failed();
  }
  state.counters["failed_points"] = failed;
  state.counters["peak_MB"] = PeakMemoryMb();
}

void BM_BundledSoftRoadmap(benchmark::State& state) {
  const io::Case c = io::ReadCase(SourcePath("examples/rotary-bha-build/case.yaml"));
  const analyses::RoadmapSettings settings = pipeline::CompleteRoadmapSettings(c, {});
  for (auto _ : state) benchmark::DoNotOptimize(pipeline::RunSoftRoadmap(c, settings).data());
}

// The bundled BHA's static, the unit of the ratios.
void BM_BundledStatic(benchmark::State& state) {
  const io::Case c = io::ReadCase(SourcePath("examples/rotary-bha-build/case.yaml"));
  for (auto _ : state) {
    const pipeline::CaseResults results = pipeline::RunCase(c, pipeline::AnalysisRequest::Only(pipeline::Analysis::Static));
    benchmark::DoNotOptimize(results.static_result->q.data());
  }
}

BENCHMARK(BM_BundledStatic)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_Point7400)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Point10000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Point7400WholeStringStiff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BundledRoadmap)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BundledSoftRoadmap)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
