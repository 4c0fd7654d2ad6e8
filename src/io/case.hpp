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

struct Case {
  std::string name;
  std::string file;        // path of the case file as given
  std::string directory;   // its directory, for relative paths
  units::System units = units::System::SI;
  units::System output_units = units::System::SI;

  std::optional<WellConfig> well;  // the survey and hole as given (the model's trajectory is in `input`)
  // What the model builder takes, read straight into it: the string, materials, model settings,
  // supports, loads, gravity, fluid and operation; with a well its trajectory, hole and bit MD; a
  // rotating string's sliding friction (rpm > 0); a WOB from the hook load when the case gives one.
  model::ModelInput input;
  analyses::AnalysesConfig analyses;
  OutputConfig output;
};

// Reads and validates a case file. Throws InputError naming the file, line, column and key path.
Case ReadCase(const std::string& path);

// The same from text (tests); `file` names it in messages, `directory` resolves survey_file.
Case ParseCase(const std::string& text, const std::string& file, const std::string& directory = ".");

// Total length of the string (m) from the bit end to its top.
double StringLength(const Case& c);

// The default output directory of a case: results/<case name with spaces as '-'>.
std::string DefaultOutputDirectory(const Case& c);

}  // namespace drillflex::io
