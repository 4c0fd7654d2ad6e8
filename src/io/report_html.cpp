#include "io/report_html.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <ctime>

#include <fmt/format.h>

#include "io/analysis_results.hpp"
#include "well/hole.hpp"

namespace drillflex::io {

namespace report_assets {  // generated at build time (src/io/CMakeLists.txt, cmake/EmbedText.cmake)
std::string ChartJs();
std::string ThreeJs();
std::string OrbitControlsJs();
std::string ReportJs();
std::string ReportCss();
}  // namespace report_assets

namespace {

using nlohmann::json;
using units::Quantity;


// A series never holds more points than this (the transient's are thinned evenly): the page stays
// light and quick to open.
constexpr std::size_t kMaxSeriesPoints = 4000;

// A value drawn but not printed (a mode shape, the hole's centre, a time series) to `digits`
// significant figures: the page stays light (JSON writes the shortest form that reads back).
double Drawn(double value, int digits = 6) {
  if (!std::isfinite(value) || value == 0.0) return 0.0;
  return std::stod(fmt::format("{:.{}g}", value, digits));
}

struct Out {
  units::System system;
  double operator()(double si, Quantity quantity) const { return units::FromSI(si, quantity, system); }
  std::string Unit(Quantity quantity) const { return std::string(units::DefaultUnit(quantity, system)); }
};

json UnitNames(const Out& out) {
  return {{"length", out.Unit(Quantity::Length)},         {"diameter", out.Unit(Quantity::Diameter)},
          {"force", out.Unit(Quantity::Force)},           {"wob", out.Unit(Quantity::WeightOnBit)},
          {"moment", out.Unit(Quantity::Moment)},         {"stress", out.Unit(Quantity::Stress)},
          {"rpm", out.Unit(Quantity::RotarySpeed)},       {"dogleg", out.Unit(Quantity::DoglegSeverity)},
          {"system", std::string(units::SystemName(out.system))}};
}

// JSON inside <script type="application/json">: "</" would end the element early.
std::string ScriptSafe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) {
    text.replace(at, 2, "<\\/");
  }
  return text;
}

std::string HtmlEscape(const std::string& text) {
  std::string escaped;
  for (const char ch : text) {
    switch (ch) {
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '&': escaped += "&amp;"; break;
      case '"': escaped += "&quot;"; break;
      default: escaped += ch;
    }
  }
  return escaped;
}

std::string UtcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

}  // namespace

void ReportData::AddStatic(const Case& c, const model::ModelInput& input, const analyses::StaticResult& result) {
  const Out out{c.output_units};
  json components = json::array();
  double s = 0.0;
  for (std::size_t index = 0; index < c.input.string.components.size(); ++index) {
    const model::Component& component = c.input.string.components[index];
    const double length = component.length * component.count;
    json entry = {{"name", component.name},
                  {"type", model::ComponentTypeName(component.type)},
                  {"from", out(s, Quantity::Length)},
                  {"to", out(s + length, Quantity::Length)},
                  {"od", out(component.outer_diameter, Quantity::Diameter)},
                  {"id", out(component.inner_diameter, Quantity::Diameter)},
                  {"count", component.count}};
    if (component.blade_diameter) entry["blade_od"] = out(*component.blade_diameter, Quantity::Diameter);
    if (component.joint_diameter) entry["joint_od"] = out(*component.joint_diameter, Quantity::Diameter);
    if (component.bend_angle) entry["bend_deg"] = *component.bend_angle / kDegree;
    components.push_back(std::move(entry));
    s += length;
  }
  json_["units"] = UnitNames(out);
  json_["components"] = std::move(components);
  if (input.well) {
    // The hole's centre at each station (the string's place in the hole is node.position less it).
    json centre = json::array();
    for (const analyses::StaticNodeResult& node : result.nodes) {
      const Vec3 point = input.well->trajectory.Position(node.has_wall ? node.md : StationMd(c, node.s));
      centre.push_back(json::array({Drawn(out(point.x(), Quantity::Length), 9), Drawn(out(point.y(), Quantity::Length), 9),
                                    Drawn(out(point.z(), Quantity::Length), 9)}));
    }
    json_["hole_centre"] = std::move(centre);
  }
}

void ReportData::AddModes(const Case& c, const analyses::ModesResult& result) {
  const Out out{c.output_units};
  json s = json::array();
  for (const double value : result.s) s.push_back(Drawn(out(value, Quantity::Length)));
  json shapes = json::array();
  for (const analyses::ModeResult& mode : result.modes) {
    json y = json::array(), z = json::array(), x = json::array();
    for (const Vec3& d : mode.displacement) {
      x.push_back(Drawn(d.x(), 4));
      y.push_back(Drawn(d.y(), 4));
      z.push_back(Drawn(d.z(), 4));
    }
    shapes.push_back({{"axial", x}, {"y", y}, {"z", z}});
  }
  json_["mode_shapes"] = {{"s", s}, {"modes", shapes}};
}

