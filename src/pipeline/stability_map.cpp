#include "pipeline/stability_map.hpp"

#include <cmath>

#include "core/error.hpp"
#include "io/report_html.hpp"
#include "pipeline/drilling_regime.hpp"
#include "pipeline/sweep_plan.hpp"

namespace drillflex::pipeline {
namespace {

using units::Quantity;

constexpr const char* kRpmKey = "operation.rpm";
constexpr const char* kWobKey = "operation.wob";
constexpr const char* kTopDriveRpmKey = "analyses.transient.top_drive.rpm";

// A varied value (as given: "120", "20 klbf") in the case's output units.
double Shown(const io::Case& c, const std::string& value, Quantity quantity) {
  return units::FromSI(units::ParseQuantity(value, quantity, c.units), quantity, c.output_units);
}

const std::string* ValueOf(const SweepCombination& values, const char* key) {
  for (const io::CaseValue& value : values) {
    if (value.key == key) return &value.value;
  }
  return nullptr;
}

// The map's colour class: backward whirl first (it wrecks a BHA fastest), then stick-slip, forward
// whirl, torsional oscillation, smooth.
std::string MapClass(const SweepOutcome& outcome) {
  if (!outcome.converged) return "failed";
  if (outcome.whirl == "backward") return "backward whirl";
  if (outcome.stick_slip_severity >= kStickSlipSeverity) return "stick-slip";
  if (outcome.whirl == "forward") return "forward whirl";
  if (outcome.stick_slip_severity >= kTorsionalOscillationSeverity) return "torsional oscillation";
  return "smooth";
}

}  // namespace

std::vector<SweepCombination> StabilityCombinations(const io::Case& c, const std::string& rpm_values,
                                                    const std::string& wob_values) {
  if (!c.analyses.transient) {
    throw InputError({c.file, 0, 0}, "analyses.transient",
                     "a stability map runs the case's transient at each RPM and WOB: the case lists none");
  }
  std::vector<SweepCombination> combinations = SweepCombinations(
      {ParseSweepAxis(std::string(kRpmKey) + "=" + rpm_values), ParseSweepAxis(std::string(kWobKey) + "=" + wob_values)});
  const auto& drive = c.analyses.transient->top_drive;
  if (drive && drive->mode == model::TopDriveMode::Speed) {
    for (SweepCombination& values : combinations) values.push_back({kTopDriveRpmKey, *ValueOf(values, kRpmKey)});
  }
  return combinations;
}

io::ResultFiles ComposeStabilityFiles(const io::Case& c, const std::vector<SweepRow>& rows,
                                      const std::string& directory, bool report, double run_seconds) {
  io::ResultFiles files = ComposeSweepFiles(c, rows, directory);
  nlohmann::json points = nlohmann::json::array();
  for (const SweepRow& row : rows) {
    const std::string* rpm = ValueOf(row.values, kRpmKey);
    const std::string* wob = ValueOf(row.values, kWobKey);
    if (!rpm || !wob) continue;
    const SweepOutcome& outcome = row.outcome;
    auto number = [](double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); };
    points.push_back({{"run", row.index + 1},
                      {"rpm", Shown(c, *rpm, Quantity::RotarySpeed)},
                      {"wob", Shown(c, *wob, Quantity::WeightOnBit)},
                      {"class", MapClass(outcome)},
                      {"regime", outcome.regime},
                      {"stick_slip_severity", number(outcome.stick_slip_severity)},
                      {"whirl", outcome.whirl},
                      {"whirl_speed", number(units::FromSI(outcome.whirl_speed, Quantity::RotarySpeed, c.output_units))},
                      {"message", outcome.message}});
  }
  nlohmann::json& json = files.json();
  json["stability"] = {{"points", points},
                       {"severity_limits", {kTorsionalOscillationSeverity, kStickSlipSeverity}},
                       {"whirl_radius_fraction", kWhirlRadiusFraction}};
  if (report) {
    nlohmann::json page = json;
    page["units"] = std::string(units::SystemName(c.output_units));  // the report's header reads the system here
    files.Add("report.html", io::ComposeReportHtml(page, io::ReportData{}, {"stability", run_seconds}));
  }
  return files;
}

}  // namespace drillflex::pipeline
