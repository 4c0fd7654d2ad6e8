// "campbell" and campbell.csv: the gyroscopic modes against the rotary speed (analyses/gyroscopic_modes.hpp).
#include "io/analysis_results.hpp"

namespace drillflex::io {

using nlohmann::json;
using units::Quantity;

void AddCampbellResults(const Case& c, const analyses::CampbellResult& result, ResultFiles& files) {
  auto out = [&](double si, Quantity quantity) { return units::FromSI(si, quantity, c.output_units); };
  CsvTable table({"rpm", "mode", "frequency_hz", "damping_ratio", "whirl_index", "lateral_fraction"},
                 {std::string(units::DefaultUnit(Quantity::RotarySpeed, c.output_units)), "-", "Hz", "-", "-", "-"});
  json rpm = json::array(), points = json::array();
  for (const analyses::CampbellPoint& point : result.points) {
    const double speed = out(point.rotary_speed, Quantity::RotarySpeed);
    rpm.push_back(speed);
    json modes = json::array();
    for (std::size_t m = 0; m < point.modes.size(); ++m) {
      const analyses::ModeResult& mode = point.modes[m];
      table.AddRow({speed, static_cast<double>(m + 1), mode.frequency_hz, mode.damping_ratio, mode.whirl_index,
                    mode.lateral_fraction});
      modes.push_back({{"frequency_hz", mode.frequency_hz},
                       {"damping_ratio", mode.damping_ratio},
                       {"kind", analyses::ModeKindName(mode.kind)},
                       {"whirl", analyses::WhirlName(mode.whirl)},
                       {"whirl_index", mode.whirl_index}});
    }
    points.push_back(modes);
  }
  json synchronous = json::array();
  for (const analyses::CampbellCrossing& crossing : result.synchronous) {
    synchronous.push_back({{"rpm", out(crossing.rotary_speed, Quantity::RotarySpeed)},
                           {"frequency_hz", crossing.frequency_hz},
                           {"branch", crossing.branch + 1},
                           {"whirl", analyses::WhirlName(crossing.whirl)}});
  }
  files.Add("campbell.csv", table.ToString());
  files.json()["campbell"] = {
      {"rpm", rpm}, {"modes", points}, {"synchronous", synchronous}, {"basis_size", result.basis_size}};
}

}  // namespace drillflex::io
