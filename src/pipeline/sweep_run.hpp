// A sweep: one case run once for each combination of values (pipeline/sweep_plan.hpp), each run
// through RunCase with the analyses the case lists, in parallel on one machine (--jobs). A run that
// fails is a row with its message, never the end of the sweep; every finished row is journalled, so
// an interrupted sweep resumes where it stopped.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/case.hpp"
#include "io/result_files.hpp"
#include "pipeline/sweep_outcome.hpp"
#include "pipeline/sweep_plan.hpp"

namespace drillflex::pipeline {

struct SweepRow {
  int index = 0;  // 0-based, in combination order (the CSV's `run` column counts from 1)
  SweepCombination values;
  SweepOutcome outcome;
};

struct SweepProgress {
  int done = 0;      // rows finished, resumed ones included
  int total = 0;
  int failed = 0;
  double elapsed_seconds = 0.0;  // since this call started
  int run_this_call = 0;         // rows finished by this call (the time left is estimated from them)
};

struct SweepOptions {
  std::string directory;   // where sweep.csv, sweep.json, the journal and runs/ go
  int jobs = 1;            // runs at once on this machine (threads, each with its share of the cores)
  bool keep_runs = false;  // each run's own result files under DIRECTORY/runs/NNNN/
  bool resume = false;     // take the rows the journal holds instead of running them again
  std::function<void(const SweepProgress&)> progress;
};

// The journal of finished rows: one JSON object a line, SI, doubles to the last bit.
inline constexpr const char* kSweepJournal = "sweep-journal.jsonl";

// One run: the base case with `values` set (io::WithValues), its analyses run, its headline taken;
// any InputError or SolverError becomes the row's message. With keep_runs its own files are written
// under `runs_directory`/NNNN (NNNN = index + 1).
SweepRow RunSweepCase(const io::Case& base, int index, const SweepCombination& values, bool keep_runs,
                      const std::string& runs_directory);

// What every way of running a sweep shares: the rows resumed from the journal, the runs still to do,
// the journal of the rows as they finish, the progress. Record() may be called from any thread.
class SweepLedger {
 public:
  // Reads the journal with options.resume (InputError when it is another sweep's), else clears it.
  SweepLedger(const std::vector<SweepCombination>& combinations, const SweepOptions& options);
  ~SweepLedger();
  SweepLedger(const SweepLedger&) = delete;
  SweepLedger& operator=(const SweepLedger&) = delete;

  const std::vector<int>& pending() const { return pending_; }
  void Record(SweepRow row);
  std::vector<SweepRow> TakeRows();

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::vector<int> pending_;
};

// Runs every combination (skipping the journal's rows with `resume`) on options.jobs threads;
// returns the rows in combination order. Throws InputError when a journal to resume from belongs to
// another sweep (other keys or values at an index).
std::vector<SweepRow> RunSweep(const io::Case& base, const std::vector<SweepCombination>& combinations,
                               const SweepOptions& options);

// The OpenMP threads this process may use (OMP_NUM_THREADS, else the cores), read on the calling
// thread: a thread started later begins with the environment's value, not the caller's.
int AvailableThreads();
// Sets the calling thread's OpenMP threads to its share when `jobs` runs share `threads`.
void ShareCoresAmongJobs(int jobs, int threads);

// Calls task(k) for every k in [0, count), handed out one at a time in order to min(jobs, count)
// threads (the calling one alone when that is 1), each with its share of the cores. An exception a
// task throws stops the handing out; the first is rethrown here once every thread has stopped (an
// exception must not leave a thread: it would end the process).
void RunTasksOnThreads(int jobs, std::size_t count, const std::function<void(std::size_t k)>& task);

// A row as JSON (SI, NaN as null) and back: the journal's lines and the MPI ranks' messages.
nlohmann::json SweepRowToJson(const SweepRow& row);
SweepRow SweepRowFromJson(const nlohmann::json& json);

// sweep.csv (a header of columns, a line of units, one row a run: run, the varied keys' values,
// converged, the headline results in the case's output units, message) and sweep.json (the same).
io::ResultFiles ComposeSweepFiles(const io::Case& base, const std::vector<SweepRow>& rows,
                                  const std::string& directory);

}  // namespace drillflex::pipeline
