// `drillflex sweep CASE --vary KEY=VALUES ... [--cases table.csv] [-o DIR] [--jobs N] [--keep-runs]
// [--resume]`: the case's analyses for every combination (pipeline/sweep_run.hpp), progress on
// standard error, sweep.csv and sweep.json written atomically at the end.
#include <functional>
#include <iostream>

#include <fmt/format.h>

#include "app/batch_progress.hpp"
#include "app/commands.hpp"
#include "app/sweep_runs.hpp"
#include "core/error.hpp"
#include "pipeline/sweep_mpi.hpp"
#include "pipeline/sweep_run.hpp"

namespace drillflex::app {
namespace {

// The time left from the runs this call made (the resumed ones took none of it).
void ShowProgress(const char* what, const pipeline::SweepProgress& progress) {
  const int remaining = progress.total - progress.done;
  ShowBatchProgress(what, progress.done, progress.total, progress.failed,
                    progress.run_this_call > 0 ? progress.elapsed_seconds / progress.run_this_call * remaining : -1.0);
}

}  // namespace

std::optional<std::vector<pipeline::SweepRow>> RunCombinations(const CommandOptions& options,
                                                               const pipeline::SweepMpiSession& mpi,
                                                               const io::Case& base,
                                                               const std::vector<pipeline::SweepCombination>& combinations,
                                                               const std::string& directory, const char* what) {
  const bool writer = mpi.rank() == 0;
  if (writer) {
    std::cout << (mpi.active() ? fmt::format("{}: {} runs of {} on {} MPI ranks\n", what, combinations.size(),
                                             base.name, mpi.size())
                               : fmt::format("{}: {} runs of {} on {} job{}\n", what, combinations.size(), base.name,
                                             options.jobs, options.jobs == 1 ? "" : "s"));
  }
  std::function<void(const pipeline::SweepProgress&)> progress;
  if (writer) progress = [what](const pipeline::SweepProgress& done) { ShowProgress(what, done); };
  const pipeline::SweepOptions sweep{directory, options.jobs, options.keep_runs, options.resume, progress};
  std::vector<pipeline::SweepRow> rows;
  try {
    rows = mpi.active() ? pipeline::RunSweepOverRanks(base, combinations, sweep, mpi)
                        : pipeline::RunSweep(base, combinations, sweep);
  } catch (const std::exception& error) {
    if (!mpi.active()) throw;
    // The other ranks wait on this one: end them all, saying why.
    std::cerr << fmt::format("drillflex: {}: rank {}: error: {}\n", what, mpi.rank(), error.what());
    mpi.Abort(kExitFailure);
  }
  if (!writer) return std::nullopt;
  return rows;
}

int CountFailed(const std::vector<pipeline::SweepRow>& rows) {
  int failed = 0;
  for (const pipeline::SweepRow& row : rows) failed += row.outcome.converged ? 0 : 1;
  return failed;
}

int RunSweepCommand(const CommandOptions& options) {
  // Under mpirun every rank reads the case and the values alike; rank 0 hands out the runs, prints and
  // writes the table (pipeline/sweep_mpi.hpp).
  const pipeline::SweepMpiSession mpi;
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
  const auto rows = RunCombinations(options, mpi, base, combinations, directory, "sweep");
  if (!rows) return kExitOk;
  pipeline::ComposeSweepFiles(base, *rows, directory).Commit();
  std::cout << fmt::format("sweep: {} runs, {} failed; results in {}/sweep.csv\n", rows->size(), CountFailed(*rows),
                           directory);
  return kExitOk;
}

}  // namespace drillflex::app
