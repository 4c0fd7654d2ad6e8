#include "io/result_files.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"

namespace drillflex::io {

void ResultFiles::Add(std::string name, std::string content) {
  files_.emplace_back(std::move(name), std::move(content));
}

std::vector<std::string> ResultFiles::Commit() const {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::create_directories(directory_, error);
  if (error) {
    throw std::runtime_error(fmt::format("cannot create the output directory '{}': {}", directory_, error.message()));
  }
  std::vector<std::string> written;
  for (const auto& [name, content] : files_) {
    const std::string path = (fs::path(directory_) / name).string();
    WriteFileAtomically(path, content);
    written.push_back(path);
  }
  const std::string json_path = (fs::path(directory_) / json_name_).string();
  WriteFileAtomically(json_path, json_.dump(2) + "\n");
  written.push_back(json_path);
  return written;
}

void WriteFileAtomically(const std::string& path, const std::string& content) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error(fmt::format("cannot write '{}': {}", temporary, std::strerror(errno)));
    file << content;
    file.flush();
    if (!file) throw std::runtime_error(fmt::format("cannot write '{}': {}", temporary, std::strerror(errno)));
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error(fmt::format("cannot move '{}' into place: {}", path, error.message()));
  }
}

CsvTable::CsvTable(std::vector<std::string> columns, std::vector<std::string> units)
    : columns_(std::move(columns)), units_(std::move(units)) {
  if (units_.size() != columns_.size()) {
    throw LogicError(fmt::format("CSV table of {} columns with {} units", columns_.size(), units_.size()));
  }
}

void CsvTable::AddRow(const std::vector<double>& values) {
  std::vector<std::string> cells;
  cells.reserve(values.size());
  for (const double value : values) cells.push_back(Number(value));
  AddCells(std::move(cells));
}

void CsvTable::AddCells(std::vector<std::string> cells) {
  if (cells.size() != columns_.size()) {
    throw LogicError(fmt::format("CSV row of {} values for {} columns", cells.size(), columns_.size()));
  }
  rows_.push_back(std::move(cells));
}

std::string CsvTable::Number(double value) { return fmt::format("{:.10g}", value + 0.0); }  // + 0.0: no "-0"

std::string CsvTable::Text(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

std::string CsvTable::ToString() const {
  std::string text;
  for (std::size_t c = 0; c < columns_.size(); ++c) text.append(c ? "," : "").append(columns_[c]);
  text.append("\n");
  for (std::size_t c = 0; c < units_.size(); ++c) text.append(c ? "," : "").append(units_[c]);
  text.append("\n");
  for (const auto& row : rows_) {
    for (std::size_t c = 0; c < row.size(); ++c) text.append(c ? "," : "").append(row[c]);
    text.append("\n");
  }
  return text;
}

}  // namespace drillflex::io
