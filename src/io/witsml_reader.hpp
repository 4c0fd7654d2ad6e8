// What the readers of each WITSML object share (internal to io/): the element names of the
// document's version, measures with their `uom` read through the unit layer, and the warnings for
// fields read but not mapped.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/witsml.hpp"
#include "io/xml_source.hpp"
#include "units/units.hpp"

namespace drillflex::io {

// The namespaces of the versions read: 1.4.1.1's on its plural root, 2.0's on the object.
inline constexpr std::string_view kWitsml1411Namespace = "http://www.witsml.org/schemas/1series";
inline constexpr std::string_view kWitsml20Namespace = "http://www.energistics.org/energyml/data/witsmlv2";

class WitsmlReader {
 public:
  WitsmlReader(const XmlSource& source, WitsmlDocument& document)
      : source_(source), document_(document), v20_(document.version == "2.0") {}

  bool v20() const { return v20_; }
  const XmlSource& source() const { return source_; }

  // An element's name in the document's version, from its 1.4.1.1 name: 2.0 writes it UpperCamel
  // (`od` -> `Od`), and renames a few (`typeTubularComp` -> `TypeTubularComponent`).
  std::string Name(std::string_view name_1411) const;
  pugi::xml_node Child(const pugi::xml_node& parent, std::string_view name_1411) const;
  std::vector<pugi::xml_node> Children(const pugi::xml_node& parent, std::string_view name_1411) const;
  // The child, or an error at the parent saying what the child holds.
  pugi::xml_node Required(const pugi::xml_node& parent, std::string_view name_1411, std::string_view what) const;

  // A measure: a finite number and a `uom` of the quantity's dimension; else an error at the element.
  WitsmlValue Measure(const pugi::xml_node& element, units::Quantity quantity) const;
  std::optional<WitsmlValue> OptionalMeasure(const pugi::xml_node& parent, std::string_view name_1411,
                                             units::Quantity quantity) const;
  WitsmlValue RequiredMeasure(const pugi::xml_node& parent, std::string_view name_1411, units::Quantity quantity,
                              std::string_view what) const;
  // A whole number (`sequence`, `lobesRotor`).
  int Integer(const pugi::xml_node& element) const;
  // The object's name: 1.4.1.1 `name`, 2.0 `Citation/Title`.
  std::string ObjectName(const pugi::xml_node& object) const;

  WitsmlOrigin Origin(const pugi::xml_node& node, std::string what) const;
  // An object's origin, "tubular 'BHA'", with its name.
  WitsmlOrigin ObjectOrigin(const pugi::xml_node& object, std::string_view kind) const {
    return Origin(object, std::string(kind) + " '" + ObjectName(object) + "'");
  }
  // Reads every child `name_1411` of `object` with `read`; an error at the object when there is none.
  template <class ReadItem>
  auto ReadEach(const pugi::xml_node& object, std::string_view name_1411, ReadItem read) const {
    std::vector<decltype(read(object))> items;
    for (const pugi::xml_node node : Children(object, name_1411)) items.push_back(read(node));
    if (items.empty()) Fail(object, "expected at least one <" + Name(name_1411) + ">");
    return items;
  }
  [[noreturn]] void Fail(const pugi::xml_node& node, const std::string& message) const {
    source_.Fail(node, message);
  }
  void Warn(const pugi::xml_node& node, const std::string& message) const;
  // The child elements whose 1.4.1.1 names are not in `known` (metadata left out).
  std::vector<pugi::xml_node> Unknown(const pugi::xml_node& parent, const std::vector<std::string_view>& known) const;
  // A warning for each of them: "<wtPerLen> 19.5 lbm/ft not mapped: <why>".
  void WarnUnmapped(const pugi::xml_node& parent, const std::vector<std::string_view>& known, std::string_view why) const;

 private:
  const XmlSource& source_;
  WitsmlDocument& document_;
  bool v20_;
};

// The object readers (io/witsml_trajectory.cpp, io/witsml_geometry.cpp, io/witsml_tubular.cpp).
WitsmlTrajectory ReadTrajectory(const WitsmlReader& reader, const pugi::xml_node& object);
WitsmlGeometry ReadGeometry(const WitsmlReader& reader, const pugi::xml_node& object);
WitsmlTubular ReadTubular(const WitsmlReader& reader, const pugi::xml_node& object);

}  // namespace drillflex::io
