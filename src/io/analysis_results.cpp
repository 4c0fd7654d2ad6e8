#include "io/analysis_results.hpp"

#include <fmt/format.h>

namespace drillflex::io {
namespace {

using nlohmann::json;
using units::Quantity;

// Converts SI to the case's output units.
struct OutputUnits {
  units::System system;
  double operator()(double si, Quantity quantity) const { return units::FromSI(si, quantity, system); }
  json Vector(const Vec3& si, Quantity quantity) const {
    return json::array({(*this)(si.x(), quantity), (*this)(si.y(), quantity), (*this)(si.z(), quantity)});
  }
  std::string Unit(Quantity quantity) const { return std::string(units::DefaultUnit(quantity, system)); }
};

}  // namespace

double StationMd(const Case& c, double s) { return c.well ? c.well->bit_md - s : s; }

void AddCaseHeader(const Case& c, const model::BuiltModel& built, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  json& root = files.json();
  root["case"] = c.name;
  root["units"] = units::SystemName(c.output_units);
  std::size_t supports = c.supports.size();
  root["model"] = {{"bodies", built.system.bodies().size()},
                   {"coordinates", built.system.num_velocities()},
                   {"contacts", built.contact_elements.size()},
                   {"couplings", built.system.bodies().empty() ? 0 : built.system.bodies().size() - 1},
                   {"supports", supports},
                   {"elements_per_body", c.model.elements_per_body},
                   {"modes_per_body", c.model.modes_per_body},
                   {"coupling_factor", c.model.coupling_factor}};
  root["column_units"] = {{"s", out.Unit(Quantity::Length)},        {"md", out.Unit(Quantity::Length)},
                          {"position", out.Unit(Quantity::Length)}, {"displacement", out.Unit(Quantity::Diameter)},
                          {"rotation", "deg"},                      {"lateral_offset", out.Unit(Quantity::Diameter)},
                          {"force", out.Unit(Quantity::Force)},     {"moment", out.Unit(Quantity::Moment)},
                          {"stress", out.Unit(Quantity::Stress)},   {"frequency", "Hz"}};
}

void AddStaticResults(const Case& c, const analyses::StaticResult& result, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  CsvTable table({"s", "md", "x", "y", "z", "ux", "uy", "uz", "rx", "ry", "rz", "lateral_offset", "axial_force",
                  "torque", "shear_force", "bending_moment", "bending_stress", "von_mises_stress"});
  json nodes = json::array();
  for (const auto& node : result.nodes) {
    const double md = StationMd(c, node.s);
    const Vec3 rotation_deg = node.rotation / kDegree;
    table.AddRow({out(node.s, Quantity::Length), out(md, Quantity::Length), out(node.position.x(), Quantity::Length),
                  out(node.position.y(), Quantity::Length), out(node.position.z(), Quantity::Length),
                  out(node.displacement.x(), Quantity::Diameter), out(node.displacement.y(), Quantity::Diameter),
                  out(node.displacement.z(), Quantity::Diameter), rotation_deg.x(), rotation_deg.y(), rotation_deg.z(),
                  out(node.lateral_offset, Quantity::Diameter), out(node.axial_force, Quantity::Force),
                  out(node.torque, Quantity::Moment), out(node.shear_force, Quantity::Force),
                  out(node.bending_moment, Quantity::Moment), out(node.bending_stress, Quantity::Stress),
                  out(node.von_mises_stress, Quantity::Stress)});
    nodes.push_back({{"s", out(node.s, Quantity::Length)},
                     {"md", out(md, Quantity::Length)},
                     {"position", out.Vector(node.position, Quantity::Length)},
                     {"displacement", out.Vector(node.displacement, Quantity::Diameter)},
                     {"rotation", json::array({rotation_deg.x(), rotation_deg.y(), rotation_deg.z()})},
                     {"lateral_offset", out(node.lateral_offset, Quantity::Diameter)},
                     {"axial_force", out(node.axial_force, Quantity::Force)},
                     {"torque", out(node.torque, Quantity::Moment)},
                     {"bending_moment", out(node.bending_moment, Quantity::Moment)},
                     {"shear_force", out(node.shear_force, Quantity::Force)},
                     {"bending_stress", out(node.bending_stress, Quantity::Stress)},
                     {"von_mises_stress", out(node.von_mises_stress, Quantity::Stress)}});
  }
  json reactions = json::array();
  for (const auto& reaction : result.reactions) {
    reactions.push_back({{"s", out(reaction.s, Quantity::Length)},
                         {"force", out.Vector(reaction.force, Quantity::Force)},
                         {"moment", out.Vector(reaction.moment, Quantity::Moment)}});
  }
  json contacts = json::array();
  CsvTable contact_table({"s", "md", "normal_force", "friction_force", "high_side_angle"});
  for (const auto& contact : result.contacts) {
    const double angle = contact.high_side_angle / kDegree;
    contact_table.AddRow({out(contact.s, Quantity::Length), out(contact.md, Quantity::Length),
                          out(contact.normal_force, Quantity::Force), out(contact.friction_force, Quantity::Force), angle});
    contacts.push_back({{"s", out(contact.s, Quantity::Length)},
                        {"md", out(contact.md, Quantity::Length)},
                        {"component", c.string.components[contact.component].name},
                        {"normal_force", out(contact.normal_force, Quantity::Force)},
                        {"friction_force", out(contact.friction_force, Quantity::Force)},
                        {"high_side_angle", angle}});
  }
  if (!result.contacts.empty()) files.Add("contacts.csv", contact_table.ToString());
  files.Add("static.csv", table.ToString());
  files.json()["static"] = {{"converged", result.converged},
                            {"iterations", result.iterations},
                            {"load_steps", result.load_steps},
                            {"residual_norm", out(result.residual_norm, Quantity::Force)},
                            {"nodes", nodes},
                            {"contacts", contacts},
                            {"reactions", reactions},
                            {"table", "static.csv"}};
  if (result.bit) {
    files.json()["static"]["bit"] = {{"side_force", out(result.bit->side_force, Quantity::Force)},
                                     {"build_force", out(result.bit->build_force, Quantity::Force)},
                                     {"walk_force", out(result.bit->walk_force, Quantity::Force)},
                                     {"tilt", result.bit->tilt / kDegree}};
  }
}

void AddModesResults(const Case& c, const analyses::ModesResult& result, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  CsvTable frequencies({"mode", "frequency_hz", "axial_fraction", "torsional_fraction", "lateral_fraction"});
  CsvTable shapes({"mode", "s", "ux", "uy", "uz", "rx", "ry", "rz"});
  json modes = json::array();
  for (std::size_t m = 0; m < result.modes.size(); ++m) {
    const auto& mode = result.modes[m];
    frequencies.AddRow({static_cast<double>(m + 1), mode.frequency_hz, mode.axial_fraction, mode.torsional_fraction,
                        mode.lateral_fraction});
    for (std::size_t i = 0; i < result.s.size() && i < mode.displacement.size(); ++i) {
      shapes.AddRow({static_cast<double>(m + 1), out(result.s[i], Quantity::Length), mode.displacement[i].x(),
                     mode.displacement[i].y(), mode.displacement[i].z(), mode.rotation[i].x(), mode.rotation[i].y(),
                     mode.rotation[i].z()});
    }
    modes.push_back({{"frequency_hz", mode.frequency_hz},
                     {"kind", analyses::ModeKindName(mode.kind)},
                     {"rigid_body", mode.rigid_body},
                     {"axial_fraction", mode.axial_fraction},
                     {"torsional_fraction", mode.torsional_fraction},
                     {"lateral_fraction", mode.lateral_fraction}});
  }
  files.Add("modes.csv", frequencies.ToString());
  files.Add("mode_shapes.csv", shapes.ToString());
  files.json()["modes"] = modes;
}

void AddBucklingResults(const Case& c, const analyses::BucklingResult& result, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  CsvTable table({"load_factor", "compression", "frequency_hz"});
  json points = json::array();
  for (const auto& point : result.frequency_table) {
    table.AddRow({point.load_factor, out(point.compression, Quantity::Force), point.frequency_hz});
    points.push_back({{"load_factor", point.load_factor},
                      {"compression", out(point.compression, Quantity::Force)},
                      {"frequency_hz", point.frequency_hz}});
  }
  files.Add("buckling.csv", table.ToString());
  files.json()["buckling"] = {
      {"load_factor", result.load_factor},
      {"critical_load", out(result.critical_load, Quantity::Force)},
      {"load_factors", result.load_factors},
      {"reference_compression", out(result.reference_compression, Quantity::Force)},
      {"frequency_method",
       {{"converged", result.frequency_method_converged},
        {"load_factor", result.frequency_load_factor},
        {"critical_load", out(result.frequency_critical_load, Quantity::Force)},
        {"unloaded_frequency_hz", result.unloaded_frequency_hz},
        {"table", points}}}};
}

}  // namespace drillflex::io
