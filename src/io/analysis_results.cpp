#include "io/analysis_results.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analyses/bit_tendency.hpp"
#include "analyses/string_limits.hpp"

namespace drillflex::io {
namespace {

using nlohmann::json;
using units::Quantity;

// Converts SI to the case's output units.
struct OutputUnits {
  units::System system;
  double operator()(double si, Quantity quantity) const { return units::FromSI(si, quantity, system) + 0.0; }
  json Vector(const Vec3& si, Quantity quantity) const {
    return json::array({(*this)(si.x(), quantity), (*this)(si.y(), quantity), (*this)(si.z(), quantity)});
  }
  std::string Unit(Quantity quantity) const { return std::string(units::DefaultUnit(quantity, system)); }
};

}  // namespace

double StationMd(const Case& c, double s) { return c.well ? c.well->bit_md - s : s; }

json UtilisationJson(const Case& c, const analyses::LimitUtilisation& limit) {
  const OutputUnits out{c.output_units};
  if (limit.component < 0) return nullptr;
  return {{"limit", limit.limit},
          {"utilisation", limit.utilisation},
          {"s", out(limit.s, Quantity::Length)},
          {"md", out(limit.md, Quantity::Length)},
          {"component", c.input.string.components.at(limit.component).name}};
}

void AddCaseHeader(const Case& c, const model::BuiltModel& built, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  json& root = files.json();
  root["case"] = c.name;
  root["units"] = units::SystemName(c.output_units);
  std::size_t supports = c.input.supports.size();
  root["model"] = {{"bodies", built.system.bodies().size()},
                   {"coordinates", built.system.num_velocities()},
                   {"contacts", built.contacts.size()},
                   {"couplings", built.system.bodies().empty() ? 0 : built.system.bodies().size() - 1},
                   {"supports", supports},
                   {"elements_per_body", c.input.settings.elements_per_body},
                   {"modes_per_body", c.input.settings.modes_per_body},
                   {"coupling_factor", c.input.settings.coupling_factor},
                   // The pipe above holds the top (model/string_above.hpp; model.top).
                   {"pipe_above", built.string_above.has_value()}};
  root["column_units"] = {{"s", out.Unit(Quantity::Length)},        {"md", out.Unit(Quantity::Length)},
                          {"position", out.Unit(Quantity::Length)}, {"displacement", out.Unit(Quantity::Diameter)},
                          {"rotation", "deg"},                      {"lateral_offset", out.Unit(Quantity::Diameter)},
                          {"force", out.Unit(Quantity::Force)},     {"moment", out.Unit(Quantity::Moment)},
                          {"stress", out.Unit(Quantity::Stress)},   {"frequency", "Hz"},
                          {"hole_offset", out.Unit(Quantity::Diameter)},
                          {"offset_high_side_angle", "deg"},
                          {"clearance", out.Unit(Quantity::Diameter)},
                          {"hole_diameter", out.Unit(Quantity::Diameter)}};
}

void AddOperation(const Case& c, const model::ModelInput& input, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  nlohmann::json operation = {{"weight_on_bit", out(input.operation.weight_on_bit, Quantity::WeightOnBit)},
                              {"rpm", out(input.operation.rotary_speed, Quantity::RotarySpeed)},
                              {"torque_on_bit", out(input.operation.torque_on_bit, Quantity::Moment)}};
  if (c.input.operation.hook_load) {
    operation["hook_load"] = out(*c.input.operation.hook_load, Quantity::Force);
    operation["string_above_weight"] = out(model::StringAboveWeight(input), Quantity::Force);
  }
  files.json()["operation"] = operation;
}

namespace {

// Station results: static.csv rows and the "nodes" of results.json. With a well (a node has_wall),
// the MD is the contact's (of the hole cross-section through the node) and the place in the hole
// is added: hole_offset, offset_high_side_angle, clearance, hole_diameter.
json AddStaticNodes(const Case& c, const std::vector<analyses::StaticNodeResult>& nodes, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  const bool in_hole = std::any_of(nodes.begin(), nodes.end(), [](const auto& node) { return node.has_wall; });
  std::vector<std::string> columns{"s",  "md", "x",  "y",  "z", "ux", "uy", "uz", "rx", "ry", "rz", "lateral_offset",
                                   "axial_force", "torque", "shear_force", "bending_moment", "bending_stress",
                                   "von_mises_stress"};
  const std::string length = out.Unit(Quantity::Length), diameter = out.Unit(Quantity::Diameter),
                    force = out.Unit(Quantity::Force), moment = out.Unit(Quantity::Moment),
                    stress = out.Unit(Quantity::Stress);
  std::vector<std::string> column_units{length,   length, length, length, length, diameter, diameter, diameter, "deg",
                                        "deg",    "deg",  diameter, force, moment, force, moment, stress, stress};
  if (in_hole) columns.insert(columns.end(), {"hole_offset", "offset_high_side_angle", "clearance", "hole_diameter"});
  if (in_hole) column_units.insert(column_units.end(), {diameter, "deg", diameter, diameter});
  CsvTable table(std::move(columns), std::move(column_units));
  json rows = json::array();
  for (const auto& node : nodes) {
    const double md = node.has_wall ? node.md : StationMd(c, node.s);
    const Vec3 rotation_deg = node.rotation / kDegree;
    std::vector<double> row{out(node.s, Quantity::Length),
                            out(md, Quantity::Length),
                            out(node.position.x(), Quantity::Length),
                            out(node.position.y(), Quantity::Length),
                            out(node.position.z(), Quantity::Length),
                            out(node.displacement.x(), Quantity::Diameter),
                            out(node.displacement.y(), Quantity::Diameter),
                            out(node.displacement.z(), Quantity::Diameter),
                            rotation_deg.x(),
                            rotation_deg.y(),
                            rotation_deg.z(),
                            out(node.lateral_offset, Quantity::Diameter),
                            out(node.axial_force, Quantity::Force),
                            out(node.torque, Quantity::Moment),
                            out(node.shear_force, Quantity::Force),
                            out(node.bending_moment, Quantity::Moment),
                            out(node.bending_stress, Quantity::Stress),
                            out(node.von_mises_stress, Quantity::Stress)};
    json entry = {{"s", out(node.s, Quantity::Length)},
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
                  {"von_mises_stress", out(node.von_mises_stress, Quantity::Stress)}};
    if (in_hole) {
      const std::vector<double> hole{out(node.hole_offset, Quantity::Diameter),
                                     node.offset_high_side_angle / kDegree,
                                     out(node.clearance, Quantity::Diameter),
                                     out(node.hole_diameter, Quantity::Diameter)};
      row.insert(row.end(), hole.begin(), hole.end());
      entry["hole_offset"] = hole[0];
      entry["offset_high_side_angle"] = hole[1];
      entry["clearance"] = hole[2];
      entry["hole_diameter"] = hole[3];
    }
    table.AddRow(row);
    rows.push_back(std::move(entry));
  }
  files.Add("static.csv", table.ToString());
  return rows;
}

// The wall contacts carrying force: contacts.csv (when there are any) and results.json.
json AddStaticContacts(const Case& c, const std::vector<analyses::ContactReport>& reports, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  json contacts = json::array();
  CsvTable contact_table({"s", "md", "normal_force", "friction_force", "high_side_angle", "component"},
                         {out.Unit(Quantity::Length), out.Unit(Quantity::Length), out.Unit(Quantity::Force),
                          out.Unit(Quantity::Force), "deg", "-"});
  for (const auto& contact : reports) {
    const double angle = contact.high_side_angle / kDegree;
    contact_table.AddCells({CsvTable::Number(out(contact.s, Quantity::Length)),
                            CsvTable::Number(out(contact.md, Quantity::Length)),
                            CsvTable::Number(out(contact.normal_force, Quantity::Force)),
                            CsvTable::Number(out(contact.friction_force, Quantity::Force)), CsvTable::Number(angle),
                            CsvTable::Text(c.input.string.components.at(contact.component).name)});
    contacts.push_back({{"s", out(contact.s, Quantity::Length)},
                        {"md", out(contact.md, Quantity::Length)},
                        {"component", c.input.string.components.at(contact.component).name},
                        {"normal_force", out(contact.normal_force, Quantity::Force)},
                        {"friction_force", out(contact.friction_force, Quantity::Force)},
                        {"high_side_angle", angle}});
  }
  if (!reports.empty()) files.Add("contacts.csv", contact_table.ToString());
  return contacts;
}

json BitJson(const Case& c, const analyses::BitReport& bit) {
  const OutputUnits out{c.output_units};
  const analyses::BitTendency tendency = analyses::ClassifyBitTendency(bit);
  return {{"side_force", out(bit.side_force, Quantity::Force)},
          {"build_force", out(bit.build_force, Quantity::Force)},
          {"walk_force", out(bit.walk_force, Quantity::Force)},
          {"tilt", bit.tilt / kDegree},
          {"tendency",
           {{"inclination", analyses::TendencyName(tendency.inclination)},
            {"azimuth", analyses::TendencyName(tendency.azimuth)},
            {"threshold", out(tendency.threshold, Quantity::Force)}}}};
}

// The string's limits along the static (analyses/string_limits.hpp): per-station arrays, the buckled
// zones, each limit's largest utilisation and the closest; a limit that does not apply is 0 at a station
// and left out of the summary.
json StaticLimitsJson(const Case& c, const analyses::StaticResult& result) {
  const OutputUnits out{c.output_units};
  const analyses::StringLimits limits = analyses::ComputeStringLimits(c.input, result.nodes, c.limits.design_factor);
  json s = json::array(), md = json::array(), yield = json::array(), allowable = json::array(),
       von_mises = json::array(), stress = json::array(), makeup = json::array(), torque = json::array(),
       sinusoidal = json::array(), helical = json::array(), buckling = json::array(), state = json::array(),
       fatigue_stress = json::array(), fatigue_allowable = json::array(), fatigue = json::array(),
       dogleg = json::array(), max_dogleg = json::array();
  // A limit that does not apply at a station (the bit, a material without a yield, no make-up torque
  // given, no room to buckle into) is written 0: results.json holds no null.
  const auto shown = [&out](double si, Quantity quantity) {
    return std::isfinite(si) ? out(si, quantity) : 0.0;
  };
  const auto ratio = [](double value) { return std::isfinite(value) ? value : 0.0; };
  for (const analyses::NodeLimits& node : limits.nodes) {
    s.push_back(out(node.s, Quantity::Length));
    md.push_back(out(node.md, Quantity::Length));
    yield.push_back(shown(node.yield, Quantity::Stress));
    allowable.push_back(shown(node.allowable_stress, Quantity::Stress));
    von_mises.push_back(shown(node.von_mises_stress, Quantity::Stress));
    stress.push_back(ratio(node.stress_utilisation));
    makeup.push_back(shown(node.makeup_torque, Quantity::Moment));
    torque.push_back(ratio(node.torque_utilisation));
    sinusoidal.push_back(shown(node.sinusoidal_load, Quantity::Force));
    helical.push_back(shown(node.helical_load, Quantity::Force));
    buckling.push_back(ratio(node.buckling_utilisation));
    state.push_back(analyses::BucklingStateName(node.buckling));
    fatigue_stress.push_back(shown(node.fatigue_bending_stress, Quantity::Stress));
    fatigue_allowable.push_back(shown(node.allowable_bending_stress, Quantity::Stress));
    fatigue.push_back(ratio(node.fatigue_utilisation));
    dogleg.push_back(shown(node.hole_curvature, Quantity::DoglegSeverity));
    max_dogleg.push_back(shown(node.max_dogleg, Quantity::DoglegSeverity));
  }
  json zones = json::array();
  for (const analyses::BuckledZone& zone : limits.zones) {
    zones.push_back({{"kind", analyses::BucklingStateName(zone.state)},
                     {"md_from", out(zone.md_from, Quantity::Length)},
                     {"md_to", out(zone.md_to, Quantity::Length)}});
  }
  // Each limit's largest utilisation; a limit that applies nowhere is left out.
  json summary = json::object();
  for (const auto& [key, limit] : {std::pair{"yield", &limits.yield}, std::pair{"makeup_torque", &limits.makeup_torque},
                                   std::pair{"helical_buckling", &limits.helical_buckling},
                                   std::pair{"fatigue", &limits.fatigue}, std::pair{"closest", &limits.closest}}) {
    json entry = UtilisationJson(c, *limit);
    if (!entry.is_null()) summary[key] = std::move(entry);
  }
  // The worst station for fatigue: the hole's dogleg there and Lubinski's permissible one (pipe, HWDP).
  if (summary.contains("fatigue")) {
    const auto at = std::find_if(limits.nodes.begin(), limits.nodes.end(), [&limits](const analyses::NodeLimits& node) {
      return node.s == limits.fatigue.s && node.fatigue_utilisation == limits.fatigue.utilisation;
    });
    if (at != limits.nodes.end()) {
      summary["fatigue"]["dogleg_severity"] = shown(at->hole_curvature, Quantity::DoglegSeverity);
      if (std::isfinite(at->max_dogleg)) {
        summary["fatigue"]["max_dogleg_severity"] = shown(at->max_dogleg, Quantity::DoglegSeverity);
      }
      summary["fatigue"]["bending_stress"] = shown(at->fatigue_bending_stress, Quantity::Stress);
      summary["fatigue"]["allowable_bending_stress"] = shown(at->allowable_bending_stress, Quantity::Stress);
    }
  }
  return {{"design_factor", limits.design_factor},
          {"nodes",
           {{"s", s},
            {"md", md},
            {"yield", yield},
            {"allowable_stress", allowable},
            {"von_mises_stress", von_mises},
            {"stress_utilisation", stress},
            {"makeup_torque", makeup},
            {"torque_utilisation", torque},
            {"sinusoidal_load", sinusoidal},
            {"helical_load", helical},
            {"buckling_utilisation", buckling},
            {"buckling", state},
            {"fatigue_bending_stress", fatigue_stress},
            {"allowable_bending_stress", fatigue_allowable},
            {"fatigue_utilisation", fatigue},
            {"dogleg_severity", dogleg},
            {"max_dogleg_severity", max_dogleg}}},
          {"buckled_zones", zones},
          {"summary", summary},
          {"notes", limits.notes}};
}

}  // namespace

void AddStaticResults(const Case& c, const analyses::StaticResult& result, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  json reactions = json::array();
  for (const auto& reaction : result.reactions) {
    reactions.push_back({{"s", out(reaction.s, Quantity::Length)},
                         {"force", out.Vector(reaction.force, Quantity::Force)},
                         {"moment", out.Vector(reaction.moment, Quantity::Moment)}});
  }
  files.json()["static"] = {{"converged", result.converged},
                            {"method_used", result.method},
                            {"warnings", result.warnings},
                            {"iterations", result.iterations},
                            {"load_steps", result.load_steps},
                            {"residual_norm", out(result.residual_norm, Quantity::Force)},
                            {"nodes", AddStaticNodes(c, result.nodes, files)},
                            {"contacts", AddStaticContacts(c, result.contacts, files)},
                            {"reactions", reactions},
                            {"limits", StaticLimitsJson(c, result)},
                            {"table", "static.csv"}};
  if (result.bit) files.json()["static"]["bit"] = BitJson(c, *result.bit);
  if (result.pipe_above) {
    const analyses::PipeAboveReaction& pipe = *result.pipe_above;
    files.json()["static"]["pipe_above"] = {{"s", out(pipe.s, Quantity::Length)},
                                            {"force", out.Vector(pipe.force, Quantity::Force)},
                                            {"moment", out.Vector(pipe.moment, Quantity::Moment)},
                                            {"tension", out(pipe.tension, Quantity::Force)},
                                            {"buckled", pipe.buckled}};
  }
  if (result.mwd) {
    const analyses::MwdSag& mwd = *result.mwd;
    files.json()["static"]["mwd"] = {{"s", out(mwd.s, Quantity::Length)},
                                     {"md", out(mwd.md, Quantity::Length)},
                                     {"axis_inclination", out(mwd.axis_inclination, Quantity::Angle)},
                                     {"hole_inclination", out(mwd.hole_inclination, Quantity::Angle)},
                                     {"sag", out(mwd.sag, Quantity::Angle)},
                                     {"axis_azimuth", out(mwd.axis_azimuth, Quantity::Angle)},
                                     {"hole_azimuth", out(mwd.hole_azimuth, Quantity::Angle)}};
  }
}

void AddModesResults(const Case& c, const analyses::ModesResult& result, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  std::vector<std::string> columns{"mode", "frequency_hz", "damping_ratio", "axial_fraction", "torsional_fraction",
                                   "lateral_fraction"};
  std::vector<std::string> column_units{"-", "Hz", "-", "-", "-", "-"};
  if (result.gyroscopic) columns.push_back("whirl_index"), column_units.push_back("-");
  CsvTable frequencies(columns, column_units);
  // Mode shapes are normalized (the largest displacement 1): their entries have no unit.
  CsvTable shapes({"mode", "s", "ux", "uy", "uz", "rx", "ry", "rz"}, {"-", out.Unit(Quantity::Length), "-", "-", "-", "-", "-", "-"});
  json modes = json::array();
  for (std::size_t m = 0; m < result.modes.size(); ++m) {
    const auto& mode = result.modes[m];
    std::vector<double> row{static_cast<double>(m + 1), mode.frequency_hz,        mode.damping_ratio,
                            mode.axial_fraction,        mode.torsional_fraction, mode.lateral_fraction};
    if (result.gyroscopic) row.push_back(mode.whirl_index);
    frequencies.AddRow(row);
    for (std::size_t i = 0; i < result.s.size() && i < mode.displacement.size(); ++i) {
      shapes.AddRow({static_cast<double>(m + 1), out(result.s[i], Quantity::Length), mode.displacement[i].x(),
                     mode.displacement[i].y(), mode.displacement[i].z(), mode.rotation[i].x(), mode.rotation[i].y(),
                     mode.rotation[i].z()});
    }
    modes.push_back({{"frequency_hz", mode.frequency_hz},
                     {"damping_ratio", mode.damping_ratio},
                     {"kind", analyses::ModeKindName(mode.kind)},
                     {"rigid_body", mode.rigid_body},
                     {"near_zero", mode.near_zero},
                     {"negative_stiffness", mode.negative_stiffness},
                     {"axial_fraction", mode.axial_fraction},
                     {"torsional_fraction", mode.torsional_fraction},
                     {"lateral_fraction", mode.lateral_fraction}});
    if (result.gyroscopic) {
      modes.back()["whirl"] = analyses::WhirlName(mode.whirl);
      modes.back()["whirl_index"] = mode.whirl_index;
    }
  }
  if (result.gyroscopic) {
    files.json()["gyroscopic"] = {{"rpm", out(result.rotary_speed, Quantity::RotarySpeed)},
                                  {"basis_size", result.basis_size}};
  }
  files.Add("modes.csv", frequencies.ToString());
  files.Add("mode_shapes.csv", shapes.ToString());
  files.json()["modes"] = modes;
  // The first lateral mode at 1× rotation beside the field rule of thumb (validation.md V6).
  const RuleOfThumbSpeed rule = ComputeRuleOfThumbCriticalSpeed(c);
  json critical = {{"rule_of_thumb", out(rule.rotary_speed, Quantity::RotarySpeed)},
                   {"rule_of_thumb_span", out(rule.span, Quantity::Length)}};
  if (const analyses::ModeResult* lateral = analyses::FirstLateralMode(result)) {
    critical["first_lateral"] = 60.0 * lateral->frequency_hz;
  }
  files.json()["critical_rpm"] = critical;
}

void AddBucklingResults(const Case& c, const analyses::BucklingResult& result, ResultFiles& files) {
  const OutputUnits out{c.output_units};
  CsvTable table({"load_factor", "compression", "frequency_hz"}, {"-", out.Unit(Quantity::Force), "Hz"});
  json points = json::array();
  for (const auto& point : result.frequency_table) {
    table.AddRow({point.load_factor, out(point.compression, Quantity::Force), point.frequency_hz});
    points.push_back({{"load_factor", point.load_factor},
                      {"compression", out(point.compression, Quantity::Force)},
                      {"frequency_hz", point.frequency_hz}});
  }
  files.Add("buckling.csv", table.ToString());
  // The buckled shape: per station its s and the displacement (string frame, largest = 1).
  json mode_s = json::array(), mode_displacement = json::array();
  for (std::size_t i = 0; i < result.s.size() && i < result.mode_displacement.size(); ++i) {
    mode_s.push_back(out(result.s[i], Quantity::Length));
    const Vec3& d = result.mode_displacement[i];
    mode_displacement.push_back(json::array({d.x(), d.y(), d.z()}));
  }
  files.json()["buckling"] = {
      {"scaled", result.scaled_wob ? "wob" : "all"},
      {"method", result.about_equilibrium ? "lateral frequency about the equilibrium" : "eigenproblem"},
      {"load_factor", result.load_factor},
      {"critical_load", out(result.critical_load, Quantity::Force)},
      {"load_factors", result.load_factors},
      {"reference_compression", out(result.reference_compression, Quantity::Force)},
      {"mode", {{"s", mode_s}, {"displacement", mode_displacement}}},
      {"frequency_method",
       {{"converged", result.frequency_method_converged},
        {"load_factor", result.frequency_load_factor},
        {"critical_load", out(result.frequency_critical_load, Quantity::Force)},
        {"unloaded_frequency_hz", result.unloaded_frequency_hz},
        {"table", points}}}};
  if (result.critical_wob > 0.0) files.json()["buckling"]["critical_wob"] = out(result.critical_wob, Quantity::Force);
  // No onset up to load_factor (analyses::BucklingResult::lower_bound): the loads there are lower bounds.
  if (result.lower_bound) files.json()["buckling"]["lower_bound"] = true;
  // The string lies buckled at the case's loads; the onset was searched below them (load_factor < 1).
  if (result.buckled_at_case_loads) files.json()["buckling"]["buckled_at_case_loads"] = true;
  // The onset is the pipe above the model reaching F_sin (model/string_above.hpp).
  if (result.onset_above_model) files.json()["buckling"]["onset_above_model"] = true;
  if (result.sinusoidal.computed) {
    const analyses::SinusoidalBucklingScreen& screen = result.sinusoidal;
    files.json()["buckling"]["dawson_paslay"] = {
        {"load_factor", screen.load_factor},
        {"s", out(screen.s, Quantity::Length)},
        {"md", out(screen.md, Quantity::Length)},
        {"compression", out(screen.compression, Quantity::Force)},
        {"sinusoidal_load", out(screen.sinusoidal_load, Quantity::Force)},
        {"helical_load", out(screen.helical_load, Quantity::Force)},
        {"largest_ratio", screen.largest_ratio}};
  }
}

}  // namespace drillflex::io
