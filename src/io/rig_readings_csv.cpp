// ParseRigReadingsCsv: a readings CSV (../shared/spec/case-format.md "Rig readings"): a header, a line
// of units, one row a reading; every value checked where it stands.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/rig_readings.hpp"
#include "io/rig_readings_rows.hpp"

namespace drillflex::io {
namespace {

struct Cell {
  std::string text;  // white space trimmed
  int column = 0;    // 1-based character column of its first character
};

// The cells of a line cut at every comma (no quoting: the contract's values hold no commas).
std::vector<Cell> SplitCells(std::string_view line) {
  std::vector<Cell> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = std::min(line.find(',', start), line.size());
    const std::string_view cell = line.substr(start, comma - start);
    const auto first = cell.find_first_not_of(" \t\r");
    const auto last = cell.find_last_not_of(" \t\r");
    const bool empty = first == std::string_view::npos;
    cells.push_back({empty ? "" : std::string(cell.substr(first, last - first + 1)),
                     static_cast<int>(start + (empty ? 0 : first)) + 1});
    if (comma == line.size()) return cells;
    start = comma + 1;
  }
}

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// A numeric column of the contract: its name, its quantity, and whether a row may leave it empty.
struct NumericColumn {
  const char* name;
  units::Quantity quantity;
  bool optional;
};

// None may be negative: a depth in the well, a hook load, a torque's and a WOB's magnitude, a speed.
constexpr NumericColumn kNumeric[] = {{"bit_md", units::Quantity::Length, false},
                                      {"hook_load", units::Quantity::Force, false},
                                      {"surface_torque", units::Quantity::Moment, true},
                                      {"wob", units::Quantity::WeightOnBit, false},
                                      {"rpm", units::Quantity::RotarySpeed, false}};
constexpr std::size_t kBitMd = 0, kHookLoad = 1, kTorque = 2, kWob = 3, kRpm = 4;
constexpr const char* kRequired = "bit_md, activity, hook_load, surface_torque, wob, rpm";

// The file's lines as the reader walks them: blank lines and '#' comments skipped.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {
    if (text_.starts_with("\xEF\xBB\xBF")) text_.remove_prefix(3);  // a UTF-8 byte order mark
  }
  // The next line that holds something, with its number; false at the end.
  bool Next(std::string_view& line, int& number) {
    while (start_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', start_), text_.size());
      line = text_.substr(start_, end - start_);
      start_ = end + 1;
      ++number_;
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string_view::npos || line[first] == '#') continue;
      number = number_;
      return true;
    }
    return false;
  }
  int last_line() const { return std::max(number_, 1); }

 private:
  std::string_view text_;
  std::size_t start_ = 0;
  int number_ = 0;
};

}  // namespace

