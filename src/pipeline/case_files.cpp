#include "pipeline/case_files.hpp"

#include "io/analysis_results.hpp"
#include "io/report_html.hpp"
#include "io/vtk_files.hpp"
#include "pipeline/casing_wear_run.hpp"
#include "pipeline/transient_limits.hpp"

namespace drillflex::pipeline {

io::ResultFiles ComposeResultFiles(const io::Case& c, const CaseResults& results, const FileOptions& options) {
  io::ResultFiles files(options.directory.empty() ? io::DefaultOutputDirectory(c) : options.directory);
  const model::ModelInput& input = results.model.input;
  io::AddCaseHeader(c, results.model.built, files);
  io::AddOperation(c, input, files);
  io::ReportData report;
  // The modes and the vibration write the equilibrium they start from too: the report and
  // string.vtp draw it.
  if (results.static_result) {
    io::AddStaticResults(c, *results.static_result, files);
    AddCasingWearResults(c, files);
    if (options.report) report.AddStatic(c, input, *results.static_result);
    if (options.vtk) io::AddStaticVtk(c, results.model.built, *results.static_result, files);
  }
  if (results.modes) {
    io::AddModesResults(c, *results.modes, files);
    if (options.report) report.AddModes(c, *results.modes);
  }
  if (results.campbell) io::AddCampbellResults(c, *results.campbell, files);
  if (results.vibration) {
    io::AddVibrationResults(c, *results.vibration, files);
    if (options.report) report.AddExcitations(c);
  }
  if (results.buckling) io::AddBucklingResults(c, *results.buckling, files);
  if (results.tendency) io::AddTendencyResults(c, *results.tendency, files);
  if (results.transient) {
    io::AddTransientResults(c, *results.transient, files);
    if (results.transient_limits) AddTransientLimits(c, *results.transient_limits, files);
    if (options.report) report.AddTransient(c, input, *results.transient);
    if (options.vtk && results.transient_setup) {
      io::AddTransientVtk(c, results.transient_setup->moving, *results.transient, files);
    }
  }
  // The analyses of a run that kept what finished and did not finish: named, with why (the report shows
  // each where its section would be).
  if (!results.failures.empty()) {
    auto& failures = files.json()["failures"] = nlohmann::json::array();
    for (const AnalysisFailure& failure : results.failures) {
      failures.push_back({{"analysis", AnalysisName(failure.analysis)}, {"message", failure.message}});
    }
  }
  if (options.report) {
    files.Add("report.html", io::ComposeReportHtml(files.json(), report, {options.command, options.run_seconds}));
  }
  return files;
}

}  // namespace drillflex::pipeline
