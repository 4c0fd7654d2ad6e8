// A test-only WITSML writer (never in src/: drillflex reads WITSML, it does not write it): a case's
// survey, hole and string as WITSML 1.4.1.1 or 2.0 trajectory, wbGeometry and tubular documents, in
// field units (ft, in, dega), each number with 15 significant digits so that the case's own decimals
// come back exactly. tests/pipeline/witsml_round_trip_test.cpp imports them again.
#pragma once

#include <string>

#include <fmt/format.h>

#include "io/case.hpp"

namespace drillflex::test_witsml {

enum class Version { V1411, V20 };

struct Documents {
  std::string trajectory, geometry, tubular;  // the documents' texts
};

inline constexpr double kFt = 0.3048;
inline constexpr double kIn = 0.0254;

// One XML element with a measure: <od uom="in">6.75</od>.
inline std::string Measure(const std::string& name, double value, const char* uom) {
  return fmt::format("<{0} uom=\"{1}\">{2:.15g}</{0}>", name, uom, value);
}

class Writer {
 public:
  explicit Writer(Version version) : v20_(version == Version::V20) {}

  // An element name of 1.4.1.1 in this version (2.0 capitalizes it, with two renames).
  std::string Name(const std::string& name) const {
    if (!v20_) return name;
    if (name == "typeTubularComp") return "TypeTubularComponent";
    if (name == "wbGeometrySection") return "WellboreGeometrySection";
    std::string upper = name;
    upper[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(upper[0])));
    return upper;
  }
  std::string M(const std::string& name, double value, const char* uom) const { return Measure(Name(name), value, uom); }
  std::string T(const std::string& name, const std::string& text) const {
    return fmt::format("<{0}>{1}</{0}>", Name(name), text);
  }

