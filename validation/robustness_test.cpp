// Robustness (issue 4): 200 randomized static cases (validation/robustness_cases.hpp: inclination
// 0–100°, DLS up to 10°/100 ft, radial collar clearance from 0.25 in, WOB 0–50 klbf, 1–3
// stabilizers) run through `drillflex static` under `timeout 120`. Each must converge (exit 0, a
// converged results.json whose every number is finite, finite CSV tables) or stop with a clear
// message (exit 3 saying it did not converge, no result files written); two cases run at a time. A hang, a crash, any
// other exit status, a NaN or Inf, or a partial output fails the test. The convergence rate, the
// median and largest time and one row per case are printed and written to
// <build>/validation-results/robustness/summary.csv; the case files stay beside it.
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "robustness_cases.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kCaseCount = 200;
constexpr int kTimeoutSeconds = 120;
constexpr int kWorkers = 2;  // cases run two at a time (a 2-core machine)

std::string ReadText(const fs::path& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

std::string LastLine(const std::string& text) {
  std::istringstream stream(text);
  std::string line, last;
  while (std::getline(stream, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last;
}

std::string Lower(std::string text) {
  for (char& ch : text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return text;
}

// Every number in `value` finite; a null (what nlohmann::json writes for NaN or Inf) is a defect.
void CheckFinite(const json& value, const std::string& where, std::vector<std::string>& problems) {
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

// Every cell after the header line a finite number.
void CheckCsv(const fs::path& path, std::vector<std::string>& problems) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  for (int row = 1; std::getline(file, line); ++row) {
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      char* end = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      if (end == cell.c_str() || *end != '\0' || !std::isfinite(value)) {
        problems.push_back(path.filename().string() + " row " + std::to_string(row) + ": '" + cell + "'");
        return;
      }
    }
  }
}

struct Outcome {
  int status = -1;  // exit status of `timeout drillflex …`; 124 on a timeout
  double seconds = 0.0;      // wall-clock
  double cpu_seconds = 0.0;  // user + system of the process tree (the machine may be shared)
  double peak_mb = 0.0;      // largest resident size in the process tree
  int iterations = -1, load_steps = -1;
  std::string message;                // the last line the run printed
  std::vector<std::string> problems;  // why the case fails the test (empty: it passes)
};

// Exit 0: a converged, finite results.json with finite tables. Exit 3: a "did not converge"
// message and no result file. Anything else: a failure.
void Judge(const fs::path& output, const std::string& log, Outcome& outcome) {
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
    const json results = json::parse(ReadText(output / "results.json"), nullptr, false);
    if (results.is_discarded() || !results.contains("static")) {
      outcome.problems.push_back("results.json unreadable or without 'static'");
      return;
    }
    const json& static_results = results["static"];
    if (static_results.value("converged", false) != true) outcome.problems.push_back("exit 0 but converged != true");
    outcome.iterations = static_results.value("iterations", -1);
    outcome.load_steps = static_results.value("load_steps", -1);
    CheckFinite(results, "results", outcome.problems);
    CheckCsv(output / "static.csv", outcome.problems);
    if (fs::exists(output / "contacts.csv")) CheckCsv(output / "contacts.csv", outcome.problems);
    if (!static_results.contains("bit")) outcome.problems.push_back("no bit report in a well");
  } else if (outcome.status == 3) {
    const std::string text = Lower(log);
    if (text.find("did not converge") == std::string::npos && text.find("not converged") == std::string::npos) {
      outcome.problems.push_back("exit 3 without a 'did not converge' message");
    }
    for (const char* name : {"results.json", "static.csv", "contacts.csv"}) {
      if (fs::exists(output / name)) outcome.problems.push_back(std::string("exit 3 but ") + name + " written");
    }
  } else if (outcome.status == 124 || outcome.status == 137) {
    outcome.problems.push_back("hang: killed after " + std::to_string(kTimeoutSeconds) + " s");
  } else if (outcome.status < 0) {
    outcome.problems.push_back("could not start the shell");
  } else {
    outcome.problems.push_back("exit status " + std::to_string(outcome.status));
  }
}

// Runs `sh -c line` and waits for it with wait4, which also gives the CPU time and peak memory of
// the whole process tree (the shell, `timeout` and drillflex, each reaped by its parent).
void RunShell(const std::string& line, Outcome& outcome) {
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

Outcome RunRobustnessCase(const RobustnessCase& c, const fs::path& directory) {
  const std::string stem = fmt::format("case-{:03d}", c.index);
  const fs::path case_file = directory / (stem + ".yaml");
  const fs::path output = directory / stem;
  const fs::path log_file = directory / (stem + ".log");
  fs::remove_all(output);
  std::ofstream(case_file) << ToYaml(c);
  const std::string line = fmt::format("timeout -k 5 {} {} static {} -o {} > {} 2>&1", kTimeoutSeconds, DRILLFLEX_EXE,
                                       case_file.string(), output.string(), log_file.string());
  Outcome outcome;
  const auto start = std::chrono::steady_clock::now();
  RunShell(line, outcome);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string log = ReadText(log_file);
  outcome.message = LastLine(log);
  Judge(output, log, outcome);
  return outcome;
}

std::string StatusName(const Outcome& outcome) {
  if (!outcome.problems.empty()) return "FAIL";
  return outcome.status == 0 ? "converged" : "not_converged";
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

TEST(Robustness, GeneratorSpansTheStatedRanges) {
  double min_clearance = 1e9, max_inclination = 0.0, max_dls = 0.0, min_wob = 1e9, max_wob = 0.0;
  int by_stabilizers[4] = {0, 0, 0, 0};
  for (int i = 0; i < kCaseCount; ++i) {
    const RobustnessCase c = MakeRobustnessCase(i);
    EXPECT_LE(c.max_dls_deg_per_100ft, 10.0 + 1e-9) << i;
    EXPECT_GE(c.clearance_in, 0.25) << i;
    EXPECT_GE(c.final_inclination_deg, 0.0) << i;
    EXPECT_LE(c.final_inclination_deg, 100.0) << i;
    EXPECT_GE(c.bha_length_ft, 60.0) << i;
    EXPECT_LE(c.bha_length_ft, 150.0) << i;
    ASSERT_EQ(static_cast<int>(c.stabilizer_at_ft.size()), c.stabilizers) << i;
    for (std::size_t k = 1; k < c.stabilizer_at_ft.size(); ++k) EXPECT_GE(c.stabilizer_at_ft[k] - c.stabilizer_at_ft[k - 1], 5.0) << i;
    EXPECT_LE(c.stabilizer_at_ft.back() + 5.0, c.bha_length_ft + 1e-9) << i;
    EXPECT_GT(c.hole_in - c.blade_under_gauge_in, c.collar_od_in) << i;
    // The string stays well below the first survey station (the surface).
    EXPECT_LT(c.string_length_ft, c.bit_md_ft - 300.0) << i;
    EXPECT_GE(c.bit_md_ft, c.kop_ft) << i;
    EXPECT_LE(c.bit_md_ft, c.survey.back().md_ft) << i;
    min_clearance = std::min(min_clearance, c.clearance_in);
    max_inclination = std::max(max_inclination, c.final_inclination_deg);
    max_dls = std::max(max_dls, c.max_dls_deg_per_100ft);
    min_wob = std::min(min_wob, c.wob_klbf);
    max_wob = std::max(max_wob, c.wob_klbf);
    ++by_stabilizers[c.stabilizers];
  }
  // The 200 cases reach the corners of the stated ranges.
  EXPECT_LT(min_clearance, 0.30);
  EXPECT_GT(max_inclination, 95.0);
  EXPECT_GT(max_dls, 9.5);
  EXPECT_LT(min_wob, 2.0);
  EXPECT_GT(max_wob, 48.0);
  for (int n = 1; n <= 3; ++n) EXPECT_GT(by_stabilizers[n], 40) << n << " stabilizers";
}

constexpr const char* kSummaryHeader =
    "index,seed,inclination_deg,dls_deg_per_100ft,clearance_in,hole_in,wob_klbf,stabilizers,bha_ft,string_ft,status,"
    "exit,seconds,cpu_seconds,peak_mb,iterations,load_steps,message\n";

std::string SummaryRow(const RobustnessCase& c, const Outcome& outcome) {
  std::string message = outcome.status == 0 ? "" : outcome.message;
  for (char& ch : message) if (ch == ',' || ch == '"') ch = ';';
  return fmt::format("{},{},{:.3f},{:.3f},{:.4f},{},{:.3f},{},{:.2f},{:.2f},{},{},{:.3f},{:.3f},{:.1f},{},{},{}\n",
                     c.index, kRobustnessSeed + c.index, c.final_inclination_deg, c.max_dls_deg_per_100ft,
                     c.clearance_in, c.hole_in, c.wob_klbf, c.stabilizers, c.bha_length_ft, c.string_length_ft,
                     StatusName(outcome), outcome.status, outcome.seconds, outcome.cpu_seconds, outcome.peak_mb,
                     outcome.iterations, outcome.load_steps, message);
}

// Runs every case on kWorkers threads (each a `drillflex` process at a time), printing a line as
// each case ends and its row to progress.csv (the order they end in; summary.csv is written sorted
// at the end).
std::vector<Outcome> RunAll(const fs::path& directory) {
  std::vector<Outcome> outcomes(kCaseCount);
  // DRILLFLEX_ROBUSTNESS_STRIDE=k runs every k-th case only (a quick look; the test then counts the others as not run).
  const char* stride_text = std::getenv("DRILLFLEX_ROBUSTNESS_STRIDE");
  const int stride = stride_text ? std::max(1, std::atoi(stride_text)) : 1;
  std::atomic<int> next{0};
  std::mutex print;
  std::ofstream progress(directory / "progress.csv");
  progress << kSummaryHeader << std::flush;
  auto work = [&]() {
    for (int i = next++ * stride; i < kCaseCount; i = next++ * stride) {
      const RobustnessCase c = MakeRobustnessCase(i);
      outcomes[i] = RunRobustnessCase(c, directory);
      const Outcome& outcome = outcomes[i];
      const std::lock_guard<std::mutex> lock(print);
      std::cout << fmt::format("{:>5} {:>6.2f} {:>6.2f} {:>6.3f} {:>6.2f} {:>4} {:<14} {:>8.3f} {:>8.3f} {:>6}\n", i,
                               c.final_inclination_deg, c.max_dls_deg_per_100ft, c.clearance_in, c.wob_klbf,
                               c.stabilizers, StatusName(outcome), outcome.seconds, outcome.cpu_seconds,
                               outcome.iterations);
      if (outcome.status != 0) std::cout << "      " << outcome.message << "\n";
      std::cout << std::flush;
      progress << SummaryRow(c, outcome) << std::flush;
    }
  };
  std::vector<std::thread> workers;
  for (int w = 0; w < kWorkers; ++w) workers.emplace_back(work);
  for (auto& worker : workers) worker.join();
  return outcomes;
}

TEST(Robustness, RandomCasesConvergeOrStopWithAMessage) {
  const fs::path directory = fs::path(DRILLFLEX_BINARY_DIR) / "validation-results" / "robustness";
  fs::create_directories(directory);
  std::cout << fmt::format("{:>5} {:>6} {:>6} {:>6} {:>6} {:>4} {:<14} {:>8} {:>8} {:>6}\n", "case", "inc", "dls",
                           "clear", "wob", "stab", "status", "wall_s", "cpu_s", "iter");
  const auto wall_start = std::chrono::steady_clock::now();
  const std::vector<Outcome> outcomes = RunAll(directory);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  std::ofstream summary(directory / "summary.csv");
  summary << kSummaryHeader;
  int converged = 0, stopped = 0;
  std::vector<double> times, cpu_times, peaks;
  std::vector<std::string> failures;
  for (int i = 0; i < kCaseCount; ++i) {
    const RobustnessCase c = MakeRobustnessCase(i);
    const Outcome& outcome = outcomes[i];
    times.push_back(outcome.seconds);
    cpu_times.push_back(outcome.cpu_seconds);
    peaks.push_back(outcome.peak_mb);
    if (outcome.problems.empty()) (outcome.status == 0 ? converged : stopped) += 1;
    summary << SummaryRow(c, outcome);
    for (const auto& problem : outcome.problems) {
      failures.push_back(fmt::format("case {:03d}: {} ({})", i, problem, outcome.message));
    }
  }
  const double rate = 100.0 * converged / kCaseCount;
  const std::string totals = fmt::format(
      "converged {}/{} ({:.1f} %), stopped with a message {}, failed {}; a case: wall median {:.3f} s, max {:.3f} s; "
      "CPU median {:.3f} s, max {:.3f} s; peak memory median {:.0f} MB, max {:.0f} MB; {:.0f} s in all on {} workers",
      converged, kCaseCount, rate, stopped, kCaseCount - converged - stopped, Median(times),
      *std::max_element(times.begin(), times.end()), Median(cpu_times),
      *std::max_element(cpu_times.begin(), cpu_times.end()), Median(peaks), *std::max_element(peaks.begin(), peaks.end()),
      wall, kWorkers);
  std::cout << totals << "\n";
  std::ofstream(directory / "summary.txt") << totals << "\n";
  for (const auto& failure : failures) ADD_FAILURE() << failure;
}

}  // namespace
}  // namespace drillflex::validation
