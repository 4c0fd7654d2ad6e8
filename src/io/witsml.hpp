// WITSML 1.4.1.1 and 2.0 documents: `trajectory`, `tubular` and `wbGeometry` (2.0: Trajectory,
// Tubular, WellboreGeometry) read into what drillflex needs of them, each value kept as the document
// wrote it (its text and `uom`) beside its SI value, and each item with the line it came from. The
// version and the object come from the document itself. Bad documents throw InputError naming the
// file, line, element path and what was expected; fields read but not mapped become warnings.
// docs/case-format.md "Import" has the mapping.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/string_config.hpp"
#include "well/survey.hpp"

namespace drillflex::io {

// A measure as the document gives it.
struct WitsmlValue {
  double si = 0.0;   // in SI (m, rad, kg/m, ...)
  std::string text;  // the number as written ("8.5")
  std::string uom;   // its unit as written ("in"); "" for a value computed here in SI
};

// Where an item came from, for messages and for the comments of an imported case.
struct WitsmlOrigin {
  std::string file;
  int line = 0;
  std::string what;  // "trajectoryStation uid=s3", "tubularComponent 3 (drill collar)"
};

struct WitsmlStation {
  WitsmlValue md, inclination, azimuth;
  WitsmlOrigin origin;
};

struct WitsmlTrajectory {
  std::string name;
  WitsmlOrigin origin;
  std::vector<WitsmlStation> stations;  // MD strictly increasing, at least two
};

// One hole interval by MD, the narrowest section over it (the innermost pipe where casings overlap).
struct WitsmlHoleInterval {
  WitsmlValue top, bottom;
  WitsmlValue diameter;  // the drift of a casing or liner (else its nominal ID), an open hole's diameter
  std::string source;    // "casing, diaDrift"
  WitsmlOrigin origin;   // the section the diameter comes from
  bool cased = false;    // inside casing or a liner (the section's typeHoleCasing is not open hole)
};

struct WitsmlGeometry {
  std::string name;
  WitsmlOrigin origin;
  std::vector<WitsmlHoleInterval> hole;  // top down, contiguous
};

struct WitsmlComponent {
  model::ComponentType type = model::ComponentType::Sub;
  std::string witsml_type;   // typeTubularComp as written
  int sequence = 0;
  std::string name;          // its description, else ""
  std::string material;      // a built-in drillflex material, else "" (the type's default)
  WitsmlValue od;
  std::optional<WitsmlValue> id;      // absent only for a bit
  WitsmlValue length;                 // one item (lenJointAv when len is a whole number of joints)
  int count = 1;
  std::optional<WitsmlValue> blade_od, blade_length;          // stabilizer, motor
  std::optional<WitsmlValue> joint_od, joint_id, joint_length; // drill pipe, HWDP (connections)
  std::optional<WitsmlValue> bend, bend_to_bit;               // motor: angle, distance from the bit
  std::optional<int> lobes;                                   // motor: rotor lobes
  std::string grade;                                          // an API grade's name (model/string_limits.hpp), else ""
  std::optional<WitsmlValue> makeup_torque;                   // the connections' smallest tqMakeup
  WitsmlOrigin origin;
};

struct WitsmlTubular {
  std::string name;
  WitsmlOrigin origin;
  std::vector<WitsmlComponent> components;  // from the bit up (sequence 1 first)
};

struct WitsmlDocument {
  std::string file;
  std::string version;  // "1.4.1.1" or "2.0"
  std::vector<WitsmlTrajectory> trajectories;
  std::vector<WitsmlTubular> tubulars;
  std::vector<WitsmlGeometry> geometries;
  std::vector<std::string> warnings;  // "file:line: path: <field> not mapped: why"
};

// Reads a WITSML document from memory (tests, fuzzing); `file_name` names it in messages.
WitsmlDocument ReadWitsml(std::string_view text, const std::string& file_name);
// The same from a file.
WitsmlDocument ReadWitsmlFile(const std::string& path);

// The documents' content as drillflex's own input, in SI.
std::vector<well::SurveyStation> SurveyOf(const WitsmlTrajectory& trajectory);
std::vector<well::HoleSection> HoleOf(const WitsmlGeometry& geometry);
model::Component ComponentOf(const WitsmlComponent& component);

}  // namespace drillflex::io
