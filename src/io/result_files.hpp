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
  // `json_name`: the JSON file written last (results.json; a sweep's sweep.json).
  explicit ResultFiles(std::string directory, std::string json_name = "results.json")
      : directory_(std::move(directory)), json_name_(std::move(json_name)) {}

  const std::string& directory() const { return directory_; }
  void Add(std::string name, std::string content);
  nlohmann::json& json() { return json_; }
  const nlohmann::json& json() const { return json_; }
  // The files Add()ed so far (name, content), results.json not among them.
  const std::vector<std::pair<std::string, std::string>>& files() const { return files_; }

  // Writes every file and the JSON file last; returns the paths written. Throws std::runtime_error
  // (with the path and the system's reason) when the directory or a file cannot be written.
  std::vector<std::string> Commit() const;

 private:
  std::string directory_;
  std::string json_name_;
  std::vector<std::pair<std::string, std::string>> files_;
  nlohmann::json json_ = nlohmann::json::object();
};

// Writes `content` to `path` through a temporary file and a rename.
void WriteFileAtomically(const std::string& path, const std::string& content);

// A CSV table: a header line of column names, a second line with each column's unit ("-" for a
// pure number: a ratio, a count, an index), then rows of numbers with full precision. The names stay
// what results.json calls the same quantities; the units are the case's output units
// (case-format.md "Command line and results": pandas reads it with header=[0, 1] or skiprows=[1]).
class CsvTable {
 public:
  // `units[i]` is the unit of `columns[i]`; both as many.
  CsvTable(std::vector<std::string> columns, std::vector<std::string> units);
  void AddRow(const std::vector<double>& values);
  // A row of cells already written: Number(x) for a number, Text(s) for a name.
  void AddCells(std::vector<std::string> cells);
  static std::string Number(double value);
  static std::string Text(const std::string& text);  // quoted when it holds a comma, a quote or a line break
  std::string ToString() const;
  std::size_t rows() const { return rows_.size(); }

 private:
  std::vector<std::string> columns_;
  std::vector<std::string> units_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace drillflex::io
