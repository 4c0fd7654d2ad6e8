// A WITSML tubular: its components from the bit up (sequence 1 entered the hole first), each mapped
// to a drillflex component with the keys of its type (blades, tool joints, bend).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/types.hpp"
#include "io/witsml_component_types.hpp"
#include "io/witsml_reader.hpp"
#include "model/string_limits.hpp"

namespace drillflex::io {
namespace {

using model::ComponentType;
using units::Quantity;

struct Read {
  WitsmlComponent component;
  pugi::xml_node node;
  std::optional<WitsmlValue> bend_from_bottom;  // distBendBot: from the component's lower end
};

// One item of a multi-joint entry: `len` is the whole entry; when it holds a whole number of
// `lenJointAv` joints the case lists one joint with a count.
void ReadLengthAndCount(const WitsmlReader& reader, const pugi::xml_node& node, WitsmlComponent& component) {
  component.length = reader.RequiredMeasure(node, "len", Quantity::Length, "the component's length");
  if (!(component.length.si > 0.0)) reader.Fail(reader.Child(node, "len"), "the length must be positive");
  const auto joint = reader.OptionalMeasure(node, "lenJointAv", Quantity::Length);
  if (!joint) return;
  const double joints = component.length.si / joint->si;
  const double whole = std::round(joints);
  constexpr double kMostJoints = 1e6;  // a count an int holds, and more joints than any string has
  if (joint->si > 0.0 && whole >= 1.0 && whole <= kMostJoints && std::abs(joints - whole) <= 1e-9 * joints) {
    component.count = static_cast<int>(whole);
    component.length = *joint;
  } else {
    reader.Warn(reader.Child(node, "lenJointAv"),
                fmt::format("<{}> not mapped: {} {} is not a whole number of {} {} joints; the component is one piece",
                            reader.Name("lenJointAv"), component.length.text, component.length.uom, joint->text, joint->uom));
  }
}

// The blades of a stabilizer (or a motor's stabilizer): the largest blade OD, the gauge length.
void ReadBlades(const WitsmlReader& reader, const pugi::xml_node& blades, WitsmlComponent& component) {
  component.blade_od = reader.OptionalMeasure(blades, "odBladeMx", Quantity::Diameter);
  component.blade_length = reader.OptionalMeasure(blades, "lenBladeGauge", Quantity::Length);
  const char* length_from = "lenBladeGauge";
  if (!component.blade_length) {
    component.blade_length = reader.OptionalMeasure(blades, "lenBlade", Quantity::Length);
    length_from = "lenBlade";
  }
  if (component.blade_od && component.blade_od->si < component.od.si) {
    reader.Fail(reader.Child(blades, "odBladeMx"), "the blade OD must not be smaller than the body OD (od)");
  }
  if (component.blade_length &&
      component.blade_length->si > component.length.si * (1.0 + 1e-12)) {
    reader.Fail(reader.Child(blades, length_from), "the blades must not be longer than the component");
  }
  // lenBlade is read when the gauge length is not given, and needs no word when it is.
  reader.WarnUnmapped(blades, {"odBladeMx", "lenBladeGauge", "lenBlade"},
                      "drillflex's blades are one OD over a length centred on the component");
}

// Tool joints of drill pipe and HWDP from the connections: the largest OD, the smallest ID, the
// lengths of the pin and box added (one connection: its own length).
void ReadToolJoints(const WitsmlReader& reader, const pugi::xml_node& node, WitsmlComponent& component) {
  for (const pugi::xml_node connection : reader.Children(node, "connection")) {
    const auto od = reader.OptionalMeasure(connection, "od", Quantity::Diameter);
    const auto id = reader.OptionalMeasure(connection, "id", Quantity::Diameter);
    const auto length = reader.OptionalMeasure(connection, "len", Quantity::Length);
    // The weakest connection's make-up torque is the component's torque limit.
    const auto makeup = reader.OptionalMeasure(connection, "tqMakeup", Quantity::Moment);
    if (makeup && !(makeup->si > 0.0)) reader.Fail(reader.Child(connection, "tqMakeup"), "the make-up torque must be positive");
    if (makeup && (!component.makeup_torque || makeup->si < component.makeup_torque->si)) component.makeup_torque = makeup;
    if (od && (!component.joint_od || od->si > component.joint_od->si)) component.joint_od = od;
    if (id && (!component.joint_id || id->si < component.joint_id->si)) component.joint_id = id;
    if (length) {
      if (component.joint_length) {
        component.joint_length = WitsmlValue{component.joint_length->si + length->si, "", ""};
      } else {
        component.joint_length = length;
      }
    }
    reader.WarnUnmapped(connection, {"od", "id", "len", "position", "typeThread", "sizeThread", "tqMakeup"},
                        "a tool joint is its OD, ID, length and make-up torque");
  }
  if (component.joint_od && component.joint_od->si < component.od.si) {
    reader.Fail(node, "the connection's OD must not be smaller than the pipe body's OD");
  }
}

// A motor's bend (the first <bend>) and its rotor's lobes.
void ReadMotor(const WitsmlReader& reader, const pugi::xml_node& node, Read& read) {
  const auto bends = reader.Children(node, "bend");
  if (!bends.empty()) {
    read.component.bend = reader.OptionalMeasure(bends.front(), "angle", Quantity::Angle);
    read.bend_from_bottom = reader.OptionalMeasure(bends.front(), "distBendBot", Quantity::Length);
    constexpr double kLargestBend = 5.0 * kPi / 180.0;  // rad: drillflex's bent housings (case-format.md)
    if (read.component.bend && (read.component.bend->si < 0.0 || read.component.bend->si > kLargestBend)) {
      reader.Fail(reader.Child(bends.front(), "angle"), "expected a bend angle between 0 and 5 deg");
    }
    if (read.component.bend && !read.bend_from_bottom) {
      reader.Warn(bends.front(), "<bend> not mapped: it gives no distBendBot (where the bend is)");
      read.component.bend.reset();
    }
    for (std::size_t i = 1; i < bends.size(); ++i) {
      reader.Warn(bends[i], "<bend> not mapped: drillflex's motor has one bend (the first is taken)");
    }
  }
  if (const pugi::xml_node motor = reader.Child(node, "motor")) {
    if (const pugi::xml_node lobes = reader.Child(motor, "lobesRotor")) read.component.lobes = reader.Integer(lobes);
    reader.WarnUnmapped(motor, {"lobesRotor"}, "a motor is its body, bend, blades and rotor lobes");
  }
}

// What a component of the type takes from a document, for the warnings.
const char* MappedFields(ComponentType type) {
  switch (type) {
    case ComponentType::Stabilizer: return "its OD, ID, length, material and blades";
    case ComponentType::Motor: return "its OD, ID, length, material, blades, bend and rotor lobes";
    case ComponentType::Pipe:
    case ComponentType::Hwdp: return "its OD, ID, length, material and tool joints (connections)";
    default: return "its OD, ID, length and material";
  }
}

Read ReadComponent(const WitsmlReader& reader, const pugi::xml_node& node) {
  Read read;
  read.node = node;
  WitsmlComponent& component = read.component;
  component.witsml_type = TrimmedText(reader.Required(node, "typeTubularComp", "the component's type"));
  component.sequence = reader.Integer(reader.Required(node, "sequence", "the component's place from the bit (1)"));
  if (component.sequence < 1) reader.Fail(reader.Child(node, "sequence"), "expected a sequence number of 1 or more");
  component.name = TrimmedText(reader.Child(node, "description"));
  const auto mapped = MapTubularComponentType(component.witsml_type);
  component.type = mapped ? mapped->type : ComponentType::Sub;
  if (mapped) component.material = mapped->material;
  component.origin = reader.Origin(node, fmt::format("{} {} ({})", reader.Name("tubularComponent"), component.sequence,
                                                     component.witsml_type));
  if (!mapped) {
    reader.Warn(reader.Child(node, "typeTubularComp"),
                fmt::format("'{}' has no drillflex type: read as a sub (a plain tube of its OD, ID and length)",
                            component.witsml_type));
  }
  component.od = reader.RequiredMeasure(node, "od", Quantity::Diameter, "the component's outside diameter");
  if (!(component.od.si > 0.0)) reader.Fail(reader.Child(node, "od"), "the outside diameter must be positive");
  component.id = reader.OptionalMeasure(node, "id", Quantity::Diameter);
  if (!component.id && component.type != ComponentType::Bit) {
    reader.Fail(node, fmt::format("expected an <{}> element: the component's bore", reader.Name("id")));
  }
  if (component.id && (component.id->si < 0.0 || component.id->si >= component.od.si)) {
    reader.Fail(reader.Child(node, "id"), "the inside diameter must lie between 0 and the outside diameter (od)");
  }
  ReadLengthAndCount(reader, node, component);
  std::vector<std::string_view> used = {"typeTubularComp", "sequence", "od", "id", "len", "lenJointAv", "typeMaterial"};
  const bool bladed = component.type == ComponentType::Stabilizer || component.type == ComponentType::Motor;
  if (bladed) {
    if (const pugi::xml_node blades = reader.Child(node, "stabilizer")) ReadBlades(reader, blades, component);
    used.push_back("stabilizer");
  }
  if (component.type == ComponentType::Pipe || component.type == ComponentType::Hwdp) {
    ReadToolJoints(reader, node, component);
    used.push_back("connection");
  }
  if (component.type == ComponentType::Motor) {
    ReadMotor(reader, node, read);
    used.insert(used.end(), {"bend", "motor"});
  }
  // The API grade, where the document names one drillflex knows (its minimum yield rates the component).
  if (const pugi::xml_node grade = reader.Child(node, "grade")) {
    const std::string name = TrimmedText(grade);
    if (const auto found = model::FindSteelGrade(name)) component.grade = found->name;
    else reader.Warn(grade, fmt::format("<grade> not mapped: '{}' is not an API drill-pipe grade drillflex rates (E-75, "
                                        "X-95, G-105, S-135): give the component's 'yield' in the case", name));
  }
  used.push_back("grade");
  if (const pugi::xml_node material = reader.Child(node, "typeMaterial")) {
    if (const auto name = MapMaterialType(TrimmedText(material))) component.material = *name;
    else reader.Warn(material, fmt::format("'{}' is not a drillflex material: the type's default is taken", TrimmedText(material)));
  }
  reader.WarnUnmapped(node, used, fmt::format("a {} is {}", model::ComponentTypeName(component.type),
                                              MappedFields(component.type)));
  return read;
}

}  // namespace

WitsmlTubular ReadTubular(const WitsmlReader& reader, const pugi::xml_node& object) {
  WitsmlTubular tubular;
  tubular.name = reader.ObjectName(object);
  tubular.origin = reader.ObjectOrigin(object, "tubular");
  std::vector<Read> reads =
      reader.ReadEach(object, "tubularComponent", [&](const pugi::xml_node& node) { return ReadComponent(reader, node); });
  std::stable_sort(reads.begin(), reads.end(),
                   [](const Read& a, const Read& b) { return a.component.sequence < b.component.sequence; });
  double below = 0.0;  // m of string below the current component
  for (std::size_t i = 0; i < reads.size(); ++i) {
    Read& read = reads[i];
    const pugi::xml_node sequence = reader.Child(read.node, "sequence");
    if (read.component.sequence != static_cast<int>(i) + 1) {
      reader.Fail(sequence, i > 0 && read.component.sequence == reads[i - 1].component.sequence
                                ? fmt::format("sequence {} appears twice: each component has its own number",
                                              read.component.sequence)
                                : fmt::format("the sequence numbers skip from {} to {}: expected {} (the components "
                                              "numbered 1, 2, 3, ... from the bit up)",
                                              i, read.component.sequence, i + 1));
    }
    if (read.component.type == ComponentType::Bit && i != 0) {
      reader.Fail(sequence, "a bit must be the first component (sequence 1)");
    }
    if (read.bend_from_bottom) {
      // The bend's distance from the bit: the string below the motor, then the bend above its lower end.
      read.component.bend_to_bit = WitsmlValue{below + read.bend_from_bottom->si, "", ""};
    }
    below += read.component.length.si * read.component.count;
    tubular.components.push_back(read.component);
  }
  return tubular;
}

model::Component ComponentOf(const WitsmlComponent& witsml) {
  model::Component component;
  component.type = witsml.type;
  component.name = witsml.name.empty() ? model::ComponentTypeName(witsml.type) : witsml.name;
  component.outer_diameter = witsml.od.si;
  component.inner_diameter = witsml.id ? witsml.id->si : 0.0;
  component.length = witsml.length.si;
  component.count = witsml.count;
  const bool magnetic_tool = witsml.type == ComponentType::Mwd || witsml.type == ComponentType::Lwd;
  component.material = !witsml.material.empty() ? witsml.material : magnetic_tool ? "nonmag" : "steel";
  const auto si = [](const std::optional<WitsmlValue>& value) {
    return value ? std::optional<double>(value->si) : std::nullopt;
  };
  component.blade_diameter = si(witsml.blade_od);
  component.blade_length = si(witsml.blade_length);
  component.joint_diameter = si(witsml.joint_od);
  component.joint_inner_diameter = si(witsml.joint_id);
  component.joint_length = si(witsml.joint_length);
  component.bend_angle = si(witsml.bend);
  component.bend_to_bit = si(witsml.bend_to_bit);
  component.lobes = witsml.lobes;
  if (const auto grade = model::FindSteelGrade(witsml.grade)) {
    component.grade = grade->name;
    component.yield_strength = grade->yield;
  }
  component.makeup_torque = si(witsml.makeup_torque);
  component.source_line = witsml.origin.line;
  return component;
}

}  // namespace drillflex::io
