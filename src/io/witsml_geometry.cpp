// A WITSML wbGeometry (2.0 WellboreGeometry): the hole diameter by MD. A casing or liner section
// gives its drift diameter (`diaDrift`: what a tool can pass), else its nominal ID; an open-hole
// section its ID (the hole's diameter). Where sections overlap (a liner inside casing, nested casing
// strings from the surface) the narrowest one holds.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "io/witsml_reader.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

struct Section {
  pugi::xml_node node;
  WitsmlValue top, bottom, diameter;
  std::string source;
  WitsmlOrigin origin;
  bool cased = false;  // a casing or liner (any type but open hole)
};

bool IsOpenHole(const std::string& type) { return type == "open hole" || type.empty(); }

Section ReadSection(const WitsmlReader& reader, const pugi::xml_node& node) {
  Section section;
  section.node = node;
  const std::string type = TrimmedText(reader.Child(node, "typeHoleCasing"));
  if (reader.v20()) {
    // 2.0: SectionMdInterval holds MdTop and MdBase (Energistics common's MdInterval).
    const pugi::xml_node interval = reader.Required(node, "sectionMdInterval", "the section's MD range");
    section.top = reader.RequiredMeasure(interval, "mdTop", Quantity::Length, "the MD of the section's top");
    section.bottom = reader.RequiredMeasure(interval, "mdBase", Quantity::Length, "the MD of the section's bottom");
  } else {
    section.top = reader.RequiredMeasure(node, "mdTop", Quantity::Length, "the MD of the section's top");
    section.bottom = reader.RequiredMeasure(node, "mdBottom", Quantity::Length, "the MD of the section's bottom");
  }
  if (!(section.bottom.si > section.top.si)) {
    reader.Fail(node, fmt::format("the section's bottom ({} {}) must lie below its top ({} {})", section.bottom.text,
                                  section.bottom.uom, section.top.text, section.top.uom));
  }
  const auto drift = IsOpenHole(type) ? std::nullopt : reader.OptionalMeasure(node, "diaDrift", Quantity::Diameter);
  const auto inner = reader.OptionalMeasure(node, "idSection", Quantity::Diameter);
  if (drift) {
    section.diameter = *drift;
    section.source = "diaDrift";
  } else if (inner) {
    section.diameter = *inner;
    section.source = "idSection";
    if (!IsOpenHole(type)) {
      reader.Warn(node, "no <diaDrift>: the nominal ID (idSection) is taken as the hole a tool can pass");
    }
  } else {
    reader.Fail(node, fmt::format("expected <{}> (the hole's or pipe's inside diameter){}", reader.Name("idSection"),
                                  IsOpenHole(type) ? "" : fmt::format(" or <{}>", reader.Name("diaDrift"))));
  }
  if (!(section.diameter.si > 0.0)) reader.Fail(node, "the section's diameter must be positive");
  section.source = fmt::format("{}, {}", type.empty() ? "unknown type" : type, section.source);
  section.cased = !IsOpenHole(type);
  const std::string uid = node.attribute("uid").value();
  section.origin = reader.Origin(node, fmt::format("{}{}", reader.Name("wbGeometrySection"), uid.empty() ? "" : " uid=" + uid));
  reader.WarnUnmapped(node, {"typeHoleCasing", "mdTop", "mdBottom", "sectionMdInterval", "idSection", "diaDrift"},
                      "drillflex's hole is a diameter by MD");
  return section;
}

}  // namespace

WitsmlGeometry ReadGeometry(const WitsmlReader& reader, const pugi::xml_node& object) {
  WitsmlGeometry geometry;
  geometry.name = reader.ObjectName(object);
  geometry.origin = reader.ObjectOrigin(object, "wbGeometry");
  const std::vector<Section> sections =
      reader.ReadEach(object, "wbGeometrySection", [&](const pugi::xml_node& node) { return ReadSection(reader, node); });
  // Every MD where a section starts or ends, top down; between two of them the narrowest section
  // covering the interval sets the diameter.
  std::vector<const WitsmlValue*> depths;
  for (const Section& section : sections) depths.insert(depths.end(), {&section.top, &section.bottom});
  std::sort(depths.begin(), depths.end(), [](const WitsmlValue* a, const WitsmlValue* b) { return a->si < b->si; });
  depths.erase(std::unique(depths.begin(), depths.end(),
                           [](const WitsmlValue* a, const WitsmlValue* b) {
                             // The same depth written in two units ("4500 ft", "1371.6 m").
                             return std::abs(a->si - b->si) <= 1e-9 * std::max(1.0, std::abs(a->si));
                           }),
               depths.end());
  for (std::size_t i = 0; i + 1 < depths.size(); ++i) {
    const Section* narrowest = nullptr;
    for (const Section& section : sections) {
      const double tolerance = 1e-9 * std::max(1.0, depths[i + 1]->si);
      const bool covers = section.top.si <= depths[i]->si + tolerance && section.bottom.si >= depths[i + 1]->si - tolerance;
      if (covers && (!narrowest || section.diameter.si < narrowest->diameter.si)) narrowest = &section;
    }
    if (!narrowest) {
      reader.Fail(object, fmt::format("no section covers the MD from {} {} to {} {}: the hole must be described "
                                      "without gaps",
                                      depths[i]->text, depths[i]->uom, depths[i + 1]->text, depths[i + 1]->uom));
    }
    const bool same = !geometry.hole.empty() && geometry.hole.back().origin.line == narrowest->origin.line &&
                      geometry.hole.back().origin.what == narrowest->origin.what;
    if (same) {
      geometry.hole.back().bottom = *depths[i + 1];
    } else {
      geometry.hole.push_back(
          {*depths[i], *depths[i + 1], narrowest->diameter, narrowest->source, narrowest->origin, narrowest->cased});
    }
  }
  return geometry;
}

std::vector<well::HoleSection> HoleOf(const WitsmlGeometry& geometry) {
  std::vector<well::HoleSection> hole;
  for (std::size_t i = 0; i < geometry.hole.size(); ++i) {
    const bool last = i + 1 == geometry.hole.size();
    well::HoleSection section{last ? std::nullopt : std::optional<double>(geometry.hole[i].bottom.si),
                              geometry.hole[i].diameter.si, std::nullopt};
    section.cased = geometry.hole[i].cased;
    hole.push_back(section);
  }
  return hole;
}

}  // namespace drillflex::io
