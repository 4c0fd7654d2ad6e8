// ReadWitsml: the document's version and objects from its root element, and what the object readers
// share (io/witsml_reader.hpp).
#include "io/witsml_reader.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace drillflex::io {
namespace {

// Metadata that says nothing of the mechanics; never warned about.
constexpr std::string_view kMetadata[] = {"commonData", "customData",   "extensionAny", "extensionNameValue",
                                          "citation",   "nameTag",      "vendor",       "model",
                                          "description", "aliases",     "existence"};

bool SameName(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

struct ObjectKind {
  std::string_view root_1411;  // the plural container of 1.4.1.1
  std::string_view object_1411;
  std::string_view object_20;  // 2.0: the root element is the object
};

constexpr ObjectKind kKinds[] = {{"trajectorys", "trajectory", "Trajectory"},
                                 {"tubulars", "tubular", "Tubular"},
                                 {"wbGeometrys", "wbGeometry", "WellboreGeometry"}};

void ReadObject(const WitsmlReader& reader, const ObjectKind& kind, const pugi::xml_node& object,
                WitsmlDocument& document) {
  if (kind.object_1411 == "trajectory") document.trajectories.push_back(ReadTrajectory(reader, object));
  else if (kind.object_1411 == "tubular") document.tubulars.push_back(ReadTubular(reader, object));
  else document.geometries.push_back(ReadGeometry(reader, object));
}

const std::string kExpectedObjects =
    "drillflex reads the WITSML objects trajectory, tubular and wbGeometry (1.4.1.1: trajectorys, tubulars, "
    "wbGeometrys; 2.0: Trajectory, Tubular, WellboreGeometry)";

// The root's version attribute, which must be `expected`.
std::string CheckedVersion(const XmlSource& source, const char* attribute, std::string_view expected) {
  const std::string version = source.root().attribute(attribute).value();
  if (version != expected) {
    source.Fail(source.root(), fmt::format("WITSML {} '{}' is not read: drillflex reads 1.4.1.1 and 2.0 (this "
                                           "namespace: {})", attribute, version, expected));
  }
  return version;
}

void ReadVersion1411(const XmlSource& source, WitsmlDocument& document) {
  const pugi::xml_node root = source.root();
  document.version = CheckedVersion(source, "version", "1.4.1.1");
  const WitsmlReader reader(source, document);
  for (const ObjectKind& kind : kKinds) {
    if (LocalName(root) != kind.root_1411) continue;
    for (const pugi::xml_node object : reader.Children(root, kind.object_1411)) ReadObject(reader, kind, object, document);
    if (document.trajectories.empty() && document.tubulars.empty() && document.geometries.empty()) {
      source.Fail(root, fmt::format("the document holds no <{}>", kind.object_1411));
    }
    return;
  }
  source.Fail(root, fmt::format("<{}> is not a document drillflex reads: {}", LocalName(root), kExpectedObjects));
}

void ReadVersion20(const XmlSource& source, WitsmlDocument& document) {
  const pugi::xml_node root = source.root();
  document.version = CheckedVersion(source, "schemaVersion", "2.0");
  const WitsmlReader reader(source, document);
  for (const ObjectKind& kind : kKinds) {
    if (LocalName(root) == kind.object_20) return ReadObject(reader, kind, root, document);
  }
  source.Fail(root, fmt::format("<{}> is not an object drillflex reads: {}", LocalName(root), kExpectedObjects));
}

}  // namespace

std::string WitsmlReader::Name(std::string_view name_1411) const {
  if (!v20_) return std::string(name_1411);
  if (name_1411 == "typeTubularComp") return "TypeTubularComponent";
  if (name_1411 == "wbGeometrySection") return "WellboreGeometrySection";
  std::string name(name_1411);
  if (!name.empty()) name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  return name;
}

pugi::xml_node WitsmlReader::Child(const pugi::xml_node& parent, std::string_view name_1411) const {
  return ChildElement(parent, Name(name_1411));
}

std::vector<pugi::xml_node> WitsmlReader::Children(const pugi::xml_node& parent, std::string_view name_1411) const {
  const std::string name = Name(name_1411);
  std::vector<pugi::xml_node> children;
  for (const pugi::xml_node child : parent.children()) {
    if (child.type() == pugi::node_element && LocalName(child) == name) children.push_back(child);
  }
  return children;
}

pugi::xml_node WitsmlReader::Required(const pugi::xml_node& parent, std::string_view name_1411,
                                      std::string_view what) const {
  const pugi::xml_node child = Child(parent, name_1411);
  if (!child) Fail(parent, fmt::format("expected a <{}> element: {}", Name(name_1411), what));
  return child;
}

WitsmlValue WitsmlReader::Measure(const pugi::xml_node& element, units::Quantity quantity) const {
  WitsmlValue value;
  value.text = TrimmedText(element);
  double number = 0.0;
  const char* end = value.text.data() + value.text.size();
  const auto [stop, error] = std::from_chars(value.text.data(), end, number);
  if (value.text.empty() || error != std::errc() || stop != end || !std::isfinite(number)) {
    Fail(element, fmt::format("expected {} as a number, got '{}'", units::QuantityName(quantity), value.text));
  }
  value.uom = element.attribute("uom").value();
  if (value.uom.empty()) {
    Fail(element, fmt::format("the value has no 'uom' attribute: expected the unit of {} (such as uom=\"{}\")",
                              units::QuantityName(quantity), units::DefaultUnit(quantity, units::System::SI)));
  }
  units::Unit unit;
  try {
    unit = units::ParseUnit(value.uom);
  } catch (const UnitError& unknown) {
    Fail(element, fmt::format("unknown unit of measure uom=\"{}\" ({})", value.uom, unknown.what()));
  }
  if (!(unit.dimension == units::DimensionOf(quantity))) {
    Fail(element, fmt::format("uom=\"{}\" is {}, but {} is expected", value.uom,
                              units::DimensionName(unit.dimension), units::QuantityName(quantity)));
  }
  value.si = number * unit.to_si;
  if (!std::isfinite(value.si)) Fail(element, fmt::format("{} {} is out of range", value.text, value.uom));
  return value;
}

std::optional<WitsmlValue> WitsmlReader::OptionalMeasure(const pugi::xml_node& parent, std::string_view name_1411,
                                                         units::Quantity quantity) const {
  const pugi::xml_node element = Child(parent, name_1411);
  if (!element) return std::nullopt;
  return Measure(element, quantity);
}

WitsmlValue WitsmlReader::RequiredMeasure(const pugi::xml_node& parent, std::string_view name_1411,
                                          units::Quantity quantity, std::string_view what) const {
  return Measure(Required(parent, name_1411, what), quantity);
}

int WitsmlReader::Integer(const pugi::xml_node& element) const {
  const std::string text = TrimmedText(element);
  int number = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, number);
  if (text.empty() || error != std::errc() || stop != end) {
    Fail(element, fmt::format("expected a whole number, got '{}'", text));
  }
  return number;
}

