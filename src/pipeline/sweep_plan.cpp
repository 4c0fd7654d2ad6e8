#include "pipeline/sweep_plan.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "core/error.hpp"

namespace drillflex::pipeline {
namespace {

constexpr const char* kVaryFile = "--vary";

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream stream(text);
  while (std::getline(stream, part, separator)) parts.push_back(Trim(part));
  if (!text.empty() && text.back() == separator) parts.push_back("");
  return parts;
}

bool ParseNumber(const std::string& text, double& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && ptr == end && std::isfinite(value);
}

// "FROM:TO:STEP UNIT" → the values with the unit appended.
std::vector<std::string> ExpandRange(const std::string& key, const std::string& range) {
  // The unit: what follows the last number (after the first space past the third field).
  const auto space = range.find(' ');
  const std::string numbers = Trim(range.substr(0, space));
  const std::string unit = space == std::string::npos ? "" : Trim(range.substr(space));
  const std::vector<std::string> fields = Split(numbers, ':');
  double from = 0.0, to = 0.0, step = 0.0;
  if (fields.size() != 3 || !ParseNumber(fields[0], from) || !ParseNumber(fields[1], to) ||
      !ParseNumber(fields[2], step)) {
    throw InputError({kVaryFile, 0, 0}, key,
                     fmt::format("expected a range FROM:TO:STEP with an optional unit (10:40:5 klbf), got '{}'", range));
  }
  if (step == 0.0 || (to - from) * step < 0.0) {
    throw InputError({kVaryFile, 0, 0}, key,
                     fmt::format("the step {} does not lead from {} to {}", fields[2], fields[0], fields[1]));
  }
  // Each value from its index (no summed round-off), printed with 12 significant digits so that
  // 0.1 × 3 reads 0.3; TO is included when a step lands within 1e-9 of a step of it.
  const double count = std::floor((to - from) / step + 1e-9);
  if (count + 1.0 > kMaxSweepValues) {
    throw InputError({kVaryFile, 0, 0}, key,
                     fmt::format("the range '{}' has {:.0f} values, more than {}", range, count + 1.0, kMaxSweepValues));
  }
  std::vector<std::string> values;
  for (int k = 0; k <= static_cast<int>(count); ++k) {
    const double value = from + k * step;
    const std::string number = fmt::format("{:.12g}", value == 0.0 ? 0.0 : value);
    values.push_back(unit.empty() ? number : number + " " + unit);
  }
  return values;
}

// One CSV line's cells: separated by commas, a cell in double quotes may hold commas ("" is a quote).
std::vector<std::string> CsvCells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell.push_back('"');
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        cell.push_back(ch);
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      cells.push_back(Trim(cell));
      cell.clear();
    } else {
      cell.push_back(ch);
    }
  }
  cells.push_back(Trim(cell));
  return cells;
}

}  // namespace

SweepAxis ParseSweepAxis(const std::string& spec) {
  const auto equals = spec.find('=');
  if (equals == std::string::npos) {
    throw InputError({kVaryFile, 0, 0}, "", fmt::format("expected KEY=VALUES (operation.rpm=60,120,180), got '{}'", spec));
  }
  SweepAxis axis{Trim(spec.substr(0, equals)), {}};
  const std::string values = Trim(spec.substr(equals + 1));
  if (axis.key.empty()) throw InputError({kVaryFile, 0, 0}, "", fmt::format("no key before '=' in '{}'", spec));
  if (values.empty()) throw InputError({kVaryFile, 0, 0}, axis.key, "no values after '='");
  if (values.find(':') != std::string::npos && values.find(',') == std::string::npos) {
    axis.values = ExpandRange(axis.key, values);
  } else {
    axis.values = Split(values, ',');
    for (const std::string& value : axis.values) {
      if (value.empty()) throw InputError({kVaryFile, 0, 0}, axis.key, fmt::format("an empty value in '{}'", values));
    }
  }
  return axis;
}

std::vector<SweepCombination> SweepCombinations(const std::vector<SweepAxis>& axes) {
  std::set<std::string> keys;
  double count = 1.0;
  for (const SweepAxis& axis : axes) {
    if (!keys.insert(axis.key).second) throw InputError({kVaryFile, 0, 0}, axis.key, "the key is varied twice");
    count *= static_cast<double>(axis.values.size());
  }
  if (count > kMaxSweepValues) {
    throw InputError({kVaryFile, 0, 0}, "", fmt::format("{:.0f} combinations, more than {}", count, kMaxSweepValues));
  }
  std::vector<SweepCombination> combinations(1);
  for (const SweepAxis& axis : axes) {
    std::vector<SweepCombination> next;
    next.reserve(combinations.size() * axis.values.size());
    for (const SweepCombination& prefix : combinations) {
      for (const std::string& value : axis.values) {
        SweepCombination combination = prefix;
        combination.push_back({axis.key, value});
        next.push_back(std::move(combination));
      }
    }
    combinations = std::move(next);
  }
  return combinations;
}

std::vector<SweepCombination> SweepRowsFromCsv(const std::string& path) {
  std::ifstream stream(path);
  if (!stream) throw InputError({path, 0, 0}, "", "cannot open the table of cases");
  std::vector<std::string> keys;
  std::vector<SweepCombination> rows;
  std::string line;
  int line_number = 0;
  while (std::getline(stream, line)) {
    ++line_number;
    const std::string trimmed = Trim(line);
    if (trimmed.empty() || trimmed.front() == '#') continue;
    const std::vector<std::string> cells = CsvCells(trimmed);
    if (keys.empty()) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].empty()) {
          throw InputError({path, line_number, 0}, "", fmt::format("the header's column {} names no key", i + 1));
        }
      }
      keys = cells;
      continue;
    }
    if (cells.size() != keys.size()) {
      throw InputError({path, line_number, 0}, "",
                       fmt::format("{} cells where the header names {} keys", cells.size(), keys.size()));
    }
    SweepCombination row;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (cells[i].empty()) throw InputError({path, line_number, 0}, keys[i], "an empty value");
      row.push_back({keys[i], cells[i]});
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError({path, line_number, 0}, "", "the table has no rows of cases");
  return rows;
}

}  // namespace drillflex::pipeline
