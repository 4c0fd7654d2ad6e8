// Reads `well:`: the survey (inline or from a CSV file), the hole sections and the bit MD.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <fmt/format.h>

#include "io/case_sections.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

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

well::SurveyStation NormalizedStation(double md, double inclination, double azimuth) {
  azimuth = std::fmod(azimuth, 2.0 * kPi);
  if (azimuth < 0.0) azimuth += 2.0 * kPi;
  return {md, inclination, azimuth};
}

std::vector<well::SurveyStation> ReadInlineSurvey(const YamlView& node) {
  node.ExpectSequence("survey stations [MD, inclination, azimuth]");
  std::vector<well::SurveyStation> stations;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlView row = node.Item(i);
    if (!row.IsSequence() || row.size() != 3) {
      row.Fail("expected a survey station [MD, inclination, azimuth]");
    }
    const auto station = NormalizedStation(row.Item(0).AsQuantity(Quantity::Length),
                                           row.Item(1).AsQuantity(Quantity::Angle),
                                           row.Item(2).AsQuantity(Quantity::Angle));
    CheckStation(station, stations.empty() ? nullptr : &stations.back(),
                 [&](const std::string& message) { row.Fail(message); });
    stations.push_back(station);
  }
  return stations;
}

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream stream(line);
  while (std::getline(stream, cell, ',')) {
    const auto first = cell.find_first_not_of(" \t\r");
    const auto last = cell.find_last_not_of(" \t\r");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  return cells;
}

// A survey CSV: three columns MD, inclination, azimuth in the case's units; a header line allowed.
std::vector<well::SurveyStation> ReadSurveyFile(const YamlView& node, const std::string& directory) {
  const std::string given = node.AsString();
  const std::filesystem::path path = std::filesystem::path(given).is_absolute()
                                         ? std::filesystem::path(given)
                                         : std::filesystem::path(directory) / given;
  std::ifstream file(path);
  if (!file) node.Fail(fmt::format("cannot read the survey file '{}'", path.string()));
  std::vector<well::SurveyStation> stations;
  std::string line;
  int line_number = 0;
  const units::System system = node.context().system;
  while (std::getline(file, line)) {
    ++line_number;
    const auto cells = SplitCsvLine(line);
    const bool blank = cells.empty() || (cells.size() == 1 && cells[0].empty());
    if (blank || cells[0].rfind('#', 0) == 0) continue;
    auto fail = [&](const std::string& message) {
      throw InputError({path.string(), line_number, 0}, "well.survey_file", message);
    };
    if (cells.size() != 3) fail(fmt::format("expected 3 columns (MD, inclination, azimuth), got {}", cells.size()));
    double values[3];
    bool numeric = true;
    const Quantity kinds[3] = {Quantity::Length, Quantity::Angle, Quantity::Angle};
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
  if (stations.size() < 2) node.Fail(fmt::format("the survey file '{}' has fewer than two stations", path.string()));
  return stations;
}

std::vector<well::HoleSection> ReadHole(const YamlView& node) {
  if (node.IsScalar()) return {{std::nullopt, node.AsPositive(Quantity::Diameter), std::nullopt}};
  node.ExpectSequence("hole sections {to, diameter}");
  std::vector<well::HoleSection> sections;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlView item = node.Item(i);
    item.ExpectMap("a hole section {to: MD, diameter: D}", false);
    item.AllowOnlyKeys({"to", "diameter", "diameter_at_end"});
    well::HoleSection section;
    section.to_md = item.OptionalPositive("to", Quantity::Length);
    section.diameter = item.Positive("diameter", Quantity::Diameter);
    section.diameter_at_end = item.OptionalPositive("diameter_at_end", Quantity::Diameter);
    const bool last = i + 1 == node.size();
    if (!last && !section.to_md) item.Fail("only the last hole section may omit 'to' (it runs to the bottom)");
    if (last && section.diameter_at_end && !section.to_md) {
      item.Fail("a tapered last section ('diameter_at_end') needs 'to', the MD where it ends");
    }
    if (last && section.to_md && !section.diameter_at_end) section.to_md.reset();  // runs to the bottom
    if (!sections.empty() && section.to_md && !(*section.to_md > *sections.back().to_md)) {
      item.Child("to").Fail("hole sections must be listed top down with increasing 'to'");
    }
    sections.push_back(section);
  }
  return sections;
}

// `witsml:`: the survey of the one trajectory among the documents, and the hole of their one
// wbGeometry unless the case gives `hole`.
void ReadWitsmlWell(const YamlView& node, const std::string& directory, bool needs_hole, WellConfig& well,
                    std::vector<std::string>& warnings) {
  const auto documents = ReadWitsmlKey(node, directory, warnings);
  std::vector<const WitsmlTrajectory*> trajectories;
  std::vector<const WitsmlGeometry*> geometries;
  for (const auto& document : documents) {
    for (const auto& trajectory : document.trajectories) trajectories.push_back(&trajectory);
    for (const auto& geometry : document.geometries) geometries.push_back(&geometry);
  }
  if (trajectories.size() != 1) {
    node.Fail(fmt::format("expected one trajectory among the WITSML documents, found {}", trajectories.size()));
  }
  well.survey = SurveyOf(*trajectories.front());
  well.survey_file = trajectories.front()->origin.file;
  if (!needs_hole) return;
  if (geometries.size() != 1) {
    node.Fail(fmt::format("expected one wbGeometry among the WITSML documents (or the well's 'hole'), found {}",
                          geometries.size()));
  }
  well.hole = HoleOf(*geometries.front());
}

}  // namespace

WellConfig ReadWellSection(const YamlView& node, const std::string& directory, std::vector<std::string>& warnings) {
  node.ExpectMap("the well", false);
  node.AllowOnlyKeys({"survey", "survey_file", "witsml", "hole", "bit_md", "output_step"});
  WellConfig well;
  if (int(node.Has("survey")) + int(node.Has("survey_file")) + int(node.Has("witsml")) != 1) {
    node.Fail("give exactly one of 'survey' (a list of [MD, inclination, azimuth]), 'survey_file' or 'witsml' "
              "(WITSML trajectory and wbGeometry documents)");
  }
  if (const auto witsml = node.OptionalChild("witsml")) {
    ReadWitsmlWell(*witsml, directory, !node.Has("hole"), well, warnings);
  } else if (const auto survey = node.OptionalChild("survey")) {
    well.survey = ReadInlineSurvey(*survey);
    if (well.survey.size() < 2) survey->Fail("a survey needs at least two stations");
  } else {
    const YamlView file = node.Child("survey_file");
    well.survey_file = file.AsString();
    well.survey = ReadSurveyFile(file, directory);
  }
  if (!node.Has("witsml") || node.Has("hole")) well.hole = ReadHole(node.Child("hole"));
  well.bit_md = well.survey.back().md;
  if (const auto bit = node.OptionalChild("bit_md")) {
    well.bit_md = bit->AsPositive(Quantity::Length);
    if (well.bit_md > well.survey.back().md * (1.0 + 1e-12)) {
      bit->Fail(fmt::format("the bit MD lies beyond the last survey station ({:.6g} {})",
                            units::FromSI(well.survey.back().md, Quantity::Length, node.context().system),
                            units::DefaultUnit(Quantity::Length, node.context().system)));
    }
  }
  const double default_step = node.context().system == units::System::Field ? 30.0 * 0.3048 : 10.0;
  well.output_step = node.Has("output_step") ? node.Positive("output_step", Quantity::Length)
                                             : default_step;
  return well;
}

}  // namespace drillflex::io
