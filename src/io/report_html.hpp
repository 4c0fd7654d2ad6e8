// report.html: the engineer's report of a job, one self-contained page (its scripts inlined: Chart.js
// and three.js from Debian's packages, embedded at build time; no network reference, no file beside
// it). The page draws what results.json holds (the same object, inlined), in the case's output
// units, plus a few things results.json does not carry (ReportData: the string's components, the
// hole's centre at each station, mode shapes, the transient's time series). docs/architecture.md
// says why Chart.js and three.js; docs/case-format.md lists the sections.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/transient_analysis.hpp"
#include "analyses/vibration_analysis.hpp"
#include "io/case.hpp"
#include "model/builder.hpp"

namespace drillflex::io {

// What the report draws beyond results.json, gathered as the analyses run (output units).
class ReportData {
 public:
  // The components along the string (s from the bit, OD, blades) and, with a well, the hole's centre
  // at every station (for the 3-D view).
  void AddStatic(const Case& c, const model::ModelInput& input, const analyses::StaticResult& result);
  // Each mode's lateral shape along the string (|u_y|, |u_z| and their signed values).
  void AddModes(const Case& c, const analyses::ModesResult& result);
  // The time series the transient section plots, and each probe's orbit with the radial clearance
  // there (the wall's circle).
  void AddTransient(const Case& c, const model::ModelInput& input, const analyses::TransientResult& result);
  // The vibration's excitations by name ("imbalance 1×", "bit 3×", "motor"), in the case's order.
  void AddExcitations(const Case& c);

  const nlohmann::json& content() const { return json_; }

 private:
  nlohmann::json json_ = nlohmann::json::object();
};

// The header's facts about the run.
struct ReportRun {
  std::string command;        // "static", "run", ...
  double run_seconds = 0.0;   // wall time of the job up to the report
};

// The page: `results` is the job's results.json object, `data` what ReportData gathered.
std::string ComposeReportHtml(const nlohmann::json& results, const ReportData& data, const ReportRun& run);

}  // namespace drillflex::io
