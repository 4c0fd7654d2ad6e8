// ReadRigReadings: a readings CSV or WITSML log told apart by its first character, and what the CSV and
// log readers share (io/rig_readings_rows.hpp).
#include "io/rig_readings.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/rig_readings_rows.hpp"

namespace drillflex::io {

std::optional<double> ParseNumber(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return std::nullopt;
  text = text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
  if (text.starts_with('+')) text.remove_prefix(1);  // from_chars reads no plus sign
  double number = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, number);
  if (text.empty() || error != std::errc() || stop != end || !std::isfinite(number)) return std::nullopt;
  return number;
}

double FactorToSi(std::string_view unit, units::Quantity quantity,
                  const std::function<void(const std::string&)>& fail) {
  const std::string expected =
      fmt::format("{} (such as {} or {})", units::QuantityName(quantity),
                  units::DefaultUnit(quantity, units::System::SI), units::DefaultUnit(quantity, units::System::Field));
  const auto first = unit.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos || unit.substr(first) == "-") fail("no unit: expected the unit of " + expected);
  units::Unit parsed;
  try {
    parsed = units::ParseUnit(unit);
  } catch (const UnitError& error) { fail(fmt::format("expected the unit of {}: {}", expected, error.what())); }
  if (!(parsed.dimension == units::DimensionOf(quantity))) {
    fail(fmt::format("unit \"{}\" is {}, but {} is expected", unit, units::DimensionName(parsed.dimension), expected));
  }
  if (!(std::isfinite(parsed.to_si) && parsed.to_si > 0.0)) fail(fmt::format("unit \"{}\" is out of range", unit));
  return parsed.to_si;
}

std::string DepthProblem(double bit_md, const RigReadingsOptions& options) {
  if (bit_md < 0.0) return fmt::format("the bit depth {:.6g} m is negative: expected a depth in the well", bit_md);
  // A millimetre's leeway: a reading at the well's bottom written with fewer digits than the survey.
  if (options.deepest_md && bit_md > *options.deepest_md + 1e-3) {
    return fmt::format("the bit depth {:.6g} m lies beyond the well's bottom at {:.6g} m", bit_md, *options.deepest_md);
  }
  return "";
}

RigReadings KeptReadings(const std::string& file, const std::vector<RigReading>& rows,
                         std::vector<std::string> warnings, const SourceLocation& where, const std::string& no_rows) {
  RigReadings readings;
  readings.file = file;
  std::map<RigActivity, int> left_out;
  for (const RigReading& row : rows) {
    if (IsModelledActivity(row.activity)) {
      readings.rows.push_back(row);
    } else {
      ++left_out[row.activity];
    }
  }
  if (!left_out.empty()) {
    std::string counts;
    for (const auto& [activity, count] : left_out) {
      counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", count, RigActivityName(activity));
    }
    warnings.push_back(
        fmt::format("{}: {} rows left out ({}): only drilling, rotating, pick_up and slack_off "
                    "readings are modelled",
                    file, rows.size() - readings.rows.size(), counts));
  }
  if (readings.rows.empty()) {
    throw InputError(where, "",
                     rows.empty() ? no_rows : no_rows + ": no drilling, rotating, pick_up or slack_off reading");
  }
  readings.warnings = std::move(warnings);
  return readings;
}

RigReadings ParseRigReadings(std::string_view text, const std::string& file, const RigReadingsOptions& options) {
  std::string_view body = text;
  if (body.starts_with("\xEF\xBB\xBF")) body.remove_prefix(3);  // a UTF-8 byte order mark
  const auto first = body.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && body[first] == '<') return ParseRigReadingsWitsml(text, file, options);
  return ParseRigReadingsCsv(text, file, options);
}

RigReadings ReadRigReadings(const std::string& path, const RigReadingsOptions& options) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError({path, 0, 0}, "", "cannot open the readings file");
  std::ostringstream text;
  text << stream.rdbuf();
  return ParseRigReadings(text.str(), path, options);
}

}  // namespace drillflex::io
