// "vibration" and vibration.csv; the rule-of-thumb critical RPM beside the modes.
#include <algorithm>
#include <cmath>

#include "io/analysis_results.hpp"

namespace drillflex::io {
namespace {

using nlohmann::json;
using units::Quantity;

}  // namespace

RuleOfThumbSpeed ComputeRuleOfThumbCriticalSpeed(const Case& c) {
  RuleOfThumbSpeed rule;
  if (c.input.string.components.empty()) return rule;
  // The span: between the outermost supports that hold the string laterally; else, for drill pipe
  // or HWDP with tool joints, one joint spacing (the rule's own use: the pipe between two joints
  // that touch the wall); else the whole string.
  double lowest = 1e300, highest = -1e300;
  for (const model::Support& support : c.input.supports) {
    if (!support.fixed[model::kY] && !support.fixed[model::kZ]) continue;
    lowest = std::min(lowest, support.at);
    highest = std::max(highest, support.at);
  }
  double length = 0.0, longest = -1.0;
  const model::Component* dominant = nullptr;
  for (const model::Component& component : c.input.string.components) {
    const double span = component.length * component.count;
    length += span;
    if (span > longest) longest = span, dominant = &component;
  }
  rule.span = length;
  if (highest > lowest) {
    rule.span = highest - lowest;
  } else if (dominant->joint_diameter) {
    rule.span = dominant->joint_spacing.value_or(std::min(model::kDefaultJointSpacing, dominant->length));
  }
  rule.outer_diameter = dominant->outer_diameter;
  rule.inner_diameter = dominant->inner_diameter;
  // 33,055 sqrt(OD² + ID²)/L² rpm, OD and ID in in, L in ft (validation.md V6; ±15 %): 60 × the
  // first frequency of a pinned-pinned steel tube of that span, π/(2L²) sqrt(EI/m).
  const double od = rule.outer_diameter / 0.0254, id = rule.inner_diameter / 0.0254, span_ft = rule.span / 0.3048;
  rule.rotary_speed = 33055.0 * std::sqrt(od * od + id * id) / (span_ft * span_ft) * kPi / 30.0;
  return rule;
}

void AddVibrationResults(const Case& c, const analyses::VibrationResult& result, ResultFiles& files) {
  auto out = [&](double si, Quantity quantity) { return units::FromSI(si, quantity, c.output_units); };
  const bool ratio = !result.max_clearance_ratio.empty();
  std::vector<std::string> columns = {"rpm", "max_lateral_displacement", "s_max_displacement", "max_bending_stress",
                                      "max_contact_force"};
  auto unit = [&](Quantity quantity) { return std::string(units::DefaultUnit(quantity, c.output_units)); };
  std::vector<std::string> column_units = {unit(Quantity::RotarySpeed), unit(Quantity::Diameter), unit(Quantity::Length),
                                           unit(Quantity::Stress), unit(Quantity::Force)};
  if (ratio) columns.push_back("max_clearance_ratio"), column_units.push_back("-");
  CsvTable table(columns, column_units);
  json rpm = json::array(), displacement = json::array(), stress = json::array(), contact = json::array(),
       clearance = json::array(), where = json::array();
  for (std::size_t i = 0; i < result.rotary_speeds.size(); ++i) {
    std::vector<double> row = {out(result.rotary_speeds[i], Quantity::RotarySpeed),
                               out(result.max_lateral_displacement[i], Quantity::Diameter),
                               out(result.s_max_displacement[i], Quantity::Length),
                               out(result.max_bending_stress[i], Quantity::Stress),
                               out(result.max_contact_force[i], Quantity::Force)};
    if (ratio) row.push_back(result.max_clearance_ratio[i]);
    table.AddRow(row);
    rpm.push_back(row[0]);
    displacement.push_back(row[1]);
    where.push_back(row[2]);
    stress.push_back(row[3]);
    contact.push_back(row[4]);
    if (ratio) clearance.push_back(result.max_clearance_ratio[i]);
  }
  json critical = json::array(), windows = json::array(), quiet = json::array();
  for (const auto& window : result.quietest_windows) {
    quiet.push_back({{"from", out(window.from, Quantity::RotarySpeed)}, {"to", out(window.to, Quantity::RotarySpeed)}});
  }
  for (const double value : result.critical_rotary_speeds) critical.push_back(out(value, Quantity::RotarySpeed));
  json ranked = json::array();
  for (const analyses::CriticalSpeed& speed : result.critical_speeds) {
    ranked.push_back({{"rpm", out(speed.rotary_speed, Quantity::RotarySpeed)},
                      {"severity", ratio ? speed.severity : out(speed.severity, Quantity::Diameter)},
                      {"max_lateral_displacement", out(speed.displacement, Quantity::Diameter)},
                      {"max_bending_stress", out(speed.bending_stress, Quantity::Stress)},
                      {"excitation", speed.excitation},
                      {"frequency_hz", speed.frequency / (2.0 * kPi)}});
  }
  for (const auto& window : result.safe_windows) {
    windows.push_back({{"from", out(window.from, Quantity::RotarySpeed)}, {"to", out(window.to, Quantity::RotarySpeed)}});
  }
  json block = {{"rpm", rpm},
                {"max_lateral_displacement", displacement},
                {"s_max_displacement", where},
                {"max_bending_stress", stress},
                {"max_contact_force", contact},
                {"critical_rpm", critical},
                {"critical_speeds", ranked},
                {"safe_windows", windows},
                {"quietest_windows", quiet},
                {"clearance_fraction", result.clearance_fraction},
                {"stress_limit", out(result.stress_limit, Quantity::Stress)},
                {"closed_contacts", result.closed_contacts},
                {"method", result.method == analyses::VibrationMethod::Reduced ? "reduced" : "direct"}};
  if (result.method == analyses::VibrationMethod::Reduced) block["basis_size"] = result.basis_size;
  if (result.basis_size > 0) block["reduced_check_error"] = result.reduced_check_error;
  if (result.band_modes >= 0) block["band_modes"] = result.band_modes;
  if (!result.method_note.empty()) block["method_note"] = result.method_note;
  if (ratio) block["max_clearance_ratio"] = clearance;
  // One curve per excitation: the largest displacement amplitude of its own response at each RPM.
  json by_excitation = json::array();
  for (const std::vector<double>& curve : result.excitation_displacement) {
    json values = json::array();
    for (const double value : curve) values.push_back(out(value, Quantity::Diameter));
    by_excitation.push_back(values);
  }
  block["excitation_displacement"] = by_excitation;
  files.Add("vibration.csv", table.ToString());
  files.json()["vibration"] = block;
}

}  // namespace drillflex::io
