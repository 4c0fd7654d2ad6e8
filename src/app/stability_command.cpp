// `drillflex stability CASE --rpm VALUES --wob VALUES [-o DIR] [--jobs N] [--resume] [--keep-runs]
// [--no-report]`: the stability map (pipeline/stability_map.hpp), on this machine or over MPI ranks
// like a sweep; sweep.csv, sweep.json and report.html (the map) written atomically at the end.
#include <chrono>
#include <iostream>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "app/sweep_runs.hpp"
#include "pipeline/stability_map.hpp"

namespace drillflex::app {

int RunStabilityCommand(const CommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const pipeline::SweepMpiSession mpi;
  const io::Case base = io::ReadCase(options.case_path);
  const std::vector<pipeline::SweepCombination> combinations =
      pipeline::StabilityCombinations(base, options.stability_rpm_values, options.stability_wob_values);
  const std::string directory =
      options.output_directory.empty() ? io::DefaultOutputDirectory(base) + "-stability" : options.output_directory;
  const auto rows = RunCombinations(options, mpi, base, combinations, directory, "stability");
  if (!rows) return kExitOk;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool report = base.output.report && !options.no_report;
  pipeline::ComposeStabilityFiles(base, *rows, directory, report, seconds).Commit();
  std::cout << fmt::format("stability: {} runs, {} failed; results in {}/sweep.csv{}\n", rows->size(),
                           CountFailed(*rows), directory,
                           report ? fmt::format(", the map in {}/report.html", directory) : "");
  return kExitOk;
}

}  // namespace drillflex::app
