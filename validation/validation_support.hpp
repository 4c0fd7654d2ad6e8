// Runs the drillflex command line on a validation case and reads its results.json.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace drillflex::validation {

inline std::string CasePath(const std::string& relative) {
  return std::string(DRILLFLEX_SOURCE_DIR) + "/validation/" + relative;
}

// Runs `drillflex <command> <case> -o <dir>` and returns results.json (fails the test on a
// non-zero exit status).
inline nlohmann::json RunCase(const std::string& command, const std::string& relative_case) {
  const std::string output = std::string(DRILLFLEX_BINARY_DIR) + "/validation-results/" +
                             std::filesystem::path(relative_case).replace_extension().string();
  std::filesystem::remove_all(output);
  const std::string log = output + ".log";
  std::filesystem::create_directories(std::filesystem::path(log).parent_path());
  const std::string line = std::string(DRILLFLEX_EXE) + " " + command + " " + CasePath(relative_case) + " -o " +
                           output + " > " + log + " 2>&1";
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
  while (std::getline(file, line)) {
    std::stringstream row(line);
    for (std::size_t i = 0; i < table.names.size() && std::getline(row, cell, ','); ++i) {
      table.values[i].push_back(std::stod(cell));
    }
  }
  return table;
}

}  // namespace drillflex::validation
