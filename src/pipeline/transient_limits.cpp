#include "pipeline/transient_limits.hpp"

#include <array>
#include <cmath>

#include "analyses/static_analysis.hpp"
#include "analyses/string_limits.hpp"
#include "io/analysis_results.hpp"

namespace drillflex::pipeline {
namespace {

using units::Quantity;

// The limits a transient frame is read against, in the order of the JSON's keys.
constexpr std::array kLimits{"yield", "makeup_torque", "helical_buckling", "fatigue"};

double NodeUtilisation(const analyses::NodeLimits& node, std::size_t limit) {
  switch (limit) {
    case 0: return node.stress_utilisation;
    case 1: return node.torque_utilisation;
    case 2: return node.buckling_utilisation;
    default: return node.fatigue_utilisation;
  }
}

}  // namespace

void AddTransientLimits(const io::Case& c, const model::BuiltModel& moving, const analyses::TransientResult& result,
                        io::ResultFiles& files) {
  if (result.frame_q.empty() || result.frame_q.size() != result.frame_times.size()) return;
  std::vector<analyses::NodeLimits> stations;           // s, md, component of each station
  std::vector<std::array<double, kLimits.size()>> most;  // each station's largest utilisations
  std::array<analyses::LimitUtilisation, kLimits.size()> largest{};
  std::array<double, kLimits.size()> when{};
  for (std::size_t f = 0; f < result.frame_q.size(); ++f) {
    const analyses::StringLimits limits = analyses::ComputeStringLimits(
        c.input, analyses::StaticNodeResults(moving, result.frame_q[f]), c.limits.design_factor);
    if (stations.empty()) {
      stations = limits.nodes;
      most.assign(stations.size(), {0.0, 0.0, 0.0, 0.0});
    }
    for (std::size_t i = 0; i < limits.nodes.size() && i < stations.size(); ++i) {
      for (std::size_t k = 0; k < kLimits.size(); ++k) {
        const double u = NodeUtilisation(limits.nodes[i], k);
        if (!std::isfinite(u)) continue;
        most[i][k] = std::max(most[i][k], u);
        if (largest[k].component < 0 || u > largest[k].utilisation) {
          const analyses::NodeLimits& node = limits.nodes[i];
          largest[k] = {kLimits[k], u, node.s, node.md, node.component};
          when[k] = result.frame_times[f];
        }
      }
    }
  }
  const units::System system = c.output_units;
  const auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system) + 0.0; };
  nlohmann::json nodes = {{"s", nlohmann::json::array()}, {"md", nlohmann::json::array()}};
  for (const char* key : kLimits) nodes[std::string(key) + "_utilisation"] = nlohmann::json::array();
  for (std::size_t i = 0; i < stations.size(); ++i) {
    nodes["s"].push_back(out(stations[i].s, Quantity::Length));
    nodes["md"].push_back(out(stations[i].md, Quantity::Length));
    for (std::size_t k = 0; k < kLimits.size(); ++k) nodes[std::string(kLimits[k]) + "_utilisation"].push_back(most[i][k]);
  }
  nlohmann::json summary = nlohmann::json::object();
  std::size_t closest = kLimits.size();
  for (std::size_t k = 0; k < kLimits.size(); ++k) {
    nlohmann::json entry = io::UtilisationJson(c, largest[k]);
    if (entry.is_null()) continue;
    entry["time"] = out(when[k], Quantity::Time);
    summary[kLimits[k]] = std::move(entry);
    if (closest == kLimits.size() || largest[k].utilisation > largest[closest].utilisation) closest = k;
  }
  if (closest < kLimits.size()) summary["closest"] = summary[kLimits[closest]];
  files.json()["transient"]["limits"] = {{"frames", result.frame_q.size()},
                                         {"design_factor", c.limits.design_factor},
                                         {"nodes", nodes},
                                         {"summary", summary}};
}

}  // namespace drillflex::pipeline
