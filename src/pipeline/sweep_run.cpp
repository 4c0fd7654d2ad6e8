#include "pipeline/sweep_run.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "core/error.hpp"
#include "pipeline/case_files.hpp"

namespace drillflex::pipeline {
namespace {

using units::Quantity;

// The headline columns: name in sweep.csv and sweep.json, quantity, member.
struct HeadlineColumn {
  const char* name;
  Quantity quantity;
  double SweepOutcome::*member;
};

constexpr HeadlineColumn kHeadlines[] = {
    {"bit_side_force", Quantity::Force, &SweepOutcome::bit_side_force},
    {"largest_contact_force", Quantity::Force, &SweepOutcome::largest_contact_force},
    {"peak_von_mises_stress", Quantity::Stress, &SweepOutcome::peak_von_mises_stress},
    {"first_critical_rpm", Quantity::RotarySpeed, &SweepOutcome::first_critical_speed},
    {"stick_slip_severity", Quantity::Dimensionless, &SweepOutcome::stick_slip_severity},
    {"whirl_speed", Quantity::RotarySpeed, &SweepOutcome::whirl_speed},
    {"hook_load", Quantity::Force, &SweepOutcome::hook_load},
    {"surface_torque", Quantity::Moment, &SweepOutcome::surface_torque},
    {"build_rate", Quantity::DoglegSeverity, &SweepOutcome::build_rate},
    {"turn_rate", Quantity::DoglegSeverity, &SweepOutcome::turn_rate},
};

// The words of a row, after the figures: (column, member).
struct TextColumn {
  const char* name;
  std::string SweepOutcome::*member;
};
constexpr TextColumn kTextColumns[] = {
    {"bit_tendency", &SweepOutcome::bit_tendency},
    {"whirl", &SweepOutcome::whirl},
    {"regime", &SweepOutcome::regime},
};

std::string RunName(int index) { return fmt::format("{:04d}", index + 1); }

nlohmann::json NumberOrNull(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }
double NumberFrom(const nlohmann::json& json) { return json.is_number() ? json.get<double>() : kNotComputed; }

// The journal's rows by index, checked against the sweep's combinations.
std::map<int, SweepRow> ReadJournal(const std::string& path, const std::vector<SweepCombination>& combinations) {
  std::map<int, SweepRow> rows;
  std::ifstream stream(path);
  if (!stream) return rows;
  std::string line;
  int line_number = 0;
  while (std::getline(stream, line)) {
    ++line_number;
    if (line.empty()) continue;
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception&) {
      continue;  // the line an interruption cut short: that run is simply run again
    }
    SweepRow row = SweepRowFromJson(json);
    const bool same = row.index >= 0 && row.index < static_cast<int>(combinations.size()) &&
                      combinations[static_cast<std::size_t>(row.index)].size() == row.values.size() &&
                      std::equal(row.values.begin(), row.values.end(),
                                 combinations[static_cast<std::size_t>(row.index)].begin(),
                                 [](const io::CaseValue& a, const io::CaseValue& b) {
                                   return a.key == b.key && a.value == b.value;
                                 });
    if (!same) {
      throw InputError({path, line_number, 0}, "--resume",
                       fmt::format("run {} of this journal is not run {} of this sweep (other keys or values): "
                                   "resume a sweep with the same case and --vary, or start it again without --resume",
                                   row.index + 1, row.index + 1));
    }
    rows[row.index] = std::move(row);
  }
  return rows;
}

}  // namespace

SweepRow RunSweepCase(const io::Case& base, int index, const SweepCombination& values, bool keep_runs,
                      const std::string& runs_directory) {
  SweepRow row{index, values, {}};
  try {
    const io::Case c = io::WithValues(base, values);
    CaseResults results = RunCase(c, CaseAnalyses(c));
    row.outcome = SummarizeRun(results);
    if (keep_runs) {
      const std::string directory = (std::filesystem::path(runs_directory) / RunName(index)).string();
      ComposeResultFiles(c, results, {directory, false, false, "sweep", 0.0}).Commit();
    }
  } catch (const InputError& error) {
    row.outcome = SweepOutcome{};
    row.outcome.message = error.what();
  } catch (const SolverError& error) {
    row.outcome = SweepOutcome{};
    row.outcome.message = error.what();
  }
  return row;
}

