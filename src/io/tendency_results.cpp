// "tendency" and tendency.csv: the steady build and turn rates (analyses/tendency_analysis.hpp).
#include "io/analysis_results.hpp"

#include <cmath>

namespace drillflex::io {

using nlohmann::json;
using units::Quantity;

void AddTendencyResults(const Case& c, const analyses::TendencyResult& result, ResultFiles& files) {
  auto out = [&](double si, Quantity quantity) { return units::FromSI(si, quantity, c.output_units); };
  const std::string rate_unit(units::DefaultUnit(Quantity::DoglegSeverity, c.output_units));
  const std::string force_unit(units::DefaultUnit(Quantity::Force, c.output_units));
  CsvTable table({"build_curvature", "right_curvature", "build_force", "walk_force", "tilt_build", "tilt_right",
                  "deviation_build", "deviation_right"},
                 {rate_unit, rate_unit, force_unit, force_unit, "deg", "deg", "deg", "deg"});
  json trace = json::array();
  for (const analyses::TendencyPoint& point : result.trace) {
    trace.push_back({{"build_curvature", out(point.curvature.build, Quantity::DoglegSeverity)},
                     {"right_curvature", out(point.curvature.right, Quantity::DoglegSeverity)},
                     {"deviation_build", out(point.deviation_build, Quantity::Angle)},
                     {"deviation_right", out(point.deviation_right, Quantity::Angle)}});
    table.AddRow({out(point.curvature.build, Quantity::DoglegSeverity),
                  out(point.curvature.right, Quantity::DoglegSeverity), out(point.bit.build_force, Quantity::Force),
                  out(point.bit.walk_force, Quantity::Force), out(point.bit.tilt, Quantity::Angle),
                  out(point.bit.tilt_right, Quantity::Angle), out(point.deviation_build, Quantity::Angle),
                  out(point.deviation_right, Quantity::Angle)});
  }
  files.Add("tendency.csv", table.ToString());
  const analyses::BitReport& bit = result.trace.at(result.steady_index).bit;
  // Where the BHA touches the wall in the steady hole.
  json contacts = json::array();
  for (const analyses::ContactReport& contact : result.equilibrium.contacts) {
    contacts.push_back({{"s", out(contact.s, Quantity::Length)},
                        {"md", out(contact.md, Quantity::Length)},
                        {"normal_force", out(contact.normal_force, Quantity::Force)},
                        {"high_side_angle", out(contact.high_side_angle, Quantity::Angle)}});
  }
  files.json()["tendency"] = {
      {"build_rate", out(result.build_rate, Quantity::DoglegSeverity)},
      {"turn_rate", out(result.turn_rate, Quantity::DoglegSeverity)},
      {"right_curvature", out(result.curvature.right, Quantity::DoglegSeverity)},
      {"dogleg_severity", out(result.dogleg_severity, Quantity::DoglegSeverity)},
      {"inclination", out(result.inclination, Quantity::Angle)},
      {"azimuth", out(result.azimuth, Quantity::Angle)},
      {"steerability", result.steerability},
      {"weight_on_bit", out(result.weight_on_bit, Quantity::WeightOnBit)},
      {"arc_length", out(result.arc_length, Quantity::Length)},
      {"statics", result.statics},
      {"toolfaces", result.toolfaces},
      {"contacts", contacts},
      {"trace", trace},
      {"bit",
       {{"side_force", out(bit.side_force, Quantity::Force)},
        {"build_force", out(bit.build_force, Quantity::Force)},
        {"walk_force", out(bit.walk_force, Quantity::Force)},
        {"tilt", out(bit.tilt, Quantity::Angle)},
        {"tilt_right", out(bit.tilt_right, Quantity::Angle)}}}};
  if (result.steering) {
    const analyses::SteeringRates& steering = *result.steering;
    const double sine = std::sin(result.inclination);
    const auto turn = [&](double right) { return sine > 1e-3 ? right / sine : 0.0; };
    files.json()["tendency"]["steering"] = {
        {"steer", steering.steer},
        {"natural", {{"build_rate", out(steering.natural.build, Quantity::DoglegSeverity)},
                     {"turn_rate", out(turn(steering.natural.right), Quantity::DoglegSeverity)}}},
        {"full", {{"build_rate", out(steering.full.build, Quantity::DoglegSeverity)},
                  {"turn_rate", out(turn(steering.full.right), Quantity::DoglegSeverity)}}},
        {"yield_per_steer",
         {{"build_rate", out(steering.full.build - steering.natural.build, Quantity::DoglegSeverity)},
          {"turn_rate", out(turn(steering.full.right - steering.natural.right), Quantity::DoglegSeverity)}}}};
    // The system as the case set it: a push-the-bit's pads' force, a point-the-bit's offset.
    if (c.analyses.tendency && c.analyses.tendency->rss) {
      const analyses::RssSettings& rss = *c.analyses.tendency->rss;
      json& system = files.json()["tendency"]["steering"];
      system["toolface"] = out(rss.toolface, Quantity::Angle);
      if (rss.type == analyses::RssType::Point) {
        system["type"] = "point";
        system["offset"] = out(rss.offset, Quantity::Angle);
      } else {
        system["type"] = "push";
        system["force"] = out(rss.force, Quantity::Force);
      }
    }
  }
  if (result.three_point) {
    const analyses::ThreePointYield& yield = *result.three_point;
    files.json()["tendency"]["three_point"] = {{"dogleg_severity", out(yield.curvature, Quantity::DoglegSeverity)},
                                               {"toolface", out(yield.toolface, Quantity::Angle)},
                                               {"pad", out(yield.pad, Quantity::Length)},
                                               {"bend", out(yield.bend, Quantity::Length)},
                                               {"stabilizer", out(yield.stabilizer, Quantity::Length)}};
  }
  if (result.sensitivities) {
    // A failed point is null (NaN in SI).
    const auto rates = [&](const std::vector<double>& values) {
      json list = json::array();
      for (const double v : values) list.push_back(std::isfinite(v) ? json(out(v, Quantity::DoglegSeverity)) : json());
      return list;
    };
    const auto curve = [&](const analyses::TendencyCurve& c, Quantity quantity) {
      json values = json::array();
      for (const double v : c.values) values.push_back(out(v, quantity));
      return json{{"values", values}, {"build_rate", rates(c.build_rate)}, {"turn_rate", rates(c.turn_rate)}};
    };
    const analyses::TendencySensitivities& s = *result.sensitivities;
    json gauge = curve(s.gauge_reduction, Quantity::Diameter);
    files.json()["tendency"]["sensitivities"] = {{"weight_on_bit", curve(s.weight_on_bit, Quantity::WeightOnBit)},
                                                 {"inclination", curve(s.inclination, Quantity::Angle)},
                                                 {"gauge_reduction", gauge}};
  }
}

}  // namespace drillflex::io
