// Reads `well:`: the survey (inline or from a CSV file), the hole sections and the bit MD.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "io/case_sections.hpp"
#include "io/survey_csv.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

constexpr double kMaxTrajectoryRows = 1e6;

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

// A survey CSV file (io/survey_csv.hpp), relative to the case file's directory.
std::vector<well::SurveyStation> ReadSurveyFile(const YamlView& node, const std::string& directory) {
  const std::string given = node.AsString();
  const std::filesystem::path path = std::filesystem::path(given).is_absolute()
                                         ? std::filesystem::path(given)
                                         : std::filesystem::path(directory) / given;
  // Only a regular file: a directory opens and reads as empty, and /dev/zero or a FIFO would never end.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    node.Fail(fmt::format("cannot read the survey file '{}': {}", path.string(),
                          std::filesystem::exists(path, error) ? "not a regular file" : "no such file"));
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) node.Fail(fmt::format("cannot read the survey file '{}'", path.string()));
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const auto stations = ParseSurveyCsv(text, path.string(), node.context().system);
  if (stations.size() < 2) node.Fail(fmt::format("the survey file '{}' has fewer than two stations", path.string()));
  return stations;
}

// A wall friction coefficient above this is a typing error, not a hole (open hole with cuttings beds
// reads 0.3–0.5).
constexpr double kMaxFriction = 2.0;

std::vector<well::HoleSection> ReadHole(const YamlView& node) {
  if (node.IsScalar()) return {{std::nullopt, node.AsPositive(Quantity::Diameter), std::nullopt}};
  node.ExpectSequence("hole sections {to, diameter}");
  std::vector<well::HoleSection> sections;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlView item = node.Item(i);
    item.ExpectMap("a hole section {to: MD, diameter: D}", false);
    item.AllowOnlyKeys({"to", "diameter", "diameter_at_end", "cased", "friction", "axial_friction", "wall"});
    well::HoleSection section;
    section.to_md = item.OptionalPositive("to", Quantity::Length);
    section.diameter = item.Positive("diameter", Quantity::Diameter);
    section.diameter_at_end = item.OptionalPositive("diameter_at_end", Quantity::Diameter);
    if (const auto cased = item.OptionalChild("cased")) section.cased = cased->AsBool();
    section.friction = item.OptionalQuantity("friction", Quantity::Dimensionless);
    section.axial_friction = item.OptionalQuantity("axial_friction", Quantity::Dimensionless);
    for (const char* key : {"friction", "axial_friction"}) {
      const auto mu = item.OptionalQuantity(key, Quantity::Dimensionless);
      if (mu && !(*mu >= 0.0 && *mu <= kMaxFriction)) {
        item.Child(key).Fail(fmt::format("expected a friction coefficient from 0 to {:g}", kMaxFriction));
      }
    }
    section.wall = item.OptionalPositive("wall", Quantity::Diameter);
    if (section.wall && !section.cased) {
      item.Child("wall").Fail("a wall thickness is the casing's (casing wear): give it on a section with 'cased: true'");
    }
    if (section.wall && !(*section.wall < 0.25 * section.diameter)) {
      item.Child("wall").Fail("expected a casing wall thickness below a quarter of the section's diameter (its bore)");
    }
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
  // `drillflex well` writes a row every output_step (io/trajectory_table.cpp): bound the table, which
  // a survey to 1e9 ft at a step of 1e-6 ft would make a petabyte.
  const double rows = (well.survey.back().md - well.survey.front().md) / well.output_step + well.survey.size();
  if (!(rows <= kMaxTrajectoryRows)) {
    (node.Has("output_step") ? node.Child("output_step") : node)
        .Fail(fmt::format("the trajectory table would have {:.3g} rows, one every output_step along the survey: "
                          "at most {:.0f}; give a larger output_step", rows, kMaxTrajectoryRows));
  }
  return well;
}

}  // namespace drillflex::io
