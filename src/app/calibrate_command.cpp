// `drillflex calibrate CASE --readings FILE [--fit NAMES] [--model stiff|soft] [--stiff-length L] [-j N]
// [-o DIR] [--no-report]`: the friction factors, hook-load offset and bit torque coefficient fitted to
// the rig's readings (pipeline/calibration.hpp); progress on standard error; results.json,
// calibration.csv and report.html written atomically at the end, nothing when the input is refused.
#include <chrono>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include <fmt/format.h>

#include "app/batch_progress.hpp"
#include "app/commands.hpp"
#include "core/profile.hpp"
#include "pipeline/calibration.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::app {
namespace {

std::vector<pipeline::CalibrationParameter> ParseFit(const std::string& list) {
  std::vector<pipeline::CalibrationParameter> fit;
  std::stringstream stream(list);
  std::string name;
  while (std::getline(stream, name, ',')) {
    const auto first = name.find_first_not_of(' '), last = name.find_last_not_of(' ');
    name = first == std::string::npos ? "" : name.substr(first, last - first + 1);
    if (name.empty()) continue;
    const auto parameter = pipeline::CalibrationParameterOf(name);
    if (!parameter) {
      throw InputError({"--fit", 0, 0}, "",
                       fmt::format("unknown parameter '{}': expected open_hole_friction, cased_hole_friction, "
                                   "hook_load_offset or bit_torque_coefficient",
                                   name));
    }
    fit.push_back(*parameter);
  }
  return fit;
}

}  // namespace

int RunCalibrateCommand(const CommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  profile::Enable(options.profile);
  io::Case c = io::ReadCase(options.case_path);
  if (!options.roadmap_stiff_length.empty()) {
    c = io::WithValues(c, {{"analyses.roadmap.stiff_length", options.roadmap_stiff_length}});
  }
  if (!c.well || !c.input.well) throw InputError({c.file, 0, 0}, "well", "a calibration needs a well");
  pipeline::CalibrationSettings settings;
  settings.fit = ParseFit(options.calibrate_fit);
  if (options.calibrate_model == "soft") {
    settings.model.kind = pipeline::ReadingsModelKind::kSoft;
  } else if (!options.calibrate_model.empty() && options.calibrate_model != "stiff") {
    throw InputError({"--model", 0, 0}, "", fmt::format("expected stiff or soft, got '{}'", options.calibrate_model));
  }
  settings.model.roadmap = c.analyses.roadmap.value_or(analyses::RoadmapSettings{});
  settings.model.jobs = options.jobs;
  io::RigReadingsOptions reading_options;
  reading_options.deepest_md = c.input.well->trajectory.end_md();
  const io::RigReadings readings = io::ReadRigReadings(options.readings_path, reading_options);
  for (const std::string& warning : readings.warnings) std::cerr << "drillflex: readings: " << warning << '\n';
  std::cout << fmt::format("calibrate: {} readings of {} against the {} string model of {}, on {} job{}\n",
                           readings.rows.size(), readings.file,
                           settings.model.kind == pipeline::ReadingsModelKind::kSoft ? "soft" : "stiff", c.name,
                           options.jobs, options.jobs == 1 ? "" : "s");
  // A line a model evaluation (every reading once): redrawn on a terminal, one after another in a log.
  int evaluation = 0;
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  settings.model.progress = [&evaluation, terminal](int done, int total) {
    if (done != total) return;
    std::cerr << fmt::format("{}calibrate: {} model evaluations of the {} depths{}", terminal ? "\r" : "", ++evaluation,
                             total, terminal ? "" : "\n")
              << std::flush;
  };
  settings.log = [&options](const std::string& line) {
    if (options.verbose) std::cerr << '\n' << line << '\n';
  };
  const pipeline::CalibrationResult result = pipeline::Calibrate(c, readings, settings);
  if (terminal) std::cerr << '\n';
  const std::string directory =
      options.output_directory.empty() ? io::DefaultOutputDirectory(c) + "-calibration" : options.output_directory;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool report = c.output.report && !options.no_report;
  pipeline::ComposeCalibrationFiles(c, readings, result, directory, report, seconds).Commit();
  const units::System system = c.output_units;
  for (const pipeline::FittedParameter& p : result.parameters) {
    const units::Quantity quantity = p.parameter == pipeline::CalibrationParameter::kHookLoadOffset
                                         ? units::Quantity::Force
                                         : units::Quantity::Dimensionless;
    std::string unit;
    if (quantity != units::Quantity::Dimensionless) unit = fmt::format(" {}", units::DefaultUnit(quantity, system));
    const auto shown = [&](double si) { return units::FromSI(si, quantity, system); };
    if (p.fitted) {
      std::cout << fmt::format("  {:<24} {:.5g}{}  (95 %: {:.5g} to {:.5g})\n", pipeline::CalibrationParameterName(p.parameter),
                               shown(p.value), unit, shown(p.low), shown(p.high));
    } else {
      std::cout << fmt::format("  {:<24} {:.5g}{}  held: {}\n", pipeline::CalibrationParameterName(p.parameter),
                               shown(p.value), unit, p.note);
    }
  }
  std::cout << fmt::format("  residual RMS: hook load {:.4g} {} ({} readings), surface torque {:.4g} {} ({})\n",
                           units::FromSI(result.hook_load_rms, units::Quantity::Force, system),
                           units::DefaultUnit(units::Quantity::Force, system), result.hook_load_count,
                           units::FromSI(result.torque_rms, units::Quantity::Moment, system),
                           units::DefaultUnit(units::Quantity::Moment, system), result.torque_count);
  for (const std::string& warning : result.warnings) std::cout << "  warning: " << warning << '\n';
  std::cout << fmt::format("calibrate: {} iterations, {} model evaluations; results in {}/results.json{} ({:.3g} s)\n",
                           result.iterations, result.evaluations, directory,
                           report ? fmt::format(", the plots in {}/report.html", directory) : "", seconds);
  if (options.profile) std::cerr << profile::FormatReport(seconds);
  return kExitOk;
}

}  // namespace drillflex::app
