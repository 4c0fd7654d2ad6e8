#include "io/trajectory_table.hpp"

#include <cmath>

#include "well/hole.hpp"
#include "well/trajectory.hpp"

namespace drillflex::io {

std::vector<TrajectoryRow> TrajectoryTable(const WellConfig& well) {
  const well::Trajectory trajectory(well.survey);
  const well::HoleProfile hole(well.hole);
  std::vector<double> mds;
  for (std::size_t i = 0; i + 1 < well.survey.size(); ++i) {
    const double from = well.survey[i].md;
    const double to = well.survey[i + 1].md;
    const int steps = std::max(1, static_cast<int>(std::ceil((to - from) / well.output_step - 1e-9)));
    for (int k = 0; k < steps; ++k) {
      const double md = from + k * well.output_step;
      if (md < to - 1e-9) mds.push_back(md);
    }
  }
  mds.push_back(well.survey.back().md);
  std::vector<TrajectoryRow> rows;
  rows.reserve(mds.size());
  for (const double md : mds) {
    const Vec3 position = trajectory.Position(md);
    TrajectoryRow row;
    row.md = md;
    row.inclination = trajectory.Inclination(md);
    row.azimuth = trajectory.Azimuth(md);
    row.north = position.x();
    row.east = position.y();
    row.tvd = position.z();
    row.dogleg_severity = trajectory.DoglegSeverity(md);
    row.hole_diameter = hole.Diameter(md);
    rows.push_back(row);
  }
  return rows;
}

void AddTrajectoryResults(const std::vector<TrajectoryRow>& rows, units::System system, ResultFiles& files) {
  using units::Quantity;
  auto length = [&](double v) { return units::FromSI(v, Quantity::Length, system); };
  auto angle = [&](double v) { return units::FromSI(v, Quantity::Angle, system); };
  const std::string length_unit(units::DefaultUnit(Quantity::Length, system));
  CsvTable table({"md", "inclination", "azimuth", "north", "east", "tvd", "dls", "hole_diameter"},
                 {length_unit, "deg", "deg", length_unit, length_unit, length_unit,
                  std::string(units::DefaultUnit(Quantity::DoglegSeverity, system)),
                  std::string(units::DefaultUnit(Quantity::Diameter, system))});
  nlohmann::json stations = nlohmann::json::array();
  for (const auto& row : rows) {
    const std::vector<double> values = {
        length(row.md), angle(row.inclination), angle(row.azimuth), length(row.north),
        length(row.east), length(row.tvd),
        units::FromSI(row.dogleg_severity, Quantity::DoglegSeverity, system),
        units::FromSI(row.hole_diameter, Quantity::Diameter, system)};
    table.AddRow(values);
    stations.push_back({{"md", values[0]}, {"inclination", values[1]}, {"azimuth", values[2]},
                        {"north", values[3]}, {"east", values[4]}, {"tvd", values[5]},
                        {"dls", values[6]}, {"hole_diameter", values[7]}});
  }
  files.Add("trajectory.csv", table.ToString());
  auto& json = files.json();
  json["well"] = {
      {"trajectory", stations},
      {"trajectory_csv", "trajectory.csv"},
      {"column_units",
       {{"md", units::DefaultUnit(Quantity::Length, system)},
        {"inclination", "deg"}, {"azimuth", "deg"},
        {"north", units::DefaultUnit(Quantity::Length, system)},
        {"east", units::DefaultUnit(Quantity::Length, system)},
        {"tvd", units::DefaultUnit(Quantity::Length, system)},
        {"dls", units::DefaultUnit(Quantity::DoglegSeverity, system)},
        {"hole_diameter", units::DefaultUnit(Quantity::Diameter, system)}}}};
}

}  // namespace drillflex::io
