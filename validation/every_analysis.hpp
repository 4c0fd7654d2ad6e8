// Every analysis on every generated BHA (issue 33, item 1): a generated case of either robustness
// generator (robustness_cases_adapter.hpp) with the five analyses added, run through
// `drillflex run --keep-finished` (one process a case; an analysis that fails is named in
// results.json's `failures` and the others still run), and judged analysis by analysis.
//
// The analyses: the static; 10 modes; the vibration on its default excitations (an imbalance at the
// MWD or mid-BHA, the bit at 3×) over 20–250 rpm in steps of 5; the buckling of the case's loads (its
// WOB where it has one); and a 1 s transient from the equilibrium, the top driven at the case's rpm
// (reached over 0.25 s) where the case rotates, held where it does not.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "robustness_runner.hpp"

namespace drillflex::validation {

inline constexpr std::array<const char*, 5> kEveryAnalysis = {"static", "modes", "vibration", "buckling", "transient"};

// The generated case (whose text ends in "analyses:\n  static: {}\n") with the other four added.
inline GeneratedCase WithEveryAnalysis(GeneratedCase c, double rpm) {
  c.yaml += "  modes: {count: 10}\n  vibration: {rpm: {from: 20, to: 250, step: 5}}\n  buckling: {}\n";
  c.yaml += rpm > 0.0 ? "  transient: {duration: 1 s, top_drive: {ramp: 0.25 s}, vtk_frames: 0}\n"
                      : "  transient: {duration: 1 s, vtk_frames: 0}\n";
  return c;
}

struct EveryAnalysisOutcome {
  RobustnessOutcome run;                         // status, times, memory, last line
  std::map<std::string, bool> finished;          // by analysis name
  std::map<std::string, std::string> failures;   // by analysis name: results.json's message
  std::vector<std::string> problems;             // what makes the run itself a defect (empty: none)
};

// Exit 0: every analysis in a finite results.json. Exit 3: the finished ones there, the others named
// in `failures` with a one-line message (or, when none finished, no results.json and a message).
// Anything else (bad input, a crash, a hang, a NaN) is a problem.
inline void JudgeEveryAnalysis(const fs::path& output, const std::string& log, EveryAnalysisOutcome& outcome) {
  const int status = outcome.run.status;
  for (const char* name : kEveryAnalysis) outcome.finished[name] = false;
  if (status == 124 || status == 137) {
    outcome.problems.push_back("hang: killed after the time limit");
    return;
  }
  if (status != 0 && status != 3) {
    outcome.problems.push_back(fmt::format("exit status {}: {}", status, LastLine(log)));
    return;
  }
  if (!fs::exists(output / "results.json")) {
    if (status == 0) outcome.problems.push_back("exit 0 without results.json");
    if (status == 3 && log.find("no analysis finished") == std::string::npos) {
      outcome.problems.push_back("exit 3 without results.json and without saying that no analysis finished");
    }
    for (const char* name : kEveryAnalysis) outcome.failures[name] = LastLine(log);
    return;
  }
  const nlohmann::json results = nlohmann::json::parse(ReadText(output / "results.json"), nullptr, false);
  if (results.is_discarded()) {
    outcome.problems.push_back("results.json unreadable");
    return;
  }
  CheckFinite(results, "results", outcome.problems);
  for (const char* name : kEveryAnalysis) outcome.finished[name] = results.contains(name);
  if (outcome.finished["static"]) {  // as robustness_runner.hpp judges a static run
    if (results["static"].value("converged", false) != true) outcome.problems.push_back("static: converged != true");
    if (!results["static"].contains("bit")) outcome.problems.push_back("static: no bit report in a well");
    CheckCsv(output / "static.csv", outcome.problems);
  }
  for (const auto& entry : fs::directory_iterator(output)) {
    if (entry.path().extension() == ".partial") outcome.problems.push_back("partial file " + entry.path().string());
  }
  if (results.contains("failures")) {
    for (const auto& failure : results["failures"]) {
      const std::string name = failure.value("analysis", std::string());
      const std::string message = failure.value("message", std::string());
      if (message.empty() || message.find('\n') != std::string::npos) {
        outcome.problems.push_back(name + ": the failure's message is not one line");
      }
      outcome.failures[name] = message;
      outcome.finished[name] = false;
    }
  }
  for (const char* name : kEveryAnalysis) {
    if (!outcome.finished[name] && !outcome.failures.contains(name)) {
      outcome.problems.push_back(std::string(name) + " neither finished nor named as failed");
    }
  }
  if (status == 0 && !outcome.failures.empty()) outcome.problems.push_back("exit 0 with failures");
  if (status == 3 && outcome.failures.empty()) outcome.problems.push_back("exit 3 without failures");
}

inline constexpr int kEveryAnalysisTimeoutSeconds = 600;

// `drillflex run --keep-finished --no-report` on the case in `directory` (one OpenMP thread).
inline EveryAnalysisOutcome RunEveryAnalysis(const GeneratedCase& c, const fs::path& directory) {
  EveryAnalysisOutcome outcome;
  std::string log;
  outcome.run = RunGeneratedCase(c, directory, "run", "--keep-finished --no-report", kEveryAnalysisTimeoutSeconds, &log);
  JudgeEveryAnalysis(GeneratedOutput(c, directory, "run"), log, outcome);
  return outcome;
}

struct EveryAnalysisSummary {
  int cases = 0;
  std::map<std::string, int> finished;  // by analysis
  double median_seconds = 0.0, p95_seconds = 0.0, max_seconds = 0.0;  // CPU seconds a case, all five
  std::vector<std::string> problems;    // "case: problem"
  std::vector<std::string> failures;    // "case analysis: message"
  std::string text;                     // the totals
};

// Runs `cases` two at a time, writes <directory>/summary.csv (a row a case: the times, each analysis's
// outcome) and summary.txt.
inline EveryAnalysisSummary RunEveryAnalysisCases(const std::vector<GeneratedCase>& cases, const fs::path& directory) {
  fs::create_directories(directory);
  std::vector<EveryAnalysisOutcome> outcomes(cases.size());
  std::atomic<std::size_t> next{0};
  std::mutex print;
  auto work = [&]() {
    for (std::size_t i = next++; i < cases.size(); i = next++) {
      outcomes[i] = RunEveryAnalysis(cases[i], directory);
      const std::lock_guard<std::mutex> lock(print);
      std::string failed;
      for (const auto& [name, message] : outcomes[i].failures) failed += " " + name;
      std::cout << fmt::format("{}: exit {}, {:.1f} s CPU{}{}\n", cases[i].stem, outcomes[i].run.status,
                               outcomes[i].run.cpu_seconds, failed.empty() ? "" : "; did not finish:", failed)
                << std::flush;
    }
  };
  std::thread other(work);
  work();
  other.join();
  EveryAnalysisSummary summary;
  summary.cases = static_cast<int>(cases.size());
  std::vector<double> seconds;
  std::ofstream csv(directory / "summary.csv");
  csv << "case,exit,cpu_s,wall_s,peak_mb";
  for (const char* name : kEveryAnalysis) csv << "," << name;
  csv << ",message\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const EveryAnalysisOutcome& o = outcomes[i];
    seconds.push_back(o.run.cpu_seconds);
    csv << fmt::format("{},{},{:.2f},{:.2f},{:.0f}", cases[i].stem, o.run.status, o.run.cpu_seconds, o.run.seconds,
                       o.run.peak_mb);
    std::string messages;
    for (const char* name : kEveryAnalysis) {
      const bool done = o.finished.at(name);
      summary.finished[name] += done ? 1 : 0;
      csv << "," << (done ? "finished" : "failed");
      if (o.failures.contains(name)) {
        summary.failures.push_back(fmt::format("{} {}: {}", cases[i].stem, name, o.failures.at(name)));
        messages += fmt::format("{}{}: {}", messages.empty() ? "" : " | ", name, o.failures.at(name));
      }
    }
    std::string quoted = messages;
    for (char& ch : quoted) {
      if (ch == '"') ch = '\'';
    }
    csv << ",\"" << quoted << "\"\n";
    for (const std::string& problem : o.problems) summary.problems.push_back(cases[i].stem + ": " + problem);
  }
  summary.median_seconds = Percentile(seconds, 0.5);
  summary.p95_seconds = Percentile(seconds, 0.95);
  summary.max_seconds = seconds.empty() ? 0.0 : *std::max_element(seconds.begin(), seconds.end());
  summary.text = fmt::format("{} cases; finished:", summary.cases);
  for (const char* name : kEveryAnalysis) summary.text += fmt::format(" {} {}", name, summary.finished[name]);
  summary.text += fmt::format("; CPU seconds a case (all five): median {:.2f}, 95th percentile {:.2f}, max {:.2f}",
                              summary.median_seconds, summary.p95_seconds, summary.max_seconds);
  std::ofstream(directory / "summary.txt") << summary.text << "\n";
  std::cout << summary.text << "\n";
  return summary;
}

}  // namespace drillflex::validation
