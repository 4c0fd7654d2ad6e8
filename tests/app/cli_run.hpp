// Running the drillflex command line from the app tests as a user would: a shell command's exit
// status and its output (standard output and error together), and fresh directories for its files.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace drillflex::test_cli {

struct RunResult {
  int status = -1;
  std::string output;
};

inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// Runs `command` in a shell. One log per test process: CTest runs the tests of a file in parallel
// processes, which would otherwise read each other's output.
inline RunResult RunShell(const std::string& command) {
  const std::filesystem::path log =
      std::filesystem::temp_directory_path() / ("drillflex-cli-test-" + std::to_string(::getpid()) + ".log");
  const int raw = std::system((command + " > " + log.string() + " 2>&1").c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, ReadFile(log)};
}

// An empty directory's path below the temporary directory (created by whoever writes into it).
inline std::filesystem::path FreshDirectory(const std::string& group, const std::string& name) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / group / name;
  std::filesystem::remove_all(directory);
  return directory;
}

}  // namespace drillflex::test_cli
