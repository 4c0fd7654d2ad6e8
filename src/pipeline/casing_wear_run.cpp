#include "pipeline/casing_wear_run.hpp"

#include <algorithm>
#include <cmath>

#include "analyses/soft_string.hpp"
#include "model/casing_wear.hpp"
#include "pipeline/roadmap.hpp"
#include "well/hole.hpp"

namespace drillflex::pipeline {
namespace {

using units::Quantity;

// The depths of the run and the rotating time at each: the bit MD alone, or every joint spacing from
// `from` to the bit MD drilled at the ROP (each depth rotating while the next stretch is drilled).
std::vector<std::pair<double, double>> RunDepths(const io::Case& c, const io::WearConfig& wear) {
  const double bit_md = c.well->bit_md;
  if (wear.rotating_time) return {{bit_md, *wear.rotating_time}};
  std::vector<std::pair<double, double>> depths;
  const double step = model::kDefaultJointSpacing;
  for (double md = *wear.from_md; md < bit_md - 1e-9; md += step) {
    const double next = std::min(md + step, bit_md);
    depths.emplace_back(next, (next - md) / *wear.rate_of_penetration);
  }
  return depths;
}

}  // namespace

std::vector<CasingWearStation> CasingWearStations(const io::Case& c) {
  const well::HoleProfile hole(c.well->hole);
  double deepest = 0.0;  // the deepest cased MD
  for (std::size_t i = 0; i < c.well->hole.size(); ++i) {
    if (c.well->hole[i].cased) deepest = c.well->hole[i].to_md.value_or(c.well->bit_md);
  }
  std::vector<CasingWearStation> stations;
  const int count = static_cast<int>(std::floor(std::min(deepest, c.well->bit_md) / kWearStep + 1e-9)) + 1;
  for (int i = 0; i < count; ++i) {
    CasingWearStation station;
    station.md = i * kWearStep;
    const well::HoleSection& section = hole.SectionAt(station.md);
    station.bore_diameter = hole.Diameter(station.md);
    station.wall = section.cased ? section.wall.value_or(0.0) : 0.0;
    stations.push_back(station);
  }
  return stations;
}

void AddRotatingWear(const io::Case& c, const model::ModelInput& at, analyses::SoftStringOperation friction,
                     double time, std::vector<CasingWearStation>& stations) {
  const io::WearConfig& wear = *c.limits.wear;
  const well::HoleProfile hole(c.well->hole);
  analyses::SoftStringOperation& operation = friction;
  operation.motion = analyses::SoftStringMotion::Rotating;
  operation.weight_on_bit = at.operation.weight_on_bit;
  operation.torque_on_bit = at.operation.torque_on_bit;
  operation.max_element_length = kWearStep;
  const analyses::SoftStringResult soft = analyses::ComputeSoftString(at, operation);
  // Each element (between a station and the one below it) spreads its wall force over its length.
  for (std::size_t k = 1; k < soft.stations.size(); ++k) {
    const analyses::SoftStringStation& upper = soft.stations[k];
    const double lower_md = soft.stations[k - 1].md;
    const double length = lower_md - upper.md;
    if (!(length > 0.0)) continue;
    const double per_length = upper.normal_force / length;
    const double joint = model::ContactDiameter(model::ComponentAt(at.string, upper.s));
    const double worn = model::WornVolumePerLength(wear.wear_factor, per_length, joint, wear.rotary_speed, time);
    for (CasingWearStation& station : stations) {
      if (station.md < upper.md || station.md >= lower_md || !hole.SectionAt(station.md).cased) continue;
      station.side_force_per_length = std::max(station.side_force_per_length, per_length);
      station.worn_area += worn;
      if (worn > 0.0) station.joint_diameter = joint;
    }
  }
}

void FinishCasingWear(std::vector<CasingWearStation>& stations) {
  for (CasingWearStation& station : stations) {
    if (station.joint_diameter > 0.0) {
      station.groove_depth =
          model::GrooveDepth(0.5 * station.bore_diameter, 0.5 * station.joint_diameter, station.worn_area);
    }
    if (station.wall > 0.0) {
      station.remaining_wall = std::max(station.wall - station.groove_depth, 0.0);
      station.wear_utilisation = station.groove_depth / station.wall;
    }
  }
}

CasingWear ComputeCasingWear(const io::Case& c) {
  CasingWear result;
  result.stations = CasingWearStations(c);
  analyses::SoftStringOperation friction;  // the case's: model.contact.friction, each cased section its own
  friction.axial_friction = friction.tangential_friction = c.input.settings.contact.friction;
  for (const auto& [bit_md, time] : RunDepths(c, *c.limits.wear)) {
    AddRotatingWear(c, CaseAtDepth(c, bit_md).input, friction, time, result.stations);
    result.rotating_time += time;
    ++result.depths;
  }
  FinishCasingWear(result.stations);
  return result;
}

void AddCasingWearResults(const io::Case& c, io::ResultFiles& files) {
  if (!c.limits.wear || !c.well) return;
  const CasingWear wear = ComputeCasingWear(c);
  const units::System system = c.output_units;
  const auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system) + 0.0; };
  const auto unit = [system](Quantity quantity) { return std::string(units::DefaultUnit(quantity, system)); };
  // An area in the diameters' unit squared (in² or m²).
  const auto area = [&out](double si) { return out(out(si, Quantity::Diameter), Quantity::Diameter); };
  const std::string area_unit = unit(Quantity::Diameter) + "2";
  io::CsvTable table({"md", "side_force_per_length", "worn_area", "joint_diameter", "bore_diameter", "groove_depth",
                      "wall", "remaining_wall", "wear_utilisation"},
                     {unit(Quantity::Length), unit(Quantity::ForcePerLength), area_unit, unit(Quantity::Diameter),
                      unit(Quantity::Diameter), unit(Quantity::Diameter), unit(Quantity::Diameter),
                      unit(Quantity::Diameter), "-"});
  const CasingWearStation* worst = nullptr;
  nlohmann::json md = nlohmann::json::array(), force = nlohmann::json::array(), groove = nlohmann::json::array(),
                 wall = nlohmann::json::array(), remaining = nlohmann::json::array();
  for (const CasingWearStation& station : wear.stations) {
    md.push_back(out(station.md, Quantity::Length));
    force.push_back(out(station.side_force_per_length, Quantity::ForcePerLength));
    groove.push_back(out(station.groove_depth, Quantity::Diameter));
    wall.push_back(out(station.wall, Quantity::Diameter));
    remaining.push_back(out(station.remaining_wall, Quantity::Diameter));
    table.AddRow({out(station.md, Quantity::Length), out(station.side_force_per_length, Quantity::ForcePerLength),
                  area(station.worn_area), out(station.joint_diameter, Quantity::Diameter),
                  out(station.bore_diameter, Quantity::Diameter), out(station.groove_depth, Quantity::Diameter),
                  out(station.wall, Quantity::Diameter), out(station.remaining_wall, Quantity::Diameter),
                  station.wear_utilisation});
    if (!worst || station.groove_depth > worst->groove_depth) worst = &station;
  }
  files.Add("casing_wear.csv", table.ToString());
  const io::WearConfig& config = *c.limits.wear;
  nlohmann::json json = {{"wear_factor", out(config.wear_factor, Quantity::WearFactor)},
                         {"rpm", out(config.rotary_speed, Quantity::RotarySpeed)},
                         {"rotating_time", out(wear.rotating_time, Quantity::Time)},
                         {"depths", wear.depths},
                         {"stations",
                          {{"md", md},
                           {"side_force_per_length", force},
                           {"groove_depth", groove},
                           {"wall", wall},
                           {"remaining_wall", remaining}}},
                         {"table", "casing_wear.csv"}};
  if (worst && worst->groove_depth > 0.0) {
    json["deepest_groove"] = {{"md", out(worst->md, Quantity::Length)},
                              {"side_force_per_length", out(worst->side_force_per_length, Quantity::ForcePerLength)},
                              {"worn_area", area(worst->worn_area)},
                              {"groove_depth", out(worst->groove_depth, Quantity::Diameter)}};
    if (worst->wall > 0.0) {
      json["deepest_groove"]["wall"] = out(worst->wall, Quantity::Diameter);
      json["deepest_groove"]["remaining_wall"] = out(worst->remaining_wall, Quantity::Diameter);
      json["deepest_groove"]["utilisation"] = worst->wear_utilisation;
    }
  }
  files.json()["static"]["casing_wear"] = json;
}

}  // namespace drillflex::pipeline
