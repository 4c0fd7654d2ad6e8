// The files of a calibration (pipeline/calibration.hpp): results.json, calibration.csv, report.html.
#include <cmath>

#include "io/report_html.hpp"
#include "pipeline/calibration.hpp"
#include "pipeline/readings_files.hpp"

namespace drillflex::pipeline {
namespace {

using units::Quantity;

Quantity QuantityOf(CalibrationParameter parameter) {
  return parameter == CalibrationParameter::kHookLoadOffset ? Quantity::Force : Quantity::Dimensionless;
}

nlohmann::json Number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

const char* ModelName(ReadingsModelKind kind) { return kind == ReadingsModelKind::kSoft ? "soft" : "stiff"; }

}  // namespace

io::ResultFiles ComposeCalibrationFiles(const io::Case& c, const io::RigReadings& readings,
                                        const CalibrationResult& result, const std::string& directory, bool report,
                                        double run_seconds) {
  io::ResultFiles files(directory);
  const units::System system = c.output_units;
  auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system); };
  std::vector<ModelledReading> modelled;
  for (const ReadingResidual& residual : result.residuals) modelled.push_back(residual.modelled);
  const std::vector<ModelledReadings> models{{"fitted", result.parameters[0].value, modelled}};
  files.Add("calibration.csv", ReadingsCsv(c, readings, models));

  nlohmann::json parameters = nlohmann::json::object();
  for (const FittedParameter& p : result.parameters) {
    const Quantity quantity = QuantityOf(p.parameter);
    parameters[CalibrationParameterName(p.parameter)] = {
        {"value", Number(out(p.value, quantity))},
        {"low", Number(out(p.low, quantity))},
        {"high", Number(out(p.high, quantity))},
        {"standard_error", Number(out(p.standard_error, quantity))},
        {"fitted", p.fitted},
        {"note", p.note},
        {"unit", quantity == Quantity::Dimensionless ? "-" : std::string(units::DefaultUnit(quantity, system))},
    };
  }
  nlohmann::json names = nlohmann::json::array(), matrix = nlohmann::json::array();
  for (const CalibrationParameter p : result.fitted) names.push_back(CalibrationParameterName(p));
  for (Eigen::Index a = 0; a < result.correlation.rows(); ++a) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index b = 0; b < result.correlation.cols(); ++b) row.push_back(Number(result.correlation(a, b)));
    matrix.push_back(std::move(row));
  }
  nlohmann::json& json = files.json();
  json["case"] = c.name;
  json["units"] = std::string(units::SystemName(system));
  json["calibration"] = {
      {"model", ModelName(result.model)},
      {"readings_file", readings.file},
      {"bit_diameter", out(result.bit_diameter, Quantity::Diameter)},
      {"parameters", parameters},
      {"correlation", {{"parameters", names}, {"matrix", matrix}}},
      {"rms", {{"hook_load", out(result.hook_load_rms, Quantity::Force)},
               {"surface_torque", out(result.torque_rms, Quantity::Moment)}}},
      {"scatter", {{"hook_load", out(result.hook_load_scatter, Quantity::Force)},
                   {"surface_torque", out(result.torque_scatter, Quantity::Moment)}}},
      {"counts", {{"hook_load", result.hook_load_count}, {"surface_torque", result.torque_count}}},
      {"iterations", result.iterations},
      {"evaluations", result.evaluations},
      {"converged", result.converged},
      {"warnings", result.warnings},
      {"readings", ReadingsJson(c, readings, models)},
  };
  if (report) files.Add("report.html", io::ComposeReportHtml(json, io::ReportData{}, {"calibrate", run_seconds}));
  return files;
}

}  // namespace drillflex::pipeline