int AvailableThreads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

void ShareCoresAmongJobs(int jobs, int threads) {
#ifdef _OPENMP
  omp_set_num_threads(std::max(1, threads / std::max(1, jobs)));
#else
  (void)jobs;
  (void)threads;
#endif
}

struct SweepLedger::State {
  std::vector<SweepRow> rows;
  std::ofstream journal;
  std::string journal_path;
  SweepProgress progress;
  std::function<void(const SweepProgress&)> callback;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::mutex mutex;
};

SweepLedger::SweepLedger(const std::vector<SweepCombination>& combinations, const SweepOptions& options)
    : state_(std::make_unique<State>()) {
  std::filesystem::create_directories(options.directory);
  state_->journal_path = (std::filesystem::path(options.directory) / kSweepJournal).string();
  std::map<int, SweepRow> finished;
  if (options.resume) {
    finished = ReadJournal(state_->journal_path, combinations);
  } else {
    std::filesystem::remove(state_->journal_path);
  }
  for (int i = 0; i < static_cast<int>(combinations.size()); ++i) {
    if (!finished.count(i)) pending_.push_back(i);
  }
  state_->rows.resize(combinations.size());
  state_->progress.total = static_cast<int>(combinations.size());
  for (auto& [index, row] : finished) {
    ++state_->progress.done;
    if (!row.outcome.converged) ++state_->progress.failed;
    state_->rows[static_cast<std::size_t>(index)] = std::move(row);
  }
  state_->journal.open(state_->journal_path, std::ios::app);
  if (!state_->journal) {
    throw std::runtime_error(fmt::format("cannot write the sweep's journal {}", state_->journal_path));
  }
  state_->callback = options.progress;
  if (state_->callback) state_->callback(state_->progress);
}

SweepLedger::~SweepLedger() = default;

void SweepLedger::Record(SweepRow row) {
  const std::lock_guard<std::mutex> lock(state_->mutex);
  state_->journal << SweepRowToJson(row).dump() << '\n' << std::flush;
  SweepProgress& progress = state_->progress;
  ++progress.done;
  ++progress.run_this_call;
  if (!row.outcome.converged) ++progress.failed;
  progress.elapsed_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - state_->start).count();
  state_->rows[static_cast<std::size_t>(row.index)] = std::move(row);
  if (state_->callback) state_->callback(progress);
}

std::vector<SweepRow> SweepLedger::TakeRows() {
  const std::lock_guard<std::mutex> lock(state_->mutex);
  return std::move(state_->rows);
}