RigReadings ParseRigReadingsCsv(std::string_view text, const std::string& file, const RigReadingsOptions& options) {
  Lines lines(text);
  std::string_view line;
  int number = 0;
  const auto fail_at = [&](int at_line, int column, const std::string& key, const std::string& message) {
    throw InputError({file, at_line, column}, key, message);
  };
  const std::string no_rows = "the readings file holds no reading: expected a header (" + std::string(kRequired) +
                              "), a line of units and a row a reading";
  if (!lines.Next(line, number)) fail_at(lines.last_line(), 0, "", no_rows);

  // The header: each name once; the contract's columns all present.
  const int header_line = number;
  const std::vector<Cell> header = SplitCells(line);
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const Cell& cell : header) {
    names.push_back(Lower(cell.text));
    if (!seen.insert(names.back()).second && !names.back().empty()) {
      fail_at(header_line, cell.column, names.back(), "the column is named twice in the header");
    }
  }
  const auto column_of = [&](std::string_view name) {
    const auto at = std::find(names.begin(), names.end(), name);
    if (at == names.end()) {
      fail_at(header_line, 1, std::string(name),
              fmt::format("the header has no column '{}': expected the columns {} (in any order; others are "
                          "ignored)",
                          name, kRequired));
    }
    return static_cast<std::size_t>(at - names.begin());
  };
  std::size_t numeric_column[std::size(kNumeric)];
  for (std::size_t i = 0; i < std::size(kNumeric); ++i) numeric_column[i] = column_of(kNumeric[i].name);
  const std::size_t activity_column = column_of("activity");

  // The units: each numeric column's, through the unit layer; the activity's "-" (or nothing).
  if (!lines.Next(line, number)) {
    fail_at(lines.last_line(), 0, "",
            "the readings file ends after its header: expected a line of units (such as "
            "m,-,kN,kN*m,kN,rpm) and a row a reading");
  }
  const int units_line = number;
  const std::vector<Cell> unit_cells = SplitCells(line);
  const auto unit_cell = [&](std::size_t column) {
    return column < unit_cells.size() ? unit_cells[column] : Cell{"", static_cast<int>(line.size()) + 1};
  };
  double factor[std::size(kNumeric)];
  for (std::size_t i = 0; i < std::size(kNumeric); ++i) {
    const Cell cell = unit_cell(numeric_column[i]);
    factor[i] = FactorToSi(cell.text, kNumeric[i].quantity, [&](const std::string& message) {
      fail_at(units_line, cell.column, kNumeric[i].name, "the second line's unit: " + message);
    });
  }
  if (const Cell cell = unit_cell(activity_column); !cell.text.empty() && cell.text != "-") {
    fail_at(units_line, cell.column, "activity",
            fmt::format("the second line's unit: the activity is a name, expected '-' (no unit), got '{}'", cell.text));
  }

  // The rows.
  std::vector<RigReading> rows;
  while (lines.Next(line, number)) {
    const std::vector<Cell> cells = SplitCells(line);
    if (cells.size() > header.size()) {
      fail_at(number, cells[header.size()].column, "",
              fmt::format("expected at most {} values (the header's columns), got {}", header.size(), cells.size()));
    }
    const auto cell_at = [&](std::size_t column) {
      return column < cells.size() ? cells[column] : Cell{"", static_cast<int>(line.size()) + 1};
    };
    RigReading reading;
    reading.line = number;
    std::optional<double> values[std::size(kNumeric)];
    for (std::size_t i = 0; i < std::size(kNumeric); ++i) {
      const NumericColumn& column = kNumeric[i];
      const Cell cell = cell_at(numeric_column[i]);
      const auto fail = [&](const std::string& message) { fail_at(number, cell.column, column.name, message); };
      const std::string expected =
          fmt::format("{} in {}", units::QuantityName(column.quantity), unit_cell(numeric_column[i]).text);
      if (cell.text.empty()) {
        if (column.optional) continue;
        fail("no value: expected " + expected);
      }
      const std::optional<double> value = ParseNumber(cell.text);
      if (!value) fail(fmt::format("expected a number ({}), got '{}'", expected, cell.text));
      values[i] = *value * factor[i];
      if (!std::isfinite(*values[i])) fail(fmt::format("{} is out of range", cell.text));
      if (*values[i] < 0.0) fail(fmt::format("expected {} not negative, got {}", expected, cell.text));
    }
    reading.bit_md = *values[kBitMd];
    reading.hook_load = *values[kHookLoad];
    reading.surface_torque = values[kTorque];
    reading.weight_on_bit = *values[kWob];
    reading.rotary_speed = *values[kRpm];
    if (const std::string problem = DepthProblem(reading.bit_md, options); !problem.empty()) {
      fail_at(number, cell_at(numeric_column[kBitMd]).column, "bit_md", problem);
    }
    const Cell activity = cell_at(activity_column);
    const std::optional<RigActivity> known = RigActivityOfName(Lower(activity.text));
    if (!known) {
      fail_at(number, activity.column, "activity",
              fmt::format("unknown activity '{}': expected drilling (on bottom, rotating), rotating (off bottom), "
                          "pick_up, slack_off, in_slips or other",
                          activity.text));
    }
    reading.activity = *known;
    rows.push_back(reading);
  }
  return KeptReadings(file, rows, {}, {file, rows.empty() ? lines.last_line() : header_line, 0}, no_rows);
}

}  // namespace drillflex::io
