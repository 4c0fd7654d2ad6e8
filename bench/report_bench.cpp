// The cost of the engineer's files on the bundled example's static run (issue 20: under 0.1 s):
// results.json and the CSV tables as every job writes them, and on top report.html
// and the VTK files, composed (pipeline::ComposeResultFiles, as the command line does) and
// written to disk (ResultFiles::Commit: temporary file and rename). The static solve is done once,
// outside the timed loop. Never a timed test: build in Release and run by hand,
//   DRILLFLEX_TARGETS=report_bench scripts/build && build/bench/report_bench
// Counters: report_MB, vtk_MB (the files' sizes), and solve_s (the static solve, for scale).
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "io/case.hpp"
#include "pipeline/case_files.hpp"
#include "pipeline/case_run.hpp"

namespace {

using namespace drillflex;

struct Solved {
  Solved() : c(io::ReadCase(std::string(DRILLFLEX_SOURCE_DIR "/examples/rotary-bha-build/case.yaml"))) {
    const auto start = std::chrono::steady_clock::now();
    results.emplace(pipeline::RunCase(c, pipeline::AnalysisRequest::Only(pipeline::Analysis::Static)));
    solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  io::Case c;
  std::optional<pipeline::CaseResults> results;
  double solve_seconds = 0.0;
};

const Solved& BundledExample() {
  static const Solved solved;
  return solved;
}

// Composes and writes the files of a `drillflex static` job; with_report adds report.html and VTK.
void WriteFiles(benchmark::State& state, bool with_report) {
  const Solved& s = BundledExample();
  const std::string directory = (std::filesystem::temp_directory_path() / "drillflex-report-bench").string();
  double report_bytes = 0.0, vtk_bytes = 0.0;
  for (auto _ : state) {
    pipeline::ComposeResultFiles(s.c, *s.results, {directory, with_report, with_report, "static", s.solve_seconds})
        .Commit();
  }
  if (with_report) {
    namespace fs = std::filesystem;
    report_bytes = static_cast<double>(fs::file_size(fs::path(directory) / "report.html"));
    for (const char* name : {"string.vtp", "well.vtp", "contacts.vtp"}) {
      vtk_bytes += static_cast<double>(fs::file_size(fs::path(directory) / name));
    }
  }
  state.counters["report_MB"] = report_bytes / 1e6;
  state.counters["vtk_MB"] = vtk_bytes / 1e6;
  state.counters["solve_s"] = s.solve_seconds;
}

void ResultsOnly(benchmark::State& state) { WriteFiles(state, false); }
void ResultsReportAndVtk(benchmark::State& state) { WriteFiles(state, true); }

BENCHMARK(ResultsOnly)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(ResultsReportAndVtk)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
