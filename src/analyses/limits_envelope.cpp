#include "analyses/limits_envelope.hpp"

#include <cmath>

#include "analyses/static_analysis.hpp"
#include "analyses/string_stations.hpp"

namespace drillflex::analyses {
namespace {

constexpr std::array<const char*, kEnvelopeLimits> kNames{"yield", "makeup_torque", "helical_buckling", "fatigue"};

LimitValues NoValues() {
  LimitValues values;
  values.fill(kNoLimit);
  return values;
}

// Whether `value` is larger than `largest`, or the first that applies.
bool Exceeds(double value, double largest) { return std::isfinite(value) && (!std::isfinite(largest) || value > largest); }

}  // namespace

const char* EnvelopeLimitName(std::size_t limit) { return kNames.at(limit); }

double EnvelopeUtilisation(const NodeLimits& node, std::size_t limit) {
  switch (limit) {
    case 0: return node.stress_utilisation;
    case 1: return node.torque_utilisation;
    case 2: return node.buckling_utilisation;
    default: return node.fatigue_utilisation;
  }
}

std::size_t LimitsEnvelope::closest() const {
  std::size_t best = kEnvelopeLimits;
  for (std::size_t k = 0; k < kEnvelopeLimits; ++k) {
    if (summary[k].limit.empty()) continue;
    if (best == kEnvelopeLimits || summary[k].utilisation > summary[best].utilisation) best = k;
  }
  return best;
}

LimitsRecorder::LimitsRecorder(const model::ModelInput& input, const model::BuiltModel& model, double design_factor)
    : input_(input), model_(model) {
  envelope_.design_factor = design_factor;
  const std::vector<Station> stations = StringStations(model.system);
  for (Index i = 0; i < std::ssize(stations); ++i) {
    stations_.push_back(i);
    // The MD as a static without wall offsets takes it (ComputeStringLimits): the bit's less s.
    const double s = stations[i].s;
    envelope_.stations.push_back(StationRatings(input, s, input.well ? input.bit_md - s : s, design_factor));
  }
  envelope_.largest.assign(stations.size(), NoValues());
  envelope_.when.assign(stations.size(), LimitValues{});
  envelope_.summary_time.fill(0.0);
}

void LimitsRecorder::Read(double time, const VecX& q) {
  const std::vector<StaticNodeResult> nodes = StaticNodeResults(model_, q, 1.0, stations_);
  LimitValues at_sample = NoValues();
  std::array<std::size_t, kEnvelopeLimits> where{};
  for (Index i = 0; i < std::ssize(nodes); ++i) {
    NodeLimits node = envelope_.stations[i];
    LoadStationLimits(input_, nodes[i], node);
    for (std::size_t k = 0; k < kEnvelopeLimits; ++k) {
      const double u = EnvelopeUtilisation(node, k);
      if (Exceeds(u, envelope_.largest[i][k])) {
        envelope_.largest[i][k] = u;
        envelope_.when[i][k] = time;
      }
      if (Exceeds(u, at_sample[k])) {
        at_sample[k] = u;
        where[k] = i;
      }
    }
  }
  for (std::size_t k = 0; k < kEnvelopeLimits; ++k) {
    LimitUtilisation& largest = envelope_.summary[k];
    if (!Exceeds(at_sample[k], largest.limit.empty() ? kNoLimit : largest.utilisation)) continue;
    const NodeLimits& node = envelope_.stations[where[k]];
    largest = {kNames[k], at_sample[k], node.s, node.md, node.component};
    envelope_.summary_time[k] = time;
  }
  envelope_.times.push_back(time);
  envelope_.history.push_back(at_sample);
}

}  // namespace drillflex::analyses
