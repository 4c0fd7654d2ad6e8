// A case: everything one job needs, read from one YAML file (docs/case-format.md). Plain data in SI.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "core/error.hpp"
#include "fe/material.hpp"
#include "model/builder.hpp"
#include "model/string_config.hpp"
#include "model/string_limits.hpp"
#include "units/units.hpp"
#include "well/survey.hpp"

namespace drillflex::io {

struct WellConfig {
  std::vector<well::SurveyStation> survey;  // MD (m), inclination and azimuth (rad)
  std::string survey_file;                  // as given (relative to the case file), or ""
  std::vector<well::HoleSection> hole;      // top down
  double bit_md = 0.0;                      // m
  double output_step = 0.0;                 // m, spacing of trajectory output between stations
};

// `output`: which files beside results.json and the CSV tables a job writes.
struct OutputConfig {
  bool report = true;  // report.html
  bool vtk = true;     // string.vtp, well.vtp, contacts.vtp (ParaView)
};

// `limits.wear`: casing wear (model/casing_wear.hpp) over a run of rotating hours at the bit MD, or
// drilled from `from_md` to the bit MD at `rop`, at `rotary_speed`.
struct WearConfig {
  double wear_factor = 0.0;              // 1/Pa
  std::optional<double> rotating_time;   // s, at the case's bit MD
  std::optional<double> rate_of_penetration;  // m/s, with from_md
  std::optional<double> from_md;         // m
  double rotary_speed = 0.0;             // rad/s: the case's `wear.rpm`, else operation.rpm
};

// The case's `limits:` (analyses/string_limits.hpp): the allowable stress is yield / design_factor.
struct LimitsConfig {
  double design_factor = model::kDefaultDesignFactor;
  std::optional<WearConfig> wear;
};

struct Case {
  std::string name;
  std::string file;        // path of the case file as given
  std::string directory;   // its directory, for relative paths
  std::string text;        // the case file's text as read (ParseCaseWithValues reads it again changed)
  units::System units = units::System::SI;
  units::System output_units = units::System::SI;

  std::optional<WellConfig> well;  // the survey and hole as given (the model's trajectory is in `input`)
  // What the model builder takes, read straight into it: the string, materials, model settings,
  // supports, loads, gravity, fluid and operation; with a well its trajectory, hole and bit MD; a
  // rotating string's sliding friction (rpm > 0); a WOB from the hook load when the case gives one.
  model::ModelInput input;
  analyses::AnalysesConfig analyses;
  OutputConfig output;
  LimitsConfig limits;
  // What the reader read but could not map: the fields of the WITSML documents a `witsml:` key names
  // ("file:line:column: element path: <wtPerLen> not mapped: ..."); `drillflex check` prints them.
  std::vector<std::string> warnings;
};

// Reads and validates a case file. Throws InputError naming the file, line, column and key path.
Case ReadCase(const std::string& path);

// The same from text (tests); `file` names it in messages, `directory` resolves survey_file.
Case ParseCase(const std::string& text, const std::string& file, const std::string& directory = ".");

// One value of a case set by its key path instead of the file's: `key` as the case reader names keys
// ("operation.wob", "string[4].length", "model.contact.friction", "analyses.transient.duration"),
// `value` YAML in the case's syntax: a scalar with or without a unit ("30 klbf", "40 ft", "0.3") or a
// flow list or map ("{type: collar, od: 6.75, id: 2.8125, length: 10}").
struct CaseValue {
  std::string key;
  std::string value;
};

// The case of `text` with `values` set in its YAML tree before it is read, in order. A key the case
// leaves out is added, with the maps on its way, and the reader checks it as any other; an index must
// be in its list's range. Throws InputError naming the file and the key: a key
// path that cannot be read, a key or index the case does not have, a value that is not YAML, and every
// error of the reader for a value set here (at the place of the value it replaces, or of its map).
Case ParseCaseWithValues(const std::string& text, const std::string& file, const std::string& directory,
                         const std::vector<CaseValue>& values);

// The same case read again from its text with `values` set (ParseCaseWithValues).
Case WithValues(const Case& c, const std::vector<CaseValue>& values);

// Total length of the string (m) from the bit end to its top.
double StringLength(const Case& c);

// The default output directory of a case: results/<case name with spaces as '-'>.
std::string DefaultOutputDirectory(const Case& c);

}  // namespace drillflex::io
