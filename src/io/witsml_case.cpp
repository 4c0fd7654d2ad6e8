// ImportedCaseText: the survey, the hole and the string of WITSML documents as a case file. A value is
// written bare when its unit is the case system's for its quantity (ft and in for `units: field`, m
// for SI), else with its own unit ("171.45 mm"); the numbers are the documents' own text.
#include "io/witsml_case.hpp"

#include <cctype>
#include <string_view>

#include <fmt/format.h>

#include "core/error.hpp"
#include "units/units.hpp"

namespace drillflex::io {
namespace {

using model::ComponentType;
using units::Quantity;

// A YAML scalar for a name: plain when it is plainly text, else double-quoted.
std::string YamlText(const std::string& text) {
  bool plain = !text.empty() && std::isalpha(static_cast<unsigned char>(text.front()));
  for (const char c : text) {
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || std::string_view(" -_./()+").find(c) != std::string_view::npos);
  }
  if (plain && text.back() != ' ') return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted.push_back('\\');
    if (static_cast<unsigned char>(c) >= 0x20) quoted.push_back(c);
  }
  return quoted + "\"";
}

class ValueText {
 public:
  explicit ValueText(units::System system) : system_(system) {}

  // The value for the case: bare in the case's default unit of the quantity, else with its own.
  std::string operator()(const WitsmlValue& value, Quantity quantity) const {
    if (value.uom.empty()) {  // computed here, in SI
      return fmt::format("{:.12g}", units::FromSI(value.si, quantity, system_));
    }
    const double factor = units::ParseUnit(value.uom).to_si;
    const double default_factor = units::ParseUnit(units::DefaultUnit(quantity, system_)).to_si;
    if (factor == default_factor) return value.text;
    return fmt::format("\"{} {}\"", value.text, value.uom == "dega" ? "deg" : value.uom);
  }

 private:
  units::System system_;
};

std::string Where(const WitsmlOrigin& origin) { return fmt::format("{}:{}", origin.file, origin.line); }

struct Objects {
  const WitsmlTrajectory* trajectory = nullptr;
  const WitsmlGeometry* geometry = nullptr;
  const WitsmlTubular* tubular = nullptr;
  std::vector<std::string> sources;  // "file: WITSML 1.4.1.1 trajectory 'X'"
};

template <class Object>
void Take(const Object& object, const std::string& version, const Object*& slot, Objects& objects) {
  if (slot) {
    throw InputError({object.origin.file, object.origin.line, 0}, "",
                     fmt::format("a second {} (the first: {} at {}): import one well and one string at a time",
                                 object.origin.what, slot->origin.what, Where(slot->origin)));
  }
  slot = &object;
  objects.sources.push_back(fmt::format("{}: WITSML {} {}", Where(object.origin), version, object.origin.what));
}

Objects Gather(const std::vector<WitsmlDocument>& documents) {
  Objects objects;
  for (const WitsmlDocument& document : documents) {
    for (const auto& trajectory : document.trajectories) Take(trajectory, document.version, objects.trajectory, objects);
    for (const auto& geometry : document.geometries) Take(geometry, document.version, objects.geometry, objects);
    for (const auto& tubular : document.tubulars) Take(tubular, document.version, objects.tubular, objects);
  }
  const std::string first = documents.empty() ? "" : documents.front().file;
  if (!objects.tubular) {
    throw InputError({first, 0, 0}, "", "no tubular among the documents: a case needs the string (a tubular object)");
  }
  if (objects.trajectory && !objects.geometry) {
    throw InputError({objects.trajectory->origin.file, objects.trajectory->origin.line, 0}, "",
                     "a trajectory without a wbGeometry: the case's well needs the hole diameters (give the "
                     "wbGeometry document too)");
  }
  if (objects.geometry && !objects.trajectory) {
    throw InputError({objects.geometry->origin.file, objects.geometry->origin.line, 0}, "",
                     "a wbGeometry without a trajectory: the case's well needs the survey (give the trajectory "
                     "document too)");
  }
  return objects;
}

// field when the documents' depths (the survey's, else the string's lengths) are in feet.
units::System SystemOf(const Objects& objects) {
  const WitsmlValue& length = objects.trajectory ? objects.trajectory->stations.front().md
                                                 : objects.tubular->components.front().length;
  return length.uom == "ft" || length.uom == "ftUS" ? units::System::Field : units::System::SI;
}

