#include "pipeline/transient_limits.hpp"

#include <cmath>
#include <string>

#include "io/analysis_results.hpp"

namespace drillflex::pipeline {
namespace {

using analyses::kEnvelopeLimits;
using units::Quantity;

double Finite(double value) { return std::isfinite(value) ? value : 0.0; }

// Per station: s, md, each limit's largest utilisation (0 where it does not apply) and when.
nlohmann::json StationsJson(const io::Case& c, const analyses::LimitsEnvelope& envelope) {
  const units::System system = c.output_units;
  const auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system) + 0.0; };
  nlohmann::json nodes = {{"s", nlohmann::json::array()}, {"md", nlohmann::json::array()}};
  for (std::size_t i = 0; i < envelope.stations.size(); ++i) {
    nodes["s"].push_back(out(envelope.stations[i].s, Quantity::Length));
    nodes["md"].push_back(out(envelope.stations[i].md, Quantity::Length));
    for (std::size_t k = 0; k < kEnvelopeLimits; ++k) {
      const std::string name = analyses::EnvelopeLimitName(k);
      nodes[name + "_utilisation"].push_back(Finite(envelope.largest[i][k]));
      nodes[name + "_time"].push_back(out(envelope.when[i][k], Quantity::Time));
    }
  }
  return nodes;
}

// The time, and per limit that applies its largest utilisation over the stations at each sample.
nlohmann::json HistoryJson(const io::Case& c, const analyses::LimitsEnvelope& envelope) {
  const units::System system = c.output_units;
  nlohmann::json history = {{"time", nlohmann::json::array()}};
  for (const double time : envelope.times) history["time"].push_back(units::FromSI(time, Quantity::Time, system) + 0.0);
  for (std::size_t k = 0; k < kEnvelopeLimits; ++k) {
    if (envelope.summary[k].limit.empty()) continue;
    nlohmann::json& series = history[analyses::EnvelopeLimitName(k)] = nlohmann::json::array();
    for (const analyses::LimitValues& sample : envelope.history) series.push_back(Finite(sample[k]));
  }
  const std::size_t closest = envelope.closest();
  if (closest < kEnvelopeLimits) history["closest"] = analyses::EnvelopeLimitName(closest);
  return history;
}

}  // namespace

void AddTransientLimits(const io::Case& c, const analyses::LimitsEnvelope& envelope, io::ResultFiles& files) {
  if (envelope.times.empty()) return;
  nlohmann::json summary = nlohmann::json::object();
  for (std::size_t k = 0; k < kEnvelopeLimits; ++k) {
    nlohmann::json entry = io::UtilisationJson(c, envelope.summary[k]);
    if (entry.is_null()) continue;
    entry["time"] = units::FromSI(envelope.summary_time[k], Quantity::Time, c.output_units) + 0.0;
    summary[analyses::EnvelopeLimitName(k)] = std::move(entry);
  }
  const std::size_t closest = envelope.closest();
  if (closest < kEnvelopeLimits) summary["closest"] = summary[analyses::EnvelopeLimitName(closest)];
  files.json()["transient"]["limits"] = {{"samples", envelope.times.size()},
                                         {"frames", envelope.times.size()},
                                         {"design_factor", envelope.design_factor},
                                         {"nodes", StationsJson(c, envelope)},
                                         {"summary", summary},
                                         {"history", HistoryJson(c, envelope)}};
}

}  // namespace drillflex::pipeline
