// "transient" and transient.csv: one row per output sample (analyses/transient_analysis.hpp).
#include <string>

#include <fmt/format.h>

#include "io/analysis_results.hpp"

namespace drillflex::io {
namespace {

using nlohmann::json;
using units::Quantity;

double Out(const Case& c, double si, Quantity quantity) { return units::FromSI(si, quantity, c.output_units) + 0.0; }
std::string Unit(const Case& c, Quantity quantity) { return std::string(units::DefaultUnit(quantity, c.output_units)); }

// The per-probe columns, their quantities (units) and readers.
struct ProbeColumn {
  const char* name;
  Quantity quantity;
  double (*read)(const analyses::ProbeSample&);
};
constexpr ProbeColumn kProbeColumns[] = {
    {"lateral_y", Quantity::Diameter, [](const analyses::ProbeSample& p) { return p.lateral_y; }},
    {"lateral_z", Quantity::Diameter, [](const analyses::ProbeSample& p) { return p.lateral_z; }},
    {"whirl_angle", Quantity::Angle, [](const analyses::ProbeSample& p) { return p.whirl_angle; }},
    {"contact_force", Quantity::Force, [](const analyses::ProbeSample& p) { return p.contact_force; }},
    {"bending_moment", Quantity::Moment, [](const analyses::ProbeSample& p) { return p.bending_moment; }},
};

}  // namespace

void AddTransientResults(const Case& c, const analyses::TransientResult& result, ResultFiles& files) {
  std::vector<std::string> columns = {"time",     "surface_rpm",    "surface_torque",   "hook_load",
                                      "bit_rpm",  "wob",            "tob",              "kinetic_energy",
                                      "potential_energy", "total_energy"};
  json units_of = {{"time", "s"},
                   {"surface_rpm", "rpm"},
                   {"surface_torque", Unit(c, Quantity::Moment)},
                   {"hook_load", Unit(c, Quantity::Force)},
                   {"bit_rpm", "rpm"},
                   {"wob", Unit(c, Quantity::WeightOnBit)},
                   {"tob", Unit(c, Quantity::Moment)},
                   {"energy", Unit(c, Quantity::Moment)}};
  const std::string moment = Unit(c, Quantity::Moment);
  std::vector<std::string> column_units = {"s",    "rpm",  moment, Unit(c, Quantity::Force), "rpm",
                                           Unit(c, Quantity::WeightOnBit), moment, moment, moment, moment};
  json probes = json::array();
  for (std::size_t p = 0; p < result.probe_s.size(); ++p) {
    for (const ProbeColumn& column : kProbeColumns) {
      columns.push_back(fmt::format("probe{}_{}", p + 1, column.name));
      column_units.push_back(Unit(c, column.quantity));
    }
    probes.push_back({{"s", Out(c, result.probe_s[p], Quantity::Length)},
                      {"md", Out(c, StationMd(c, result.probe_s[p]), Quantity::Length)}});
  }
  for (const ProbeColumn& column : kProbeColumns) units_of[column.name] = Unit(c, column.quantity);
  CsvTable table(columns, column_units);
  for (const analyses::TransientSample& s : result.samples) {
    std::vector<double> row = {s.time,
                               Out(c, s.surface_speed, Quantity::RotarySpeed),
                               Out(c, s.surface_torque, Quantity::Moment),
                               Out(c, s.hook_load, Quantity::Force),
                               Out(c, s.bit_speed, Quantity::RotarySpeed),
                               Out(c, s.weight_on_bit, Quantity::WeightOnBit),
                               Out(c, s.torque_on_bit, Quantity::Moment),
                               Out(c, s.kinetic_energy, Quantity::Moment),
                               Out(c, s.potential_energy, Quantity::Moment),
                               Out(c, s.kinetic_energy + s.potential_energy, Quantity::Moment)};
    for (const analyses::ProbeSample& probe : s.probes) {
      for (const ProbeColumn& column : kProbeColumns) row.push_back(Out(c, column.read(probe), column.quantity));
    }
    table.AddRow(row);
  }
  files.Add("transient.csv", table.ToString());
  const auto& stats = result.statistics;
  files.json()["transient"] = {
      {"time_series", "transient.csv"},
      {"duration", result.samples.back().time},
      {"samples", result.samples.size()},
      {"column_units", units_of},
      {"probes", probes},
      {"rho_infinity", result.rho_infinity},
      {"energy_drift", result.energy_drift},
      {"steps", stats.steps},
      {"rejected_steps", stats.error_rejections + stats.newton_failures},
      {"newton_iterations", stats.newton_iterations},
      {"factorizations", stats.factorizations},
      {"smallest_step", stats.steps > 0 ? stats.smallest_step : 0.0},
      {"largest_step", stats.largest_step},
      // The state at the end in the model's own coordinates (SI; positions with a quaternion per
      // body, velocities with the body-frame angular velocity), to continue from.
      {"final_state", {{"q", std::vector<double>(result.final_q.data(), result.final_q.data() + result.final_q.size())},
                       {"v", std::vector<double>(result.final_v.data(), result.final_v.data() + result.final_v.size())}}}};
}

}  // namespace drillflex::io