void WriteWell(const Objects& objects, const ValueText& value, std::string& text) {
  const WitsmlTrajectory& trajectory = *objects.trajectory;
  text += "well:\n";
  text += fmt::format("  # {} ({}): MD, inclination, azimuth\n  survey:\n", trajectory.origin.what, Where(trajectory.origin));
  for (const WitsmlStation& station : trajectory.stations) {
    text += fmt::format("    - [{}, {}, {}]  # {} {}\n", value(station.md, Quantity::Length),
                        value(station.inclination, Quantity::Angle), value(station.azimuth, Quantity::Angle),
                        Where(station.origin), station.origin.what);
  }
  const WitsmlGeometry& geometry = *objects.geometry;
  text += fmt::format("  # {} ({}): the hole diameter by MD, top down\n  hole:\n", geometry.origin.what,
                      Where(geometry.origin));
  for (std::size_t i = 0; i < geometry.hole.size(); ++i) {
    const WitsmlHoleInterval& interval = geometry.hole[i];
    const bool last = i + 1 == geometry.hole.size();
    const std::string to = last ? "" : fmt::format("to: {}, ", value(interval.bottom, Quantity::Length));
    text += fmt::format("    - {{{}diameter: {}{}}}  # {} {} ({}) from {} {}{}\n", to,
                        value(interval.diameter, Quantity::Diameter), interval.cased ? ", cased: true" : "",
                        Where(interval.origin), interval.origin.what,
                        interval.source, interval.top.text, interval.top.uom,
                        last ? fmt::format(" to the bottom (the document: {} {})", interval.bottom.text, interval.bottom.uom)
                             : "");
  }
}

std::string ComponentLine(const WitsmlComponent& component, const ValueText& value) {
  std::string line = fmt::format("{{type: {}", model::ComponentTypeName(component.type));
  if (!component.name.empty()) line += fmt::format(", name: {}", YamlText(component.name));
  line += fmt::format(", od: {}", value(component.od, Quantity::Diameter));
  if (component.id) line += fmt::format(", id: {}", value(*component.id, Quantity::Diameter));
  line += fmt::format(", length: {}", value(component.length, Quantity::Length));
  if (component.count != 1) line += fmt::format(", count: {}", component.count);
  if (!component.material.empty()) line += fmt::format(", material: {}", component.material);
  const auto add = [&](const char* key, const std::optional<WitsmlValue>& field, Quantity quantity) {
    if (field) line += fmt::format(", {}: {}", key, value(*field, quantity));
  };
  add("blade_od", component.blade_od, Quantity::Diameter);
  add("blade_length", component.blade_length, Quantity::Length);
  add("joint_od", component.joint_od, Quantity::Diameter);
  add("joint_id", component.joint_id, Quantity::Diameter);
  add("joint_length", component.joint_length, Quantity::Length);
  add("bend", component.bend, Quantity::Angle);
  if (component.bend) add("bend_to_bit", component.bend_to_bit, Quantity::Length);
  if (component.lobes) line += fmt::format(", lobes: {}", *component.lobes);
  if (!component.grade.empty()) line += fmt::format(", grade: {}", component.grade);
  add("makeup_torque", component.makeup_torque, Quantity::Moment);
  return line + "}";
}

}  // namespace

std::string ImportedCaseText(const std::vector<WitsmlDocument>& documents) {
  const Objects objects = Gather(documents);
  const units::System system = SystemOf(objects);
  const ValueText value(system);
  std::string text = "# Imported by `drillflex import` from\n";
  for (const std::string& source : objects.sources) text += fmt::format("#   {}\n", source);
  std::size_t warnings = 0;
  for (const WitsmlDocument& document : documents) warnings += document.warnings.size();
  if (warnings > 0) {
    text += "# Fields the documents give that drillflex does not read:\n";
    for (const WitsmlDocument& document : documents) {
      for (const std::string& warning : document.warnings) text += fmt::format("#   {}\n", warning);
    }
  }
  text += "# Add the fluid, model settings, operation and analyses the job needs (docs/case-format.md).\n";
  const std::string& name = objects.tubular->name;
  text += fmt::format("name: {}\nunits: {}\n\n", YamlText(name.empty() ? "imported" : name),
                      system == units::System::Field ? "field" : "SI");
  if (objects.trajectory) {
    WriteWell(objects, value, text);
    text += "\n";
  }
  const WitsmlTubular& tubular = *objects.tubular;
  text += fmt::format("string:  # {} ({}), from the bit up\n", tubular.origin.what, Where(tubular.origin));
  for (const WitsmlComponent& component : tubular.components) {
    text += fmt::format("  - {}  # {} {}\n", ComponentLine(component, value), Where(component.origin),
                        component.origin.what);
  }
  return text;
}

}  // namespace drillflex::io