void ReportData::AddExcitations(const Case& c) {
  json names = json::array();
  if (c.analyses.vibration) {
    for (const analyses::Excitation& excitation : c.analyses.vibration->excitations) {
      names.push_back(analyses::ExcitationName(excitation));
    }
  }
  json_["excitations"] = std::move(names);
}


void ReportData::AddTransient(const Case& c, const model::ModelInput& input, const analyses::TransientResult& result) {
  const Out out{c.output_units};
  const std::size_t count = result.samples.size();
  const std::size_t stride = std::max<std::size_t>(1, (count + kMaxSeriesPoints - 1) / kMaxSeriesPoints);
  json time = json::array(), surface_rpm = json::array(), bit_rpm = json::array(), torque = json::array(),
       wob = json::array(), hook = json::array(), tob = json::array();
  std::vector<json> probe_y(result.probe_s.size(), json::array()), probe_z(result.probe_s.size(), json::array()),
      probe_force(result.probe_s.size(), json::array());
  for (std::size_t i = 0; i < count; i += stride) {
    const analyses::TransientSample& sample = result.samples[i];
    time.push_back(Drawn(sample.time, 8));
    surface_rpm.push_back(Drawn(out(sample.surface_speed, Quantity::RotarySpeed)));
    bit_rpm.push_back(Drawn(out(sample.bit_speed, Quantity::RotarySpeed)));
    torque.push_back(Drawn(out(sample.surface_torque, Quantity::Moment)));
    tob.push_back(Drawn(out(sample.torque_on_bit, Quantity::Moment)));
    wob.push_back(Drawn(out(sample.weight_on_bit, Quantity::WeightOnBit)));
    hook.push_back(Drawn(out(sample.hook_load, Quantity::Force)));
    for (std::size_t p = 0; p < sample.probes.size() && p < probe_y.size(); ++p) {
      probe_y[p].push_back(Drawn(out(sample.probes[p].lateral_y, Quantity::Diameter)));
      probe_z[p].push_back(Drawn(out(sample.probes[p].lateral_z, Quantity::Diameter)));
      probe_force[p].push_back(Drawn(out(sample.probes[p].contact_force, Quantity::Force)));
    }
  }
  json probes = json::array();
  for (std::size_t p = 0; p < result.probe_s.size(); ++p) {
    probes.push_back({{"s", out(result.probe_s[p], Quantity::Length)},
                      {"y", probe_y[p]},
                      {"z", probe_z[p]},
                      {"contact_force", probe_force[p]}});
    // Radial clearance: the hole's radius less the contact circle's (joint, blade or body) there.
    if (const auto clearance = model::RadialClearanceAt(input, result.probe_s[p])) {
      probes.back()["clearance"] = out(*clearance, Quantity::Diameter);
    }
  }
  json_["units"] = UnitNames(out);
  json_["transient"] = {{"time", time},       {"surface_rpm", surface_rpm}, {"bit_rpm", bit_rpm},
                        {"surface_torque", torque}, {"torque_on_bit", tob}, {"wob", wob},
                        {"hook_load", hook},  {"probes", probes}};
}

std::string ComposeReportHtml(const json& results, const ReportData& data, const ReportRun& run) {
  json header = {{"command", run.command},
                 {"run_seconds", run.run_seconds},
                 {"version", DRILLFLEX_VERSION},
                 {"written", UtcNow()}};
  if (!data.content().contains("units")) {
    const units::System system = results.value("units", std::string("SI")) == "field" ? units::System::Field
                                                                                       : units::System::SI;
    header["units"] = UnitNames(Out{system});
  }
  const std::string title = HtmlEscape(results.value("case", std::string("drillflex case")));
  std::string page;
  page.reserve(1500000);
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += fmt::format("<title>{}: drillflex report</title>\n", title);
  page += "<style>\n" + report_assets::ReportCss() + "\n</style>\n</head>\n<body>\n";
  page += "<div id=\"report\"></div>\n";
  page += "<script type=\"application/json\" id=\"results-json\">" + ScriptSafe(results.dump()) + "</script>\n";
  page += "<script type=\"application/json\" id=\"report-json\">" + ScriptSafe(data.content().dump()) + "</script>\n";
  page += "<script type=\"application/json\" id=\"run-json\">" + ScriptSafe(header.dump()) + "</script>\n";
  page += "<script>\n" + report_assets::ChartJs() + "\n</script>\n";
  page += "<script>\n" + report_assets::ThreeJs() + "\n</script>\n";
  page += "<script>\n" + report_assets::OrbitControlsJs() + "\n</script>\n";
  page += "<script>\n" + report_assets::ReportJs() + "\n</script>\n";
  page += "</body>\n</html>\n";
  return page;
}

}  // namespace drillflex::io