  // The document around one object: 1.4.1.1's plural container, 2.0's object as the root.
  std::string Document(const std::string& object, const std::string& body) const {
    if (v20_) {
      std::string root = Name(object == "wbGeometry" ? "wellboreGeometry" : object);
      return fmt::format(
          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<{0} xmlns=\"http://www.energistics.org/energyml/data/witsmlv2\" "
          "xmlns:eml=\"http://www.energistics.org/energyml/data/commonv2\" schemaVersion=\"2.0\" uuid=\"00000000-0000-"
          "0000-0000-000000000001\">\n<eml:Citation><eml:Title>round trip</eml:Title></eml:Citation>\n{1}</{0}>\n",
          root, body);
    }
    return fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<{0}s xmlns=\"http://www.witsml.org/schemas/1series\" "
        "version=\"1.4.1.1\">\n<{0} uidWell=\"w\" uidWellbore=\"wb\" uid=\"o\"><name>round trip</name>\n{1}</{0}>\n</{0}s>\n",
        object, body);
  }

  std::string Trajectory(const io::WellConfig& well) const {
    std::string body;
    for (std::size_t i = 0; i < well.survey.size(); ++i) {
      const auto& station = well.survey[i];
      body += fmt::format("<{0} uid=\"s{1}\">{2}{3}{4}</{0}>\n", Name("trajectoryStation"), i + 1,
                          M("md", station.md / kFt, "ft"), M("incl", station.inclination / kDegree, "dega"),
                          M("azi", station.azimuth / kDegree, "dega"));
    }
    return Document("trajectory", body);
  }

  // Every section but the last as casing (its diameter the drift), the last as open hole to TD.
  std::string Geometry(const io::WellConfig& well) const {
    std::string body;
    double top = 0.0;
    for (std::size_t i = 0; i < well.hole.size(); ++i) {
      const auto& section = well.hole[i];
      const bool last = i + 1 == well.hole.size();
      const double bottom = last ? well.survey.back().md : *section.to_md;
      const std::string interval =
          v20_ ? fmt::format("<SectionMdInterval datum=\"KB\">{}{}</SectionMdInterval>", Measure("eml:MdTop", top / kFt, "ft"),
                             Measure("eml:MdBase", bottom / kFt, "ft"))
               : M("mdTop", top / kFt, "ft") + M("mdBottom", bottom / kFt, "ft");
      body += fmt::format("<{0} uid=\"h{1}\">{2}{3}{4}</{0}>\n", Name("wbGeometrySection"), i + 1,
                          T("typeHoleCasing", last ? "open hole" : "casing"), interval,
                          M(last ? "idSection" : "diaDrift", section.diameter / kIn, "in"));
      top = bottom;
    }
    return Document("wbGeometry", body);
  }

  std::string Tubular(const model::StringConfig& string) const {
    std::string body;
    double below = 0.0;
    for (std::size_t i = 0; i < string.components.size(); ++i) {
      const auto& c = string.components[i];
      std::string fields = T("typeTubularComp", TypeName(c.type)) + T("sequence", std::to_string(i + 1)) +
                           T("description", c.name) + M("id", c.inner_diameter / kIn, "in") +
                           M("od", c.outer_diameter / kIn, "in") + M("len", c.length * c.count / kFt, "ft");
      if (c.count > 1) fields += M("lenJointAv", c.length / kFt, "ft");
      if (c.material == "nonmag") fields += T("typeMaterial", "non-magnetic steel");
      if (c.joint_diameter || c.joint_inner_diameter || c.joint_length) {
        std::string joint;
        if (c.joint_inner_diameter) joint += M("id", *c.joint_inner_diameter / kIn, "in");
        if (c.joint_diameter) joint += M("od", *c.joint_diameter / kIn, "in");
        if (c.joint_length) joint += M("len", *c.joint_length / kFt, "ft");
        fields += fmt::format("<{0}>{1}</{0}>", Name("connection"), joint);
      }
      if (c.type == model::ComponentType::Motor) {
        if (c.lobes) fields += fmt::format("<{0}>{1}</{0}>", Name("motor"), T("lobesRotor", std::to_string(*c.lobes)));
      }
      if (c.blade_diameter || c.blade_length) {
        std::string blades;
        if (c.blade_length) blades += M("lenBladeGauge", *c.blade_length / kFt, "ft");
        if (c.blade_diameter) blades += M("odBladeMx", *c.blade_diameter / kIn, "in");
        fields += fmt::format("<{0}>{1}</{0}>", Name("stabilizer"), blades);
      }
      if (c.bend_angle && c.bend_to_bit) {
        fields += fmt::format("<{0}>{1}{2}</{0}>", Name("bend"), M("angle", *c.bend_angle / kDegree, "dega"),
                              M("distBendBot", (*c.bend_to_bit - below) / kFt, "ft"));
      }
      body += fmt::format("<{0} uid=\"c{1}\">{2}</{0}>\n", Name("tubularComponent"), i + 1, fields);
      below += c.length * c.count;
    }
    return Document("tubular", body);
  }

  static const char* TypeName(model::ComponentType type) {
    switch (type) {
      case model::ComponentType::Bit: return "bit PDC fixed cutter";
      case model::ComponentType::Stabilizer: return "stabilizer";
      case model::ComponentType::Collar: return "drill collar";
      case model::ComponentType::Hwdp: return "heavy weight drill pipe";
      case model::ComponentType::Pipe: return "drill pipe";
      case model::ComponentType::Mwd: return "MWD pulser";
      case model::ComponentType::Lwd: return "logging while drilling tool";
      case model::ComponentType::Jar: return "jar";
      case model::ComponentType::Motor: return "motor";
      case model::ComponentType::Sub: return "sub-saver";
      case model::ComponentType::Crossover: return "sub-crossover";
    }
    return "unknown";
  }

 private:
  bool v20_;
};

// The case's well (survey and hole) and string as three documents.
inline Documents WriteDocuments(const io::Case& c, Version version) {
  const Writer writer(version);
  return {writer.Trajectory(*c.well), writer.Geometry(*c.well), writer.Tubular(c.input.string)};
}

}  // namespace drillflex::test_witsml
