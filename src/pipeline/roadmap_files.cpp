// roadmap.csv, roadmap.json and the report of a roadmap (pipeline/roadmap.hpp).
#include <cmath>
#include <functional>

#include "io/report_html.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::pipeline {
namespace {

using units::Quantity;

// A column of roadmap.csv (and a key of roadmap.json's point): a quantity of one of the point's records.
template <class Record>
struct Column {
  const char* name;
  Quantity quantity;
  double Record::*member;
};

constexpr Column<RoadmapPoint> kColumns[] = {
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
constexpr Column<RoadmapLimits> kLimitColumns[] = {
    {"hook_load_limit", Quantity::Force, &RoadmapLimits::hook_load_limit},
    {"torque_limit", Quantity::Moment, &RoadmapLimits::torque_limit},
    {"helical_slack_off", Quantity::Force, &RoadmapLimits::helical_slack_off},
    {"fatigue_rotating", Quantity::Dimensionless, &RoadmapLimits::fatigue_rotating},
    {"fatigue_rotating_md", Quantity::Length, &RoadmapLimits::fatigue_rotating_md},
    {"fatigue_on_bottom", Quantity::Dimensionless, &RoadmapLimits::fatigue_on_bottom},
    {"fatigue_on_bottom_md", Quantity::Length, &RoadmapLimits::fatigue_on_bottom_md},
};

// The casing wear columns (RoadmapWear), after the limits'.
constexpr Column<RoadmapWear> kWearColumns[] = {
    {"wear_rotating_time", Quantity::Time, &RoadmapWear::rotating_time},
    {"wear_md", Quantity::Length, &RoadmapWear::md},
    {"wear_side_force_per_length", Quantity::ForcePerLength, &RoadmapWear::side_force_per_length},
    {"wear_groove_depth", Quantity::Diameter, &RoadmapWear::groove_depth},
    {"wear_remaining_wall", Quantity::Diameter, &RoadmapWear::remaining_wall},
    {"wear_utilisation", Quantity::Dimensionless, &RoadmapWear::utilisation},
};

// A run's screens in roadmap.json: its buckled zones (each tagged with the run) into `zones`, and for a
// rotating run its fatigue (`worst` and each dogleg's) into `fatigue[run]`.
void ScreenJson(const char* run, const RunScreen& screen, bool rotating, const std::function<double(double, Quantity)>& out,
                nlohmann::json& zones, nlohmann::json& fatigue) {
  for (const analyses::BuckledZone& zone : screen.zones) {
    zones.push_back({{"run", run},
                     {"kind", analyses::BucklingStateName(zone.state)},
                     {"md_from", out(zone.md_from, Quantity::Length)},
                     {"md_to", out(zone.md_to, Quantity::Length)}});
  }
  if (!rotating) return;
  nlohmann::json doglegs = nlohmann::json::array();
  for (const analyses::DoglegFatigue& dogleg : screen.doglegs) {
    doglegs.push_back({{"md_from", out(dogleg.md_from, Quantity::Length)},
                       {"md_to", out(dogleg.md_to, Quantity::Length)},
                       {"utilisation", dogleg.utilisation},
                       {"md", out(dogleg.md, Quantity::Length)},
                       {"dogleg_severity", out(dogleg.curvature, Quantity::DoglegSeverity)},
                       {"component", dogleg.component}});
  }
  nlohmann::json worst = nullptr;
  if (!screen.fatigue.limit.empty()) {
    worst = {{"utilisation", screen.fatigue.utilisation},
             {"md", out(screen.fatigue.md, Quantity::Length)},
             {"component", screen.fatigue.component}};
  }
  fatigue[run] = {{"worst", worst}, {"doglegs", doglegs}};
}

RoadmapTables Tabulate(const io::Case& c, const analyses::RoadmapSettings& settings,
                       const std::vector<RoadmapPoint>& points, units::System system) {
  auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system); };
  std::vector<std::string> columns, units_row;
  const auto head = [&](const auto& list) {
    for (const auto& column : list) {
      columns.push_back(column.name);
      units_row.push_back(UnitOf(column.quantity, system));
    }
  };
  head(kColumns);
  columns.push_back("message");
  units_row.push_back("-");
  head(kLimitColumns);
  head(kWearColumns);
  io::CsvTable table(columns, units_row);
  RoadmapTables tables;
  const std::vector<RoadmapWear> wear = RoadmapCasingWear(c, settings, points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const RoadmapPoint& point = points[i];
    std::vector<std::string> cells;
    nlohmann::json row = nlohmann::json::object();
    // A record's columns: the cells (empty where NaN) and the row's keys (null).
    const auto add = [&](const auto& list, const auto& record) {
      for (const auto& column : list) {
        const double shown = out(record.*column.member, column.quantity);
        cells.push_back(std::isfinite(shown) ? io::CsvTable::Number(shown) : "");
        row[column.name] = std::isfinite(shown) ? nlohmann::json(shown) : nlohmann::json(nullptr);
      }
    };
    add(kColumns, point);
    cells.push_back(io::CsvTable::Text(point.message));
    row["message"] = point.message;
    const RoadmapLimits limits = RoadmapPointLimits(c, settings, point);
    add(kLimitColumns, limits);
    add(kWearColumns, wear[i]);
    // The four runs' screens: the buckled zones (MD from-to) and the rotating runs' fatigue.
    nlohmann::json zones = nlohmann::json::array(), fatigue = nlohmann::json::object();
    const PointScreens& screens = limits.screens;
    ScreenJson("pick_up", screens.pick_up, false, out, zones, fatigue);
    ScreenJson("slack_off", screens.slack_off, false, out, zones, fatigue);
    ScreenJson("rotating", screens.rotating, true, out, zones, fatigue);
    ScreenJson("on_bottom", screens.on_bottom, true, out, zones, fatigue);
    row["buckled_zones"] = zones;
    row["screened_by"] = point.screens ? "stiff" : "soft";
    row["fatigue"] = fatigue;
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
  for (const auto& column : kColumns) units_json[column.name] = UnitOf(column.quantity, system);
  for (const auto& column : kLimitColumns) units_json[column.name] = UnitOf(column.quantity, system);
  for (const auto& column : kWearColumns) units_json[column.name] = UnitOf(column.quantity, system);
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