std::string WitsmlReader::ObjectName(const pugi::xml_node& object) const {
  if (!v20_) return TrimmedText(Child(object, "name"));
  return TrimmedText(ChildElement(ChildElement(object, "Citation"), "Title"));
}

WitsmlOrigin WitsmlReader::Origin(const pugi::xml_node& node, std::string what) const {
  return {source_.file(), source_.Location(node).line, std::move(what)};
}

void WitsmlReader::Warn(const pugi::xml_node& node, const std::string& message) const {
  document_.warnings.push_back(
      fmt::format("{}: {}: {}", FormatLocation(source_.Location(node)), XmlSource::Path(node), message));
}

std::vector<pugi::xml_node> WitsmlReader::Unknown(const pugi::xml_node& parent,
                                                  const std::vector<std::string_view>& known) const {
  std::vector<pugi::xml_node> unknown;
  for (const pugi::xml_node child : parent.children()) {
    if (child.type() != pugi::node_element) continue;
    bool listed = false;
    for (const std::string_view name : known) listed = listed || LocalName(child) == Name(name);
    for (const std::string_view name : kMetadata) listed = listed || SameName(LocalName(child), name);
    if (!listed) unknown.push_back(child);
  }
  return unknown;
}

void WitsmlReader::WarnUnmapped(const pugi::xml_node& parent, const std::vector<std::string_view>& known,
                                std::string_view why) const {
  for (const pugi::xml_node field : Unknown(parent, known)) {
    const std::string value = TrimmedText(field);
    const std::string uom = field.attribute("uom").value();
    Warn(field, fmt::format("<{}>{} not mapped: {}", LocalName(field),
                            value.empty() ? "" : fmt::format(" {}{}", value, uom.empty() ? "" : " " + uom), why));
  }
}

WitsmlDocument ReadWitsml(std::string_view text, const std::string& file_name) {
  const XmlSource source(text, file_name);
  WitsmlDocument document;
  document.file = file_name;
  const std::string space = NamespaceOf(source.root());
  if (space == kWitsml1411Namespace) ReadVersion1411(source, document);
  else if (space == kWitsml20Namespace) ReadVersion20(source, document);
  else {
    source.Fail(source.root(),
                fmt::format("namespace '{}' is not read: expected WITSML 1.4.1.1 ({}) or 2.0 ({})", space,
                            kWitsml1411Namespace, kWitsml20Namespace));
  }
  return document;
}

WitsmlDocument ReadWitsmlFile(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError({path, 0, 0}, "", "cannot open the WITSML document");
  std::ostringstream text;
  text << stream.rdbuf();
  return ReadWitsml(text.str(), path);
}

}  // namespace drillflex::io
