// `drillflex roadmap CASE [-o DIR] [--from MD] [--step MD] [--friction LIST] [--readings FILE] [--jobs N]
// [--no-report]`:
// the torque-and-drag roadmap (pipeline/roadmap.hpp) with the case's `analyses.roadmap` settings, the
// command line's over them; progress on standard error; roadmap.csv, roadmap.json and report.html
// written atomically at the end.
#include <chrono>
#include <iostream>

#include <fmt/format.h>

#include "app/batch_progress.hpp"
#include "app/commands.hpp"
#include "core/profile.hpp"
#include "pipeline/readings_files.hpp"
#include "pipeline/readings_model.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::app {

int RunRoadmapCommand(const CommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  profile::Enable(options.profile);
  io::Case c = io::ReadCase(options.case_path);
  // The command line's settings go through the case reader as the case's own would (units, checks).
  std::vector<io::CaseValue> values;
  if (!options.roadmap_from.empty()) values.push_back({"analyses.roadmap.from", options.roadmap_from});
  if (!options.roadmap_step.empty()) values.push_back({"analyses.roadmap.step", options.roadmap_step});
  if (!options.roadmap_model.empty()) values.push_back({"analyses.roadmap.model", options.roadmap_model});
  if (!options.roadmap_stiff_length.empty()) {
    values.push_back({"analyses.roadmap.stiff_length", options.roadmap_stiff_length});
  }
  if (!options.roadmap_friction.empty()) {
    values.push_back({"analyses.roadmap.friction", "[" + options.roadmap_friction + "]"});
  }
  if (!values.empty()) c = io::WithValues(c, values);
  const analyses::RoadmapSettings settings =
      pipeline::CompleteRoadmapSettings(c, c.analyses.roadmap.value_or(analyses::RoadmapSettings{}));
  const std::size_t depths = pipeline::RoadmapDepths(c, settings).size();
  const bool soft_only = settings.model == analyses::RoadmapModel::Soft;
  std::cout << fmt::format("roadmap: {} depths × {} friction factors of {}, 4 {} each, on {} job{}\n", depths,
                           settings.friction.size(), c.name,
                           soft_only ? "soft-string runs" : settings.model == analyses::RoadmapModel::Both
                                                                ? "statics and 4 soft-string runs"
                                                                : "statics",
                           options.jobs, options.jobs == 1 ? "" : "s");
  pipeline::RoadmapOptions run;
  run.jobs = options.jobs;
  run.progress = [](int done, int total, int failed, double seconds_left) {
    ShowBatchProgress("roadmap", done, total, failed, seconds_left);
  };
  if (options.verbose) run.log = [](const std::string& line) { std::cerr << line << '\n'; };
  const std::vector<pipeline::RoadmapPoint> points =
      soft_only ? pipeline::RunSoftRoadmap(c, settings) : pipeline::RunRoadmap(c, settings, run);
  const std::vector<pipeline::RoadmapPoint> soft_points =
      settings.model == analyses::RoadmapModel::Both ? pipeline::RunSoftRoadmap(c, settings)
                                                      : std::vector<pipeline::RoadmapPoint>{};
  // The rig's readings: each modelled at its own depth, activity and WOB at every friction factor.
  nlohmann::json readings_json = nullptr;
  std::string readings_csv;
  if (!options.readings_path.empty()) {
    io::RigReadingsOptions reading_options;
    if (c.input.well) reading_options.deepest_md = c.input.well->trajectory.end_md();
    const io::RigReadings readings = io::ReadRigReadings(options.readings_path, reading_options);
    for (const std::string& warning : readings.warnings) std::cerr << "drillflex: readings: " << warning << '\n';
    pipeline::ReadingsModelOptions model_options;
    model_options.kind = soft_only ? pipeline::ReadingsModelKind::kSoft : pipeline::ReadingsModelKind::kStiff;
    model_options.roadmap = settings;
    model_options.jobs = options.jobs;
    pipeline::ReadingsModel model(c, readings, model_options);
    std::vector<pipeline::ModelledReadings> models;
    pipeline::ReadingsParameters parameters = pipeline::CaseReadingsParameters(c);
    parameters.cased_hole_friction = settings.cased_friction;
    for (const double friction : settings.friction) {
      parameters.open_hole_friction = friction;
      std::cerr << fmt::format("\rroadmap: the {} readings at friction {:g}   ", readings.rows.size(), friction)
                << std::flush;
      models.push_back({fmt::format("μ {:g}", friction), friction, model.Evaluate(parameters)});
    }
    std::cerr << '\n';
    readings_json = pipeline::ReadingsJson(c, readings, models);
    readings_csv = pipeline::ReadingsCsv(c, readings, models);
  }
  const std::string directory =
      options.output_directory.empty() ? io::DefaultOutputDirectory(c) + "-roadmap" : options.output_directory;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool report = c.output.report && !options.no_report;
  pipeline::ComposeRoadmapFiles(c, settings, points, directory, report, seconds, soft_points, readings_json,
                                readings_csv)
      .Commit();
  int failed = 0;
  for (const pipeline::RoadmapPoint& point : points) failed += point.failed() ? 1 : 0;
  std::cout << fmt::format("roadmap: {} points, {} failed; results in {}/roadmap.csv{} ({:.3g} s)\n", points.size(),
                           failed, directory, report ? fmt::format(", the plots in {}/report.html", directory) : "",
                           seconds);
  if (options.profile) std::cerr << profile::FormatReport(seconds);
  return kExitOk;
}

}  // namespace drillflex::app
