// The string's limits over a transient run (issue 37), read at every output sample: the limits of
// analyses/string_limits.hpp (von Mises against yield / design factor, torque against make-up torque,
// compression against the helical buckling load, a rotating string's fatigue) at every station of the
// whole string, its section forces from the sample's state (analyses::StaticNodeResults), kept as an
// envelope: for each station and limit the largest utilisation over the samples and when; for each
// sample and limit the largest over the stations (the history); for each limit the largest of all,
// where and when. A station's ratings (its yield, make-up torque, buckling loads, the hole's curvature)
// are taken once (analyses::StationRatings): a sample costs the whole string's internal forces and a few
// operations a station (docs/validation.md V11b: its share of a run).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "analyses/string_limits.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// The limits an envelope follows, in this order (results.json's names): "yield", "makeup_torque",
// "helical_buckling", "fatigue".
inline constexpr std::size_t kEnvelopeLimits = 4;
const char* EnvelopeLimitName(std::size_t limit);
// A station's utilisation of limit `limit` (stress, torque, buckling, fatigue): NaN where it does not apply.
double EnvelopeUtilisation(const NodeLimits& node, std::size_t limit);

using LimitValues = std::array<double, kEnvelopeLimits>;  // one a limit, NaN where none applies

struct LimitsEnvelope {
  double design_factor = 0.0;
  std::vector<NodeLimits> stations;   // each station's ratings (s, md, component, ...), from the bit upward
  std::vector<LimitValues> largest;   // [station]: the largest utilisation over the samples
  std::vector<LimitValues> when;      // [station]: the time of the first sample that reached it, s
  std::vector<double> times;          // every sample read, s
  std::vector<LimitValues> history;   // [sample]: the largest utilisation over the stations
  std::array<LimitUtilisation, kEnvelopeLimits> summary{};  // the largest of all and where (limit "": none)
  LimitValues summary_time{};                                // when, s
  // The limit whose summary utilisation is the largest; kEnvelopeLimits when none applies.
  std::size_t closest() const;
};

// Reads the limits of `input`'s string on `model` (made from it, or from the same string: a transient's
// model in motion) at the samples it is given, in time order. `input` and `model` must outlive it.
class LimitsRecorder {
 public:
  LimitsRecorder(const model::ModelInput& input, const model::BuiltModel& model, double design_factor);
  // One output sample: the state q at `time`.
  void Read(double time, const VecX& q);
  const LimitsEnvelope& envelope() const { return envelope_; }

 private:
  const model::ModelInput& input_;
  const model::BuiltModel& model_;
  std::vector<Index> stations_;  // every station's index (analyses::StringStations)
  LimitsEnvelope envelope_;
};

}  // namespace drillflex::analyses
