// `drillflex sweep CASE --vary KEY=VALUES ... [--cases table.csv] [-o DIR] [--jobs N] [--keep-runs]
// [--resume]`: the case's analyses for every combination (pipeline/sweep_run.hpp), progress on
// standard error, sweep.csv and sweep.json written atomically at the end.
#include <unistd.h>

#include <cstdio>
#include <functional>
#include <iostream>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "pipeline/sweep_mpi.hpp"
#include "pipeline/sweep_run.hpp"

namespace drillflex::app {
namespace {

// "12 / 40 done, 1 failed, about 35 s left": a line redrawn on a terminal, a line every tenth of the
// sweep otherwise (logs of batch jobs).
void ShowProgress(const pipeline::SweepProgress& progress) {
  static const bool terminal = isatty(STDERR_FILENO) == 1;
  const int remaining = progress.total - progress.done;
  const std::string left =
      progress.run_this_call > 0 && remaining > 0
          ? fmt::format(", about {:.0f} s left", progress.elapsed_seconds / progress.run_this_call * remaining)
          : "";
  const std::string line =
      fmt::format("sweep: {} / {} done, {} failed{}", progress.done, progress.total, progress.failed, left);
  if (terminal) {
    std::fprintf(stderr, "\r%s   %s", line.c_str(), remaining == 0 ? "\n" : "");
    std::fflush(stderr);
  } else if (progress.total > 0 && (remaining == 0 || progress.done % std::max(1, progress.total / 10) == 0)) {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

}  // namespace

int RunSweepCommand(const CommandOptions& options) {
  // Under mpirun every rank reads the case and the values alike; rank 0 hands out the runs, prints and
  // writes the table (pipeline/sweep_mpi.hpp).
  const pipeline::SweepMpiSession mpi;
  const bool writer = mpi.rank() == 0;
  const io::Case base = io::ReadCase(options.case_path);
  pipeline::CaseAnalyses(base);  // the case must list analyses to run
  std::vector<pipeline::SweepCombination> combinations;
  if (!options.cases_table.empty()) {
    if (!options.vary.empty()) {
      throw InputError({"--cases", 0, 0}, "", "give either --vary or --cases, not both");
    }
    combinations = pipeline::SweepRowsFromCsv(options.cases_table);
  } else {
    if (options.vary.empty()) throw InputError({"--vary", 0, 0}, "", "nothing to vary: give --vary KEY=VALUES or --cases");
    std::vector<pipeline::SweepAxis> axes;
    for (const std::string& spec : options.vary) axes.push_back(pipeline::ParseSweepAxis(spec));
    combinations = pipeline::SweepCombinations(axes);
  }
  const std::string directory =
      options.output_directory.empty() ? io::DefaultOutputDirectory(base) + "-sweep" : options.output_directory;
  if (writer) {
    std::cout << (mpi.active() ? fmt::format("sweep: {} runs of {} on {} MPI ranks\n", combinations.size(), base.name,
                                             mpi.size())
                               : fmt::format("sweep: {} runs of {} on {} job{}\n", combinations.size(), base.name,
                                             options.jobs, options.jobs == 1 ? "" : "s"));
  }
  pipeline::SweepOptions sweep{directory, options.jobs, options.keep_runs, options.resume,
                               writer ? ShowProgress : std::function<void(const pipeline::SweepProgress&)>{}};
  std::vector<pipeline::SweepRow> rows;
  try {
    rows = mpi.active() ? pipeline::RunSweepOverRanks(base, combinations, sweep, mpi)
                        : pipeline::RunSweep(base, combinations, sweep);
  } catch (const std::exception& error) {
    if (!mpi.active()) throw;
    // The other ranks wait on this one: end them all, saying why.
    std::cerr << fmt::format("drillflex: sweep: rank {}: error: {}\n", mpi.rank(), error.what());
    mpi.Abort(kExitFailure);
  }
  if (!writer) return kExitOk;
  pipeline::ComposeSweepFiles(base, rows, directory).Commit();
  int failed = 0;
  for (const pipeline::SweepRow& row : rows) failed += row.outcome.converged ? 0 : 1;
  std::cout << fmt::format("sweep: {} runs, {} failed; results in {}/sweep.csv\n", rows.size(), failed, directory);
  return kExitOk;
}

}  // namespace drillflex::app
