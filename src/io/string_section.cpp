// Reads `materials:` and `string:` (the components from the bit upward).
#include <cctype>
#include <string_view>

#include <fmt/format.h>

#include "io/case_sections.hpp"
#include "model/string_limits.hpp"
#include "model/tool_joint_torque.hpp"

namespace drillflex::io {
namespace {

using model::ComponentType;
using units::Quantity;

const std::vector<std::pair<std::string, ComponentType>>& ComponentTypes() {
  static const std::vector<std::pair<std::string, ComponentType>> types = {
      {"bit", ComponentType::Bit},         {"stabilizer", ComponentType::Stabilizer},
      {"collar", ComponentType::Collar},   {"hwdp", ComponentType::Hwdp},
      {"pipe", ComponentType::Pipe},       {"mwd", ComponentType::Mwd},
      {"lwd", ComponentType::Lwd},         {"jar", ComponentType::Jar},
      {"motor", ComponentType::Motor},     {"sub", ComponentType::Sub},
      {"crossover", ComponentType::Crossover}};
  return types;
}

ComponentType ReadComponentType(const YamlView& node) {
  const std::string name = node.AsString();
  std::vector<std::string> names;
  for (const auto& [type_name, type] : ComponentTypes()) {
    if (type_name == name) return type;
    names.push_back(type_name);
  }
  std::string message = fmt::format("unknown component type '{}'", name);
  const std::string suggestion = ClosestMatch(name, names);
  if (!suggestion.empty()) message.append(fmt::format(" (did you mean '{}'?)", suggestion));
  else message.append("; expected one of: ").append(JoinWords(names));
  node.Fail(message);
}

std::vector<std::string> AllowedComponentKeys(ComponentType type) {
  std::vector<std::string> keys = {"type",  "name",  "od",    "id",           "length", "material",
                                   "count", "grade", "yield", "class", "makeup_torque"};
  switch (type) {
    case ComponentType::Stabilizer:
      keys.insert(keys.end(), {"blade_od", "blade_length"});
      break;
    case ComponentType::Pipe:
    case ComponentType::Hwdp:
      keys.insert(keys.end(), {"joint_od", "joint_id", "joint_length", "joint_spacing", "connection"});
      break;
    case ComponentType::Motor:
      keys.insert(keys.end(), {"bend", "bend_to_bit", "toolface", "rev_per_volume", "lobes", "blade_od", "blade_length"});
      break;
    default:
      break;
  }
  return keys;
}

// Checks a diameter pair: both positive, the bore smaller than the outside.
void CheckBore(const YamlView& item, const char* id_key, double outer, double inner, const char* od_key) {
  if (inner < 0.0) item.Child(id_key).Fail("the inner diameter must not be negative");
  if (inner >= outer) {
    const units::System system = item.context().system;
    item.Child(id_key).Fail(fmt::format(
        "the inner diameter ({:.6g} {unit}) must be smaller than '{}' ({:.6g} {unit})",
        units::FromSI(inner, Quantity::Diameter, system), od_key,
        units::FromSI(outer, Quantity::Diameter, system),
        fmt::arg("unit", units::DefaultUnit(Quantity::Diameter, system))));
  }
}

void ReadStabilizerKeys(const YamlView& item, model::Component& component) {
  component.blade_diameter = item.OptionalPositive("blade_od", Quantity::Diameter);
  component.blade_length = item.OptionalPositive("blade_length", Quantity::Length);
  if (component.blade_diameter && *component.blade_diameter < component.outer_diameter) {
    item.Child("blade_od").Fail("the blade OD must not be smaller than the body OD");
  }
  if (component.blade_length && *component.blade_length > component.length) {
    item.Child("blade_length").Fail("the blades must not be longer than the stabilizer");
  }
}

void ReadToolJointKeys(const YamlView& item, model::Component& component) {
  component.joint_diameter = item.OptionalPositive("joint_od", Quantity::Diameter);
  component.joint_inner_diameter = item.OptionalPositive("joint_id", Quantity::Diameter);
  component.joint_length = item.OptionalPositive("joint_length", Quantity::Length);
  component.joint_spacing = item.OptionalPositive("joint_spacing", Quantity::Length);
  if (component.joint_diameter && *component.joint_diameter < component.outer_diameter) {
    item.Child("joint_od").Fail("the tool-joint OD must not be smaller than the body OD");
  }
  if (component.joint_diameter && component.joint_inner_diameter) {
    CheckBore(item, "joint_id", *component.joint_diameter, *component.joint_inner_diameter, "joint_od");
  }
}

void ReadMotorKeys(const YamlView& item, model::Component& component) {
  component.bend_angle = item.OptionalQuantity("bend", Quantity::Angle);
  component.bend_to_bit = item.OptionalPositive("bend_to_bit", Quantity::Length);
  component.toolface = item.OptionalQuantity("toolface", Quantity::Angle);
  component.speed_per_flow = item.OptionalPositive("rev_per_volume", Quantity::RevolutionsPerVolume);
  if (const auto lobes = item.OptionalChild("lobes")) {
    component.lobes = lobes->AsInteger();
    if (*component.lobes < 1) lobes->Fail("expected a positive number of rotor lobes");
  }
  if (component.bend_angle && (*component.bend_angle < 0.0 || *component.bend_angle > 5.0 * kDegree)) {
    item.Child("bend").Fail("expected a bend angle between 0 and 5 deg");
  }
  if (component.toolface && (*component.toolface < 0.0 || *component.toolface > 2.0 * kPi)) {
    item.Child("toolface").Fail("expected a toolface between 0 and 360 deg (0 the high side, 90 the right)");
  }
  if (component.bend_angle && !component.bend_to_bit) {
    item.Child("bend").Fail("a bent motor needs 'bend_to_bit', the distance from the bit to the bend");
  }
  component.blade_diameter = item.OptionalPositive("blade_od", Quantity::Diameter);
  component.blade_length = item.OptionalPositive("blade_length", Quantity::Length);
}

// The ratings (model/string_limits.hpp): an API grade or a custom minimum yield (40–200 ksi), the
// pipe class, the connections' make-up torque.
void ReadRatingKeys(const YamlView& item, model::Component& component) {
  const auto grade = item.OptionalChild("grade");
  const auto yield = item.OptionalChild("yield");
  if (grade && yield) yield->Fail("give either 'grade' or a custom 'yield', not both");
  if (grade) {
    const std::string name = grade->AsString();
    const auto found = model::FindSteelGrade(name);
    if (!found) {
      std::vector<std::string> names;
      for (const model::SteelGrade& known : model::SteelGrades()) names.emplace_back(known.name);
      grade->Fail(fmt::format("unknown grade '{}'; expected one of: {} (or a custom 'yield')", name, JoinWords(names)));
    }
    component.grade = found->name;
    component.yield_strength = found->yield;
  }
  if (yield) {
    const double value = item.Positive("yield", Quantity::Stress);
    if (value < model::kLeastYield || value > model::kLargestYield) {
      yield->Fail(fmt::format("expected a minimum yield strength between 40 and 200 ksi (E-75's is 75 ksi, S-135's "
                              "135 ksi), got {:.4g} ksi ({:.4g} MPa)",
                              value / model::kPascalPerKsi, value / 1e6));
    }
    component.yield_strength = value;
  }
  if (const auto pipe_class = item.OptionalChild("class")) {
    const std::string name = pipe_class->AsString();
    if (name == "new") component.pipe_class = model::PipeClass::New;
    else if (name == "premium") component.pipe_class = model::PipeClass::Premium;
    else pipe_class->Fail(fmt::format("unknown pipe class '{}'; expected 'new' or 'premium' (the wall at 80 %)", name));
  }
  component.makeup_torque = item.OptionalPositive("makeup_torque", Quantity::Moment);
}

// Whether a connection's name is of the regular (REG) or full-hole (FH) style ("6-5/8 REG", "4-1/2 FH").
bool NamesRegularOrFullHole(const std::string& name) {
  std::string upper;
  for (const char c : name) upper.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return upper.find("REG") != std::string::npos || upper.find("FH") != std::string::npos;
}

// A tool joint's connection by name (pipe and HWDP): its make-up torque by API RP 7G's formula for the
// joint's OD and pin ID (model/tool_joint_torque.hpp) where no `makeup_torque` is given.
void ReadConnection(const YamlView& item, model::Component& component) {
  const auto connection = item.OptionalChild("connection");
  if (!connection) return;
  const std::string name = connection->AsString();
  const auto found = model::FindRotaryConnection(name);
  if (!found) {
    std::vector<std::string> names;
    for (const model::RotaryConnection& known : model::RotaryConnections()) {
      std::string shown = known.name;
      for (const model::ConnectionAlias& alias : model::RotaryConnectionAliases()) {
        if (std::string_view(alias.numbered) == known.name) shown += fmt::format(" ({})", alias.name);
      }
      names.push_back(shown);
    }
    if (NamesRegularOrFullHole(name)) {
      connection->Fail(fmt::format("connection '{}': the regular (REG) and full-hole (FH) connections other than 4 FH "
                                   "(NC40) are not supported, their thread data could not be checked against a source "
                                   "(docs/case-format.md); expected one of: {} (or give 'makeup_torque')",
                                   name, JoinWords(names)));
    }
    connection->Fail(fmt::format("unknown connection '{}'; expected one of: {} (or give 'makeup_torque')", name,
                                 JoinWords(names)));
  }
  if (item.OptionalChild("makeup_torque")) {
    item.Child("makeup_torque").Fail("give either 'makeup_torque' or a 'connection' to compute it from, not both");
  }
  if (!component.joint_diameter || !component.joint_inner_diameter) {
    connection->Fail(fmt::format("the make-up torque of {} needs the tool joint's 'joint_od' and 'joint_id' (the pin's bore)",
                                 found->name));
  }
  const double od = *component.joint_diameter, id = *component.joint_inner_diameter;
  const units::System system = item.context().system;
  const auto shown = [system](double diameter) {
    return fmt::format("{:.4g} {}", units::FromSI(diameter, Quantity::Diameter, system),
                       units::DefaultUnit(Quantity::Diameter, system));
  };
  if (!(id < model::PinThreadRoot(*found))) {
    item.Child("joint_id").Fail(fmt::format("the {} pin's bore must be smaller than its thread's root diameter ({})",
                                            found->name, shown(model::PinThreadRoot(*found))));
  }
  if (!(od > found->counterbore)) {
    item.Child("joint_od").Fail(fmt::format("the {} box's OD must be larger than its counterbore ({})", found->name,
                                            shown(found->counterbore)));
  }
  component.connection = found->name;
  component.makeup_torque = model::ConnectionTorsionalStrength(*found, od, id).makeup_torque;
}

model::Component ReadComponent(const YamlView& item, const std::map<std::string, fe::Material>& materials) {
  item.ExpectMap("a component {type, od, id, length, ...}", false);
  model::Component component;
  component.type = ReadComponentType(item.Child("type"));
  item.AllowOnlyKeys(AllowedComponentKeys(component.type));
  component.source_line = item.location().line;
  component.name = item.StringOr("name", model::ComponentTypeName(component.type));
  component.outer_diameter = item.Positive("od", Quantity::Diameter);
  const bool bore_optional = component.type == ComponentType::Bit;
  component.inner_diameter = bore_optional ? item.QuantityOr("id", Quantity::Diameter, 0.0)
                                           : item.Quantity("id", Quantity::Diameter);
  CheckBore(item, "id", component.outer_diameter, component.inner_diameter, "od");
  component.length = item.Positive("length", Quantity::Length);
  component.count = item.IntegerOr("count", 1);
  if (component.count < 1) item.Child("count").Fail("expected a count of at least 1");
  if (const auto material = item.OptionalChild("material")) {
    component.material = material->AsString();
    if (!materials.count(component.material)) {
      std::vector<std::string> names;
      for (const auto& entry : materials) names.push_back(entry.first);
      std::string message = fmt::format("unknown material '{}'", component.material);
      const std::string suggestion = ClosestMatch(component.material, names);
      if (!suggestion.empty()) message.append(fmt::format(" (did you mean '{}'?)", suggestion));
      else message.append("; known: ").append(JoinWords(names)).append(" (define others under 'materials')");
      material->Fail(message);
    }
  } else if (component.type == ComponentType::Mwd || component.type == ComponentType::Lwd) {
    component.material = "nonmag";
  }
  switch (component.type) {
    case ComponentType::Stabilizer: ReadStabilizerKeys(item, component); break;
    case ComponentType::Pipe:
    case ComponentType::Hwdp: ReadToolJointKeys(item, component); break;
    case ComponentType::Motor: ReadMotorKeys(item, component); break;
    default: break;
  }
  ReadRatingKeys(item, component);
  ReadConnection(item, component);
  return component;
}

}  // namespace

void ReadMaterialsSection(const YamlView& node, std::map<std::string, fe::Material>& materials) {
  node.ExpectMap("materials by name", false);
  for (const std::string& name : node.Keys()) {
    const YamlView item = node.Child(name);
    item.ExpectMap("a material {E, nu, density}", false);
    item.AllowOnlyKeys({"E", "nu", "density"});
    fe::Material material;
    material.name = name;
    material.youngs_modulus = item.Positive("E", Quantity::Stress);
    material.poisson_ratio = item.Quantity("nu", Quantity::Dimensionless);
    material.density = item.Positive("density", Quantity::Density);
    if (material.poisson_ratio <= -1.0 || material.poisson_ratio >= 0.5) {
      item.Child("nu").Fail("expected a Poisson ratio between -1 and 0.5");
    }
    // Bounds that take in every metal and composite a string is made of (composite pipe ~30 GPa,
    // tungsten carbide ~600 GPa; aluminium 2700, tungsten 19 300 kg/m³) and catch a value in the other
    // system's unit: 30e6 read as Pa where psi was meant, a steel density in ppg read as kg/m³.
    if (material.youngs_modulus < 1e8 || material.youngs_modulus > 1.5e12) {
      item.Child("E").Fail(fmt::format("expected a Young's modulus between 0.1 and 1500 GPa (steel's is 207 GPa, "
                                       "30e6 psi), got {:.4g} Pa ({:.4g} psi)",
                                       material.youngs_modulus,
                                       units::FromSI(material.youngs_modulus, Quantity::Stress, units::System::Field)));
    }
    if (material.density < 500.0 || material.density > 25000.0) {
      item.Child("density").Fail(fmt::format("expected a density between 500 and 25000 kg/m3 (steel's is 7850 kg/m3, "
                                             "65.5 ppg), got {:.4g} kg/m3",
                                             material.density));
    }
    materials[name] = material;
  }
}

model::StringConfig ReadStringSection(const YamlView& node, const std::map<std::string, fe::Material>& materials,
                                      const std::string& directory, std::vector<std::string>& warnings) {
  model::StringConfig string;
  if (node.IsMap()) {
    node.AllowOnlyKeys({"witsml"});
    const YamlView witsml = node.Child("witsml");
    std::vector<const WitsmlTubular*> tubulars;
    const auto documents = ReadWitsmlKey(witsml, directory, warnings);
    for (const auto& document : documents) {
      for (const auto& tubular : document.tubulars) tubulars.push_back(&tubular);
    }
    if (tubulars.size() != 1) {
      witsml.Fail(fmt::format("expected one tubular among the WITSML documents, found {}", tubulars.size()));
    }
    for (const WitsmlComponent& component : tubulars.front()->components) {
      string.components.push_back(ComponentOf(component));
    }
    return string;
  }
  node.ExpectSequence("the string's components from the bit upward (or {witsml: FILE})");
  if (node.size() == 0) node.Fail("the string needs at least one component");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlView item = node.Item(i);
    string.components.push_back(ReadComponent(item, materials));
    if (string.components.back().type == ComponentType::Bit && i != 0) {
      item.Child("type").Fail("the bit must be the first component (the string is listed from the bit upward)");
    }
  }
  return string;
}

}  // namespace drillflex::io
