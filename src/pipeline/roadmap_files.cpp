// roadmap.csv, roadmap.json and the report of a roadmap (pipeline/roadmap.hpp).
#include <cmath>

#include "io/report_html.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::pipeline {
namespace {

using units::Quantity;

struct RoadmapColumn {
  const char* name;
  Quantity quantity;
  double RoadmapPoint::*member;
};

constexpr RoadmapColumn kColumns[] = {
    {"bit_md", Quantity::Length, &RoadmapPoint::bit_md},
    {"friction", Quantity::Dimensionless, &RoadmapPoint::friction},
    {"pick_up", Quantity::Force, &RoadmapPoint::pick_up},
    {"slack_off", Quantity::Force, &RoadmapPoint::slack_off},
    {"rotating", Quantity::Force, &RoadmapPoint::rotating},
    {"off_bottom_torque", Quantity::Moment, &RoadmapPoint::off_bottom_torque},
    {"on_bottom_torque", Quantity::Moment, &RoadmapPoint::on_bottom_torque},
};

std::string UnitOf(Quantity quantity, units::System system) {
  return quantity == Quantity::Dimensionless ? "-" : std::string(units::DefaultUnit(quantity, system));
}

// The points as a CSV table (the case's output units, a row a point) and as roadmap.json's rows.
struct RoadmapTables {
  std::string csv;
  nlohmann::json rows = nlohmann::json::array();
};

// The limit columns (RoadmapLimits), after the points' own.
struct LimitColumn {
  const char* name;
  Quantity quantity;
  double RoadmapLimits::*member;
};
constexpr LimitColumn kLimitColumns[] = {
    {"hook_load_limit", Quantity::Force, &RoadmapLimits::hook_load_limit},
    {"torque_limit", Quantity::Moment, &RoadmapLimits::torque_limit},
    {"helical_slack_off", Quantity::Force, &RoadmapLimits::helical_slack_off},
};

RoadmapTables Tabulate(const io::Case& c, const analyses::RoadmapSettings& settings,
                       const std::vector<RoadmapPoint>& points, units::System system) {
  auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system); };
  std::vector<std::string> columns, units_row;
  for (const RoadmapColumn& column : kColumns) {
    columns.push_back(column.name);
    units_row.push_back(UnitOf(column.quantity, system));
  }
  columns.push_back("message");
  units_row.push_back("-");
  for (const LimitColumn& column : kLimitColumns) {
    columns.push_back(column.name);
    units_row.push_back(UnitOf(column.quantity, system));
  }
  io::CsvTable table(columns, units_row);
  RoadmapTables tables;
  for (const RoadmapPoint& point : points) {
    std::vector<std::string> cells;
    nlohmann::json row = nlohmann::json::object();
    for (const RoadmapColumn& column : kColumns) {
      const double shown = out(point.*column.member, column.quantity);
      cells.push_back(std::isfinite(shown) ? io::CsvTable::Number(shown) : "");
      row[column.name] = std::isfinite(shown) ? nlohmann::json(shown) : nlohmann::json(nullptr);
    }
    cells.push_back(io::CsvTable::Text(point.message));
    row["message"] = point.message;
    const RoadmapLimits limits = RoadmapPointLimits(c, settings, point);
    for (const LimitColumn& column : kLimitColumns) {
      const double shown = out(limits.*column.member, column.quantity);
      cells.push_back(std::isfinite(shown) ? io::CsvTable::Number(shown) : "");
      row[column.name] = std::isfinite(shown) ? nlohmann::json(shown) : nlohmann::json(nullptr);
    }
    // The buckled zones of the four runs (the soft string's), MD from-to.
    nlohmann::json zones = nlohmann::json::array();
    for (const auto& [run, list] : {std::pair{"pick_up", &limits.pick_up_zones}, std::pair{"slack_off", &limits.slack_off_zones},
                                    std::pair{"rotating", &limits.rotating_zones}, std::pair{"on_bottom", &limits.on_bottom_zones}}) {
      for (const analyses::BuckledZone& zone : *list) {
        zones.push_back({{"run", run},
                         {"kind", analyses::BucklingStateName(zone.state)},
                         {"md_from", out(zone.md_from, Quantity::Length)},
                         {"md_to", out(zone.md_to, Quantity::Length)}});
      }
    }
    row["buckled_zones"] = zones;
    table.AddCells(std::move(cells));
    tables.rows.push_back(std::move(row));
  }
  tables.csv = table.ToString();
  return tables;
}

}  // namespace

io::ResultFiles ComposeRoadmapFiles(const io::Case& c, const analyses::RoadmapSettings& settings,
                                    const std::vector<RoadmapPoint>& points, const std::string& directory,
                                    bool report, double run_seconds, const std::vector<RoadmapPoint>& soft_points,
                                    const nlohmann::json& readings, const std::string& readings_csv) {
  io::ResultFiles files(directory, "roadmap.json");
  const units::System system = c.output_units;
  auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system); };
  RoadmapTables main = Tabulate(c, settings, points, system);
  files.Add("roadmap.csv", main.csv);
  const bool both = settings.model == analyses::RoadmapModel::Both;
  RoadmapTables soft;
  if (both) {
    soft = Tabulate(c, settings, soft_points, system);
    files.Add("roadmap-soft.csv", soft.csv);
  }
  nlohmann::json units_json = nlohmann::json::object();
  for (const RoadmapColumn& column : kColumns) units_json[column.name] = UnitOf(column.quantity, system);
  for (const LimitColumn& column : kLimitColumns) units_json[column.name] = UnitOf(column.quantity, system);
  nlohmann::json& json = files.json();
  json["case"] = c.name;
  json["units"] = std::string(units::SystemName(system));
  json["roadmap"] = {
      {"from", out(settings.from_md, Quantity::Length)},
      {"step", out(settings.step, Quantity::Length)},
      {"bit_md", out(c.input.bit_md, Quantity::Length)},
      {"friction", settings.friction},
      {"rpm", out(settings.rotary_speed, Quantity::RotarySpeed)},
      {"trip_speed", out(settings.trip_speed, Quantity::Velocity)},
      {"weight_on_bit", out(c.input.operation.weight_on_bit, Quantity::WeightOnBit)},
      {"torque_on_bit", out(c.input.operation.torque_on_bit, Quantity::Moment)},
      {"model", RoadmapModelName(settings.model)},
      // The stiff model's string from the bit: "case" (the case's own), "surface", or a length.
      {"stiff_length", settings.stiff_length == 0.0        ? nlohmann::json("case")
                       : !std::isfinite(settings.stiff_length) ? nlohmann::json("surface")
                                                                 : nlohmann::json(out(settings.stiff_length, Quantity::Length))},
      {"units", units_json},
      {"design_factor", c.limits.design_factor},
      {"points", std::move(main.rows)},
  };
  if (both) json["roadmap"]["soft_points"] = std::move(soft.rows);
  if (!readings.is_null()) {
    json["roadmap"]["readings"] = readings;
    files.Add("readings.csv", readings_csv);
  }
  if (settings.cased_friction) json["roadmap"]["cased_friction"] = *settings.cased_friction;
  if (report) {
    files.Add("report.html", io::ComposeReportHtml(json, io::ReportData{}, {"roadmap", run_seconds}));
  }
  return files;
}

}  // namespace drillflex::pipeline
