#include "io/survey_csv.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/types.hpp"

namespace drillflex::io {
namespace {

// Cells as std::getline(line, cell, ',') cuts them (what the reader did on the file): an empty line
// has none, and a comma at the very end of a line opens no cell.
std::vector<std::string> SplitCsvLine(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (start < line.size()) {
    const std::size_t comma = std::min(line.find(',', start), line.size());
    const std::string_view cell = line.substr(start, comma - start);
    const auto first = cell.find_first_not_of(" \t\r");
    const auto last = cell.find_last_not_of(" \t\r");
    cells.emplace_back(first == std::string_view::npos ? "" : cell.substr(first, last - first + 1));
    start = comma + 1;
  }
  return cells;
}

}  // namespace

well::SurveyStation NormalizedStation(double md, double inclination, double azimuth) {
  azimuth = std::fmod(azimuth, 2.0 * kPi);
  if (azimuth < 0.0) azimuth += 2.0 * kPi;
  return {md, inclination, azimuth};
}

void CheckStation(const well::SurveyStation& station, const well::SurveyStation* previous,
                  const std::function<void(const std::string&)>& fail) {
  if (station.md < 0.0) fail("the MD must not be negative");
  if (station.inclination < 0.0 || station.inclination > kPi + 1e-12) {
    fail(fmt::format("the inclination must lie between 0 and 180 deg, got {:.6g} deg",
                     station.inclination / kDegree));
  }
  if (previous && !(station.md > previous->md)) {
    fail(fmt::format("the survey's MD must strictly increase: {:.6g} m follows {:.6g} m",
                     station.md, previous->md));
  }
}

std::vector<well::SurveyStation> ParseSurveyCsv(std::string_view text, const std::string& file,
                                                units::System system) {
  std::vector<well::SurveyStation> stations;
  int line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    const auto cells = SplitCsvLine(line);
    const bool blank = cells.empty() || (cells.size() == 1 && cells[0].empty());
    if (blank || cells[0].starts_with('#')) continue;
    auto fail = [&](const std::string& message) {
      throw InputError({file, line_number, 0}, "well.survey_file", message);
    };
    if (cells.size() != 3) fail(fmt::format("expected 3 columns (MD, inclination, azimuth), got {}", cells.size()));
    double values[3];
    bool numeric = true;
    const units::Quantity kinds[3] = {units::Quantity::Length, units::Quantity::Angle, units::Quantity::Angle};
    for (int c = 0; c < 3; ++c) {
      try {
        values[c] = units::ParseQuantity(cells[c], kinds[c], system);
      } catch (const UnitError& error) {
        if (stations.empty() && c == 0) { numeric = false; break; }  // a header line
        fail(error.what());
      }
    }
    if (!numeric) continue;
    const auto station = NormalizedStation(values[0], values[1], values[2]);
    CheckStation(station, stations.empty() ? nullptr : &stations.back(), fail);
    stations.push_back(station);
  }
  return stations;
}

}  // namespace drillflex::io
