// Runs the drillflex command line on a validation case and reads its results.json.
#pragma once

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace drillflex::validation {

inline std::string CasePath(const std::string& relative) {
  return (std::filesystem::path(DRILLFLEX_SOURCE_DIR "/validation") / relative).string();
}

// Runs `drillflex <command> <case> -o <dir>` and returns results.json (fails the test on a
// non-zero exit status).
// The directory a case's results go to: build-test/validation-results/<case without its extension>.
inline std::string ResultsDirectory(const std::string& relative_case) {
  return (std::filesystem::path(DRILLFLEX_BINARY_DIR "/validation-results") /
          std::filesystem::path(relative_case).replace_extension())
      .string();
}

// `run_name` gives the run its own results directory: two tests of one case run concurrently under
// ctest -j, and each clears its directory first (the other then read a half-written one).
inline nlohmann::json RunCase(const std::string& command, const std::string& relative_case,
                              const std::string& run_name = "") {
  const std::string output = ResultsDirectory(relative_case) + (run_name.empty() ? "" : "-" + run_name);
  std::filesystem::remove_all(output);
  const std::string log = output + ".log";
  std::filesystem::create_directories(std::filesystem::path(log).parent_path());
  const std::string line = fmt::format("{} {} {} -o {} > {} 2>&1", DRILLFLEX_EXE, command, CasePath(relative_case), output, log);
  const int status = std::system(line.c_str());
  if (status != 0) {
    std::ifstream text(log);
    std::string contents((std::istreambuf_iterator<char>(text)), std::istreambuf_iterator<char>());
    ADD_FAILURE() << line << " exited with " << status << ":\n" << contents;
    return nlohmann::json::object();
  }
  std::ifstream file(output + "/results.json");
  return nlohmann::json::parse(file);
}

// RunCase, printing and recording (test property run_time_s) its wall time and the model's size.
// The time is reported, never asserted (no timed tests).
inline nlohmann::json RunCaseTimed(const std::string& command, const std::string& relative_case) {
  const auto start = std::chrono::steady_clock::now();
  auto results = RunCase(command, relative_case);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto model = results.value("model", nlohmann::json::object());
  std::printf("%s: drillflex %s ran %.2f s (%d bodies, %d coordinates, %d contacts)\n", relative_case.c_str(),
              command.c_str(), seconds, model.value("bodies", 0), model.value("coordinates", 0),
              model.value("contacts", 0));
  ::testing::Test::RecordProperty("run_time_s", std::to_string(seconds));
  return results;
}

inline double RelativeError(double value, double reference) { return value / reference - 1.0; }

// The columns of a CSV file with a header line, by name.
struct CsvColumns {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;
  const std::vector<double>& operator[](const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == name) return values[i];
    }
    throw std::runtime_error("no column " + name);
  }
};

inline CsvColumns ReadCsv(const std::string& path) {
  std::ifstream file(path);
  CsvColumns table;
  std::string line, cell;
  std::getline(file, line);
  std::stringstream header(line);
  while (std::getline(header, cell, ',')) table.names.push_back(cell);
  table.values.resize(table.names.size());
  std::getline(file, line);  // the units line (io::CsvTable)
  while (std::getline(file, line)) {
    std::stringstream row(line);
    for (std::size_t i = 0; i < table.names.size() && std::getline(row, cell, ','); ++i) {
      table.values[i].push_back(std::stod(cell));
    }
  }
  return table;
}

}  // namespace drillflex::validation
