// The subcommands of the `drillflex` command line. Each returns the process exit status.
#pragma once

#include <string>
#include <vector>

namespace drillflex::app {

// Exit statuses: 0 success, 2 bad input (file, line, key named), 3 a solver that did not
// converge, 1 anything else (an unwritable output directory, an internal error).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitNotConverged = 3;

struct CommandOptions {
  std::string case_path;
  std::string output_directory;  // "" = results/<case name>
  bool verbose = false;          // the solvers' progress on standard error
  bool no_report = false;        // no report.html and no VTK files (batch runs)
  bool profile = false;          // where the solve spent its time, on standard error (core/profile.hpp)
  // `run` only: an analysis that fails is named and the others' results are written (exit 3).
  bool keep_finished = false;
  // `sweep` only:
  std::vector<std::string> vary;  // KEY=VALUES, each an axis of the sweep
  std::string cases_table;        // a CSV of key paths and one run a row, instead of (or with no) --vary
  int jobs = 1;                   // runs at once on this machine
  bool keep_runs = false;         // each run's own files under DIR/runs/NNNN/
  bool resume = false;            // skip the runs an interrupted sweep finished
  // `roadmap` only (the case's analyses.roadmap keys, as YAML values: "4000 ft", "0.2, 0.3"); `jobs` too:
  std::string roadmap_from;
  std::string roadmap_step;
  std::string roadmap_friction;
  std::string roadmap_model;  // stiff, soft or both
  std::string roadmap_stiff_length;  // a length or "surface"
  // `roadmap` and `calibrate`: the rig's readings (a readings CSV or a WITSML log).
  std::string readings_path;
  // `calibrate` only (`jobs` too): the parameters to fit, a comma list; the model, stiff or soft.
  std::string calibrate_fit;
  std::string calibrate_model;
  // `stability` only (a sweep's VALUES); `jobs`, `resume` and `keep_runs` too:
  std::string stability_rpm_values;
  std::string stability_wob_values;
  // `import` only: the WITSML documents (the case is written to output_directory's place: -o FILE).
  std::vector<std::string> documents;
};

int RunCheck(const CommandOptions& options);
int RunWell(const CommandOptions& options);
int RunStaticCommand(const CommandOptions& options);
int RunModesCommand(const CommandOptions& options);
int RunBucklingCommand(const CommandOptions& options);
int RunTendencyCommand(const CommandOptions& options);
int RunVibrationCommand(const CommandOptions& options);
int RunTransientCommand(const CommandOptions& options);
int RunCaseCommand(const CommandOptions& options);
int RunSweepCommand(const CommandOptions& options);
int RunRoadmapCommand(const CommandOptions& options);
int RunStabilityCommand(const CommandOptions& options);
int RunCalibrateCommand(const CommandOptions& options);
// `drillflex import FILE... [-o CASE.yaml]`: -o names the case file (standard output without it).
int RunImport(const CommandOptions& options);

}  // namespace drillflex::app
