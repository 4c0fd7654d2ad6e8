// Result files of one job, written atomically: every file is composed in memory first, then each
// is written to a temporary name in the output directory and renamed into place, results.json
// last. A job that fails before Commit() leaves no result files at all.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace drillflex::io {

class ResultFiles {
 public:
  explicit ResultFiles(std::string directory) : directory_(std::move(directory)) {}

  const std::string& directory() const { return directory_; }
  void Add(std::string name, std::string content);
  nlohmann::json& json() { return json_; }

  // Writes every file and results.json; returns the paths written. Throws std::runtime_error
  // (with the path and the system's reason) when the directory or a file cannot be written.
  std::vector<std::string> Commit() const;

 private:
  std::string directory_;
  std::vector<std::pair<std::string, std::string>> files_;
  nlohmann::json json_ = nlohmann::json::object();
};

// Writes `content` to `path` through a temporary file and a rename.
void WriteFileAtomically(const std::string& path, const std::string& content);

// A CSV table: a header and rows of numbers, written with full precision.
class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}
  void AddRow(const std::vector<double>& values);
  std::string ToString() const;
  std::size_t rows() const { return rows_.size(); }

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
};

}  // namespace drillflex::io
