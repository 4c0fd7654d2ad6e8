// A WITSML trajectory: its stations' MD, inclination and azimuth. Positions, TVD, DLS and the like
// that a document also gives are not read: drillflex computes them from the stations by minimum
// curvature (one warning per field, not one per station).
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "core/types.hpp"
#include "io/witsml_reader.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

// Describes a station: "trajectoryStation uid=s3", or its position in the list.
std::string StationName(const WitsmlReader& reader, const pugi::xml_node& station, std::size_t index) {
  const std::string uid = station.attribute("uid").value();
  return uid.empty() ? fmt::format("{} {}", reader.Name("trajectoryStation"), index + 1)
                     : fmt::format("{} uid={}", reader.Name("trajectoryStation"), uid);
}

}  // namespace

WitsmlTrajectory ReadTrajectory(const WitsmlReader& reader, const pugi::xml_node& object) {
  WitsmlTrajectory trajectory;
  trajectory.name = reader.ObjectName(object);
  trajectory.origin = reader.ObjectOrigin(object, "trajectory");
  struct Unread {
    pugi::xml_node first;
    int count = 0;
  };
  std::map<std::string, Unread> unread;  // by element name, in name order
  const auto stations = reader.Children(object, "trajectoryStation");
  for (std::size_t i = 0; i < stations.size(); ++i) {
    const pugi::xml_node node = stations[i];
    WitsmlStation station;
    station.md = reader.RequiredMeasure(node, "md", Quantity::Length, "the station's measured depth");
    station.inclination = reader.RequiredMeasure(node, "incl", Quantity::Angle, "the station's inclination");
    station.azimuth = reader.RequiredMeasure(node, "azi", Quantity::Angle, "the station's azimuth");
    station.origin = reader.Origin(node, StationName(reader, node, i));
    if (station.md.si < 0.0) reader.Fail(reader.Child(node, "md"), "the MD must not be negative");
    if (station.inclination.si < 0.0 || station.inclination.si > kPi + 1e-12) {
      reader.Fail(reader.Child(node, "incl"), fmt::format("the inclination must lie between 0 and 180 deg, got {} {}",
                                                          station.inclination.text, station.inclination.uom));
    }
    if (!trajectory.stations.empty() && !(station.md.si > trajectory.stations.back().md.si)) {
      const WitsmlValue& previous = trajectory.stations.back().md;
      reader.Fail(reader.Child(node, "md"),
                  fmt::format("the MD must strictly increase from one station to the next: {} {} follows {} {} ({})",
                              station.md.text, station.md.uom, previous.text, previous.uom,
                              trajectory.stations.back().origin.what));
    }
    for (const pugi::xml_node field : reader.Unknown(node, {"md", "incl", "azi", "typeTrajStation", "dTimStn",
                                                            "typeSurveyTool", "calcAlgorithm", "statusTrajStation",
                                                            "manuallyEntered"})) {
      Unread& entry = unread[std::string(LocalName(field))];
      if (entry.count++ == 0) entry.first = field;
    }
    trajectory.stations.push_back(station);
  }
  if (trajectory.stations.size() < 2) {
    reader.Fail(object, fmt::format("a trajectory needs at least two <{}> elements (MD, inclination, azimuth), got {}",
                                    reader.Name("trajectoryStation"), trajectory.stations.size()));
  }
  for (const auto& [name, entry] : unread) {
    reader.Warn(entry.first, fmt::format("<{}> (at {} of {} stations) not mapped: drillflex computes positions, TVD "
                                         "and dogleg severity from MD, inclination and azimuth (minimum curvature)",
                                         name, entry.count, trajectory.stations.size()));
  }
  return trajectory;
}

std::vector<well::SurveyStation> SurveyOf(const WitsmlTrajectory& trajectory) {
  std::vector<well::SurveyStation> survey;
  for (const WitsmlStation& station : trajectory.stations) {
    double azimuth = std::fmod(station.azimuth.si, 2.0 * kPi);
    if (azimuth < 0.0) azimuth += 2.0 * kPi;
    survey.push_back({station.md.si, station.inclination.si, azimuth});
  }
  return survey;
}

}  // namespace drillflex::io
