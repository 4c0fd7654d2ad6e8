// Runs generated static cases through `drillflex static` under `timeout` and judges each (issue 19):
// a case must converge (exit 0, a converged results.json whose every number is finite, finite CSV
// tables, a bit report) or stop with a clear message (exit 3 saying it did not converge, no result
// files written). A hang, a crash, any other exit status, a NaN or Inf, or a partial output is a
// failure. Two cases run at a time (a 2-core machine). Each case's path (results.json
// `static.method_used`), time, CPU time and peak memory are recorded in <directory>/summary.csv.
#pragma once

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace drillflex::validation {

namespace fs = std::filesystem;

// One generated case: its file stem, case file text, and the drawn parameters for the summary.
struct GeneratedCase {
  std::string stem;
  std::string yaml;
  std::string parameters;  // comma-separated values for summary.csv, in the generator's header order
};

struct RobustnessOutcome {
  int status = -1;           // exit status of `timeout drillflex …`; 124 on a timeout
  double seconds = 0.0;      // wall-clock
  double cpu_seconds = 0.0;  // user + system of the process tree
  double peak_mb = 0.0;      // largest resident size in the process tree
  int iterations = -1;
  std::string method;                 // static.method_used
  std::string message;                // the last line the run printed
  std::vector<std::string> problems;  // why the case fails the test (empty: it passes)
  bool converged() const { return problems.empty() && status == 0; }
};

inline constexpr int kRobustnessTimeoutSeconds = 120;

inline std::string ReadText(const fs::path& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

inline std::string LastLine(const std::string& text) {
  std::istringstream stream(text);
  std::string line, last;
  while (std::getline(stream, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last;
}

// Every number in `value` finite; a null (what nlohmann::json writes for NaN or Inf) is a defect.
inline void CheckFinite(const nlohmann::json& value, const std::string& where, std::vector<std::string>& problems) {
  if (value.is_null()) {
    problems.push_back(where + " is null (NaN or Inf written out)");
  } else if (value.is_number() && !std::isfinite(value.get<double>())) {
    problems.push_back(where + " is not finite");
  } else if (value.is_object()) {
    for (const auto& [key, item] : value.items()) CheckFinite(item, where + "." + key, problems);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) CheckFinite(value[i], where + "[" + std::to_string(i) + "]", problems);
  }
}

// Every cell after the header and units lines a finite number (but the names of a "component" column).
inline void CheckCsv(const fs::path& path, std::vector<std::string>& problems) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  std::vector<std::string> names;
  {
    std::istringstream header(line);
    for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  }
  std::getline(file, line);  // the units line (io::CsvTable)
  for (int row = 1; std::getline(file, line); ++row) {
    std::istringstream cells(line);
    std::string cell;
    for (std::size_t column = 0; std::getline(cells, cell, ','); ++column) {
      if (column < names.size() && names[column] == "component") continue;
      char* end = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      if (end == cell.c_str() || *end != '\0' || !std::isfinite(value)) {
        problems.push_back(path.filename().string() + " row " + std::to_string(row) + ": '" + cell + "'");
        return;
      }
    }
  }
}

// Exit 0: a converged, finite results.json with finite tables. Exit 3: a "did not converge"
// message and no result file. Anything else: a failure.
inline void JudgeStaticRun(const fs::path& output, const std::string& log, RobustnessOutcome& outcome) {
  if (fs::exists(output)) {
    for (const auto& entry : fs::directory_iterator(output)) {
      if (entry.path().extension() == ".partial") outcome.problems.push_back("partial file " + entry.path().string());
    }
  }
  const bool has_results = fs::exists(output / "results.json");
  if (outcome.status == 0) {
    if (!has_results) {
      outcome.problems.push_back("exit 0 without results.json");
      return;
    }
    const nlohmann::json results = nlohmann::json::parse(ReadText(output / "results.json"), nullptr, false);
    if (results.is_discarded() || !results.contains("static")) {
      outcome.problems.push_back("results.json unreadable or without 'static'");
      return;
    }
    const nlohmann::json& static_results = results["static"];
    if (static_results.value("converged", false) != true) outcome.problems.push_back("exit 0 but converged != true");
    outcome.iterations = static_results.value("iterations", -1);
    outcome.method = static_results.value("method_used", std::string());
    CheckFinite(results, "results", outcome.problems);
    CheckCsv(output / "static.csv", outcome.problems);
    if (fs::exists(output / "contacts.csv")) CheckCsv(output / "contacts.csv", outcome.problems);
    if (!static_results.contains("bit")) outcome.problems.push_back("no bit report in a well");
  } else if (outcome.status == 3) {
    std::string text = log;
    for (char& ch : text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (text.find("did not converge") == std::string::npos && text.find("not converged") == std::string::npos &&
        text.find("no static equilibrium") == std::string::npos) {
      outcome.problems.push_back("exit 3 without a message that says it did not converge");
    }
    for (const char* name : {"results.json", "static.csv", "contacts.csv"}) {
      if (fs::exists(output / name)) outcome.problems.push_back(std::string("exit 3 but ") + name + " written");
    }
  } else if (outcome.status == 124 || outcome.status == 137) {
    outcome.problems.push_back("hang: killed after " + std::to_string(kRobustnessTimeoutSeconds) + " s");
  } else if (outcome.status < 0) {
    outcome.problems.push_back("could not start the shell");
  } else {
    outcome.problems.push_back("exit status " + std::to_string(outcome.status));
  }
}

// Runs `sh -c line` and waits for it with wait4, which also gives the CPU time and peak memory of
// the whole process tree (the shell, `timeout` and drillflex, each reaped by its parent).
inline void RunShell(const std::string& line, RobustnessOutcome& outcome) {
  const char* argv[] = {"sh", "-c", line.c_str(), nullptr};
  pid_t pid = 0;
  if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0) {
    outcome.status = -1;
    return;
  }
  int wait_status = 0;
  rusage usage{};
  while (wait4(pid, &wait_status, 0, &usage) < 0 && errno == EINTR) {
  }
  outcome.status = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : 128 + WTERMSIG(wait_status);
  outcome.cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                        1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  outcome.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
}

// Where `drillflex <command>` on a generated case writes: its output directory and its log.
inline fs::path GeneratedOutput(const GeneratedCase& c, const fs::path& directory, const std::string& command) {
  return directory / (command == "static" ? c.stem : c.stem + "-" + command);
}

// `drillflex <command> CASE -o OUT <options>` on one case file in `directory` (one OpenMP thread: the
// cases run two at a time on two cores), killed after `timeout_seconds`; the log in `log` when given.
// A static run is judged (JudgeStaticRun); the other commands' callers judge their own.
inline RobustnessOutcome RunGeneratedCase(const GeneratedCase& c, const fs::path& directory,
                                          const std::string& command = "static", const std::string& options = "",
                                          int timeout_seconds = kRobustnessTimeoutSeconds,
                                          std::string* log = nullptr) {
  const fs::path case_file = directory / (c.stem + ".yaml");
  const fs::path output = GeneratedOutput(c, directory, command);
  const fs::path log_file = fs::path(output.string() + ".log");
  fs::remove_all(output);
  std::ofstream(case_file) << c.yaml;
  const std::string line =
      fmt::format("OMP_NUM_THREADS=1 timeout -k 5 {} {} {} {} -o {} {} > {} 2>&1", timeout_seconds, DRILLFLEX_EXE,
                  command, case_file.string(), output.string(), options, log_file.string());
  RobustnessOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  RunShell(line, outcome);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string text = ReadText(log_file);
  outcome.message = LastLine(text);
  if (command == "static") JudgeStaticRun(output, text, outcome);
  if (log) *log = text;
  return outcome;
}

inline double Percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double position = fraction * static_cast<double>(values.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (position - static_cast<double>(below)) * (values[above] - values[below]);
}

struct RobustnessSummary {
  int cases = 0, converged = 0, stopped = 0, failed = 0;
  double median_seconds = 0.0, p95_seconds = 0.0, max_seconds = 0.0;  // CPU seconds of converged cases
  std::map<std::string, int> methods;  // converged cases by static.method_used
  std::vector<std::string> failures;   // "case: problem (message)"
  std::string text;                    // the totals line
};

// Runs the cases `indices` of `generator` two at a time, printing a line as each ends and writing
// <directory>/summary.csv (one row a case, in index order) and summary.txt (the totals).
inline RobustnessSummary RunGeneratedCases(const std::function<GeneratedCase(int)>& generator,
                                           const std::vector<int>& indices, const fs::path& directory,
                                           const std::string& parameter_header) {
  fs::create_directories(directory);
  std::vector<RobustnessOutcome> outcomes(indices.size());
  std::vector<GeneratedCase> cases(indices.size());
  std::atomic<std::size_t> next{0};
  std::mutex print;
  constexpr int kWorkers = 2;
  const auto wall_start = std::chrono::steady_clock::now();
  auto work = [&]() {
    for (std::size_t i = next++; i < indices.size(); i = next++) {
      cases[i] = generator(indices[i]);
      outcomes[i] = RunGeneratedCase(cases[i], directory);
      const RobustnessOutcome& outcome = outcomes[i];
      const std::lock_guard<std::mutex> lock(print);
      std::cout << fmt::format("{:>10} {:<14} {:>8.3f} s {:>8.3f} s cpu {:>5} it  {}  [{}]\n", cases[i].stem,
                               outcome.converged() ? "converged" : outcome.problems.empty() ? "not_converged" : "FAIL",
                               outcome.seconds, outcome.cpu_seconds, outcome.iterations, outcome.method,
                               cases[i].parameters);
      if (outcome.status != 0) std::cout << "           " << outcome.message << "\n";
      std::cout << std::flush;
    }
  };
  std::vector<std::thread> workers;
  for (int w = 0; w < kWorkers; ++w) workers.emplace_back(work);
  for (auto& worker : workers) worker.join();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  RobustnessSummary summary;
  std::ofstream table(directory / "summary.csv");
  table << "case," << parameter_header << ",status,exit,method,seconds,cpu_seconds,peak_mb,iterations,message\n";
  std::vector<double> converged_cpu;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const RobustnessOutcome& outcome = outcomes[i];
    ++summary.cases;
    if (outcome.converged()) {
      ++summary.converged;
      ++summary.methods[outcome.method];
      converged_cpu.push_back(outcome.cpu_seconds);
    } else if (outcome.problems.empty()) {
      ++summary.stopped;
    } else {
      ++summary.failed;
    }
    for (const auto& problem : outcome.problems) {
      summary.failures.push_back(fmt::format("{}: {} ({})", cases[i].stem, problem, outcome.message));
    }
    std::string message = outcome.status == 0 ? "" : outcome.message;
    for (char& ch : message) if (ch == ',' || ch == '"') ch = ';';
    table << fmt::format("{},{},{},{},{},{:.3f},{:.3f},{:.1f},{},{}\n", cases[i].stem, cases[i].parameters,
                         outcome.converged() ? "converged" : outcome.problems.empty() ? "not_converged" : "FAIL",
                         outcome.status, outcome.method, outcome.seconds, outcome.cpu_seconds, outcome.peak_mb,
                         outcome.iterations, message);
  }
  summary.median_seconds = Percentile(converged_cpu, 0.5);
  summary.p95_seconds = Percentile(converged_cpu, 0.95);
  summary.max_seconds = converged_cpu.empty() ? 0.0 : *std::max_element(converged_cpu.begin(), converged_cpu.end());
  std::string methods;
  for (const auto& [method, count] : summary.methods) methods += fmt::format(" {} {},", method, count);
  summary.text = fmt::format(
      "converged {}/{} ({:.1f} %), stopped with a message {}, failed {}; a converged case on one core: CPU median "
      "{:.3f} s, 95th percentile {:.3f} s, max {:.3f} s; by path:{} {:.0f} s in all on {} workers",
      summary.converged, summary.cases, 100.0 * summary.converged / std::max(summary.cases, 1), summary.stopped,
      summary.failed, summary.median_seconds, summary.p95_seconds, summary.max_seconds, methods, wall, kWorkers);
  std::cout << summary.text << "\n";
  std::ofstream(directory / "summary.txt") << summary.text << "\n";
  return summary;
}

}  // namespace drillflex::validation
