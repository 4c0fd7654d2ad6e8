// `drillflex static|modes|buckling|vibration|transient|tendency|run CASE [-o DIR]`: run a case through the
// pipeline (pipeline/case_run.hpp), print each analysis's summary in the case's units as it finishes
// and write the results atomically.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "core/profile.hpp"
#include "pipeline/case_files.hpp"
#include "pipeline/case_run.hpp"
#include "pipeline/summary.hpp"

namespace drillflex::app {
namespace {

// A one-line progress bar of the running analysis with the time left on standard error (the
// transient's: t of its duration), drawn only when it is a terminal (none in pipes, files and tests),
// redrawn at most five times a second; its clock starts at the first update.
class ProgressBar {
 public:
  ProgressBar() : enabled_(isatty(STDERR_FILENO) == 1) {}
  ~ProgressBar() { Finish(); }
  void Update(double time, double duration) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (!started_) start_ = last_ = now;
    started_ = true;
    if (drawn_ && now - last_ < std::chrono::milliseconds(200) && time < duration) return;
    last_ = now;
    drawn_ = true;
    const double fraction = duration > 0.0 ? std::clamp(time / duration, 0.0, 1.0) : 1.0;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const int width = 30, filled = static_cast<int>(fraction * width);
    const std::string left =
        fraction > 0.0 ? fmt::format("{:.0f} s left", elapsed * (1.0 - fraction) / fraction) : std::string("...");
    std::fprintf(stderr, "\r  [%s%s] %3.0f %%  t = %.4g of %.4g s, %s   ", std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), 100.0 * fraction, time, duration, left.c_str());
    std::fflush(stderr);
  }
  // Ends the bar's line (before a summary is printed); the next update starts a new bar.
  void Finish() {
    if (drawn_) std::fputc('\n', stderr);
    drawn_ = started_ = false;
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_ = false;
  bool started_ = false;
  bool drawn_ = false;
  Clock::time_point start_, last_;
};

// A result of any analysis the run asked for (or the equilibrium one started from).
bool AnyFinished(const pipeline::CaseResults& results) {
  return results.static_result || results.modes || results.vibration || results.buckling || results.transient ||
         results.tendency;
}

int RunAnalyses(const CommandOptions& options, const pipeline::AnalysisRequest& request, const char* command) {
  const auto start = std::chrono::steady_clock::now();
  profile::Enable(options.profile);
  const io::Case c = io::ReadCase(options.case_path);
  const bool report = c.output.report && !options.no_report, vtk = c.output.vtk && !options.no_report;
  ProgressBar bar;
  pipeline::RunOptions run_options;
  run_options.keep_transient_shapes = vtk;
  run_options.keep_finished = options.keep_finished;
  auto& observer = run_options.observer;
  if (options.verbose) observer.log = [](const std::string& line) { std::cerr << line << '\n'; };
  observer.note = [](const std::string& line) { std::cout << line << '\n'; };
  observer.progress = [&bar](pipeline::Analysis, double done, double total) { bar.Update(done, total); };
  // The static summary only when asked for (the modes and the vibration solve it too, silently).
  observer.finished = [&](pipeline::Analysis analysis, const pipeline::CaseResults& results) {
    bar.Finish();
    if (analysis != pipeline::Analysis::Static || request.static_analysis) {
      pipeline::WriteSummary(std::cout, c, analysis, results);
    }
  };
  const pipeline::CaseResults results = pipeline::RunCase(c, request, run_options);
  for (const pipeline::AnalysisFailure& failure : results.failures) {
    std::cerr << fmt::format("drillflex: {}: the {} analysis did not finish: {}\n", command,
                             pipeline::AnalysisName(failure.analysis), failure.message);
  }
  if (!results.failures.empty() && !AnyFinished(results)) {
    std::cerr << fmt::format("drillflex: {}: no analysis finished; nothing written\n", command);
    return kExitNotConverged;
  }
  const double solved = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const io::ResultFiles files = [&] {
    const profile::Scope scope("output: compose the result files");
    return pipeline::ComposeResultFiles(c, results, {options.output_directory, report, vtk, command, solved});
  }();
  {
    const profile::Scope scope("output: write the result files");
    files.Commit();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << fmt::format("results written to {} ({:.3g} s){}\n", files.directory(), seconds,
                           report ? fmt::format("; the report: {}/report.html", files.directory()) : "");
  if (options.profile) std::cerr << profile::FormatReport(seconds);
  if (!results.failures.empty()) {
    std::cerr << fmt::format("drillflex: {}: {} of the analyses did not finish (results.json 'failures'); the others' "
                             "results are written\n", command, results.failures.size());
    return kExitNotConverged;
  }
  return kExitOk;
}

}  // namespace

int RunStaticCommand(const CommandOptions& options) {
  return RunAnalyses(options, pipeline::AnalysisRequest::Only(pipeline::Analysis::Static), "static");
}
int RunModesCommand(const CommandOptions& options) {
  return RunAnalyses(options, pipeline::AnalysisRequest::Only(pipeline::Analysis::Modes), "modes");
}
int RunBucklingCommand(const CommandOptions& options) {
  return RunAnalyses(options, pipeline::AnalysisRequest::Only(pipeline::Analysis::Buckling), "buckling");
}
int RunVibrationCommand(const CommandOptions& options) {
  return RunAnalyses(options, pipeline::AnalysisRequest::Only(pipeline::Analysis::Vibration), "vibration");
}
int RunTendencyCommand(const CommandOptions& options) {
  return RunAnalyses(options, pipeline::AnalysisRequest::Only(pipeline::Analysis::Tendency), "tendency");
}
int RunTransientCommand(const CommandOptions& options) {
  return RunAnalyses(options, pipeline::AnalysisRequest::Only(pipeline::Analysis::Transient), "transient");
}

int RunCaseCommand(const CommandOptions& options) {
  return RunAnalyses(options, pipeline::CaseAnalyses(io::ReadCase(options.case_path)), "run");
}

}  // namespace drillflex::app