void RunTasksOnThreads(int jobs, std::size_t count, const std::function<void(std::size_t k)>& task) {
  const int used = std::max(1, std::min(jobs, static_cast<int>(count)));
  const int threads = AvailableThreads();
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&]() {
    ShareCoresAmongJobs(used, threads);
    try {
      for (std::size_t k = next++; k < count; k = next++) task(k);
    } catch (...) {
      next = count;  // no more tasks handed out
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  if (used == 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (int j = 0; j < used; ++j) pool.emplace_back(worker);
    for (std::thread& thread : pool) thread.join();
  }
  if (failure) std::rethrow_exception(failure);
}

std::vector<SweepRow> RunSweep(const io::Case& base, const std::vector<SweepCombination>& combinations,
                               const SweepOptions& options) {
  SweepLedger ledger(combinations, options);
  const std::vector<int>& pending = ledger.pending();
  const std::string runs_directory = (std::filesystem::path(options.directory) / "runs").string();
  RunTasksOnThreads(options.jobs, pending.size(), [&](std::size_t k) {
    const int index = pending[k];
    ledger.Record(RunSweepCase(base, index, combinations[static_cast<std::size_t>(index)], options.keep_runs,
                               runs_directory));
  });
  return ledger.TakeRows();
}

nlohmann::json SweepRowToJson(const SweepRow& row) {
  nlohmann::json values = nlohmann::json::array();
  for (const io::CaseValue& value : row.values) values.push_back({value.key, value.value});
  nlohmann::json json = {{"index", row.index},
                         {"values", values},
                         {"converged", row.outcome.converged},
                         {"message", row.outcome.message}};
  for (const TextColumn& column : kTextColumns) json[column.name] = row.outcome.*column.member;
  for (const HeadlineColumn& column : kHeadlines) json[column.name] = NumberOrNull(row.outcome.*column.member);
  return json;
}

SweepRow SweepRowFromJson(const nlohmann::json& json) {
  SweepRow row;
  row.index = json.value("index", -1);
  for (const auto& value : json.value("values", nlohmann::json::array())) {
    row.values.push_back({value.at(0).get<std::string>(), value.at(1).get<std::string>()});
  }
  row.outcome.converged = json.value("converged", false);
  row.outcome.message = json.value("message", "");
  for (const TextColumn& column : kTextColumns) row.outcome.*column.member = json.value(column.name, "");
  for (const HeadlineColumn& column : kHeadlines) {
    row.outcome.*column.member = json.contains(column.name) ? NumberFrom(json[column.name]) : kNotComputed;
  }
  return row;
}

io::ResultFiles ComposeSweepFiles(const io::Case& base, const std::vector<SweepRow>& rows,
                                  const std::string& directory) {
  io::ResultFiles files(directory, "sweep.json");
  const units::System system = base.output_units;
  std::vector<std::string> columns{"run"}, units_row{"-"};
  if (!rows.empty()) {
    for (const io::CaseValue& value : rows.front().values) {
      columns.push_back(value.key);
      units_row.push_back("as given");
    }
  }
  columns.push_back("converged");
  units_row.push_back("-");
  for (const HeadlineColumn& column : kHeadlines) {
    columns.push_back(column.name);
    units_row.push_back(column.quantity == Quantity::Dimensionless ? "-"
                                                                   : std::string(units::DefaultUnit(column.quantity, system)));
  }
  for (const TextColumn& column : kTextColumns) {
    columns.push_back(column.name);
    units_row.push_back("-");
  }
  columns.push_back("message");
  units_row.push_back("-");
  io::CsvTable table(columns, units_row);
  nlohmann::json runs = nlohmann::json::array();
  for (const SweepRow& row : rows) {
    std::vector<std::string> cells{std::to_string(row.index + 1)};
    nlohmann::json run = {{"run", row.index + 1}};
    nlohmann::json values = nlohmann::json::object();
    for (const io::CaseValue& value : row.values) {
      cells.push_back(io::CsvTable::Text(value.value));
      values[value.key] = value.value;
    }
    run["values"] = values;
    cells.push_back(row.outcome.converged ? "1" : "0");
    run["converged"] = row.outcome.converged;
    for (const HeadlineColumn& column : kHeadlines) {
      const double si = row.outcome.*column.member;
      const double shown = std::isfinite(si) ? units::FromSI(si, column.quantity, system) : si;
      cells.push_back(std::isfinite(shown) ? io::CsvTable::Number(shown) : "");
      run[column.name] = NumberOrNull(shown);
    }
    for (const TextColumn& column : kTextColumns) {
      cells.push_back(io::CsvTable::Text(row.outcome.*column.member));
      run[column.name] = row.outcome.*column.member;
    }
    cells.push_back(io::CsvTable::Text(row.outcome.message));
    run["message"] = row.outcome.message;
    table.AddCells(std::move(cells));
    runs.push_back(std::move(run));
  }
  files.Add("sweep.csv", table.ToString());
  nlohmann::json& json = files.json();
  json["case"] = base.name;
  json["runs"] = runs;
  nlohmann::json units_json = nlohmann::json::object();
  for (const HeadlineColumn& column : kHeadlines) {
    units_json[column.name] =
        column.quantity == Quantity::Dimensionless ? "-" : std::string(units::DefaultUnit(column.quantity, system));
  }
  json["units"] = units_json;
  return files;
}

}  // namespace drillflex::pipeline
