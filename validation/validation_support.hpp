// Runs the drillflex command line on a validation case and reads its results.json.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace drillflex::validation
