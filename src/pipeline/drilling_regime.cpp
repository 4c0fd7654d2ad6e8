#include "pipeline/drilling_regime.hpp"

#include <cmath>

#include "pipeline/sweep_outcome.hpp"

namespace drillflex::pipeline {
namespace {

struct ProbeOrbit {
  double least_radius = 0.0;   // m
  double turned = 0.0;         // rad, the whirl angle's span over the window (unwrapped)
  double whirl_speed = 0.0;    // rad/s, least-squares slope of the unwrapped angle
};

// Probe `p`'s orbit over the samples from `first` on.
ProbeOrbit ReadOrbit(const std::vector<analyses::TransientSample>& samples, std::size_t first, std::size_t p) {
  ProbeOrbit orbit;
  double unwrapped = 0.0, previous = 0.0, lowest = 0.0, highest = 0.0;
  double sum_t = 0.0, sum_a = 0.0, sum_tt = 0.0, sum_ta = 0.0;
  const double count = static_cast<double>(samples.size() - first);
  for (std::size_t i = first; i < samples.size(); ++i) {
    const analyses::ProbeSample& probe = samples[i].probes[p];
    const double angle = probe.whirl_angle;
    if (i == first) {
      unwrapped = angle;
      lowest = highest = angle;
      orbit.least_radius = std::hypot(probe.lateral_y, probe.lateral_z);
    } else {
      // The smallest step between two wrapped angles (samples are far closer than half a turn).
      unwrapped += std::remainder(angle - previous, 2.0 * kPi);
    }
    previous = angle;
    lowest = std::min(lowest, unwrapped);
    highest = std::max(highest, unwrapped);
    orbit.least_radius = std::min(orbit.least_radius, std::hypot(probe.lateral_y, probe.lateral_z));
    const double t = samples[i].time;
    sum_t += t;
    sum_a += unwrapped;
    sum_tt += t * t;
    sum_ta += t * unwrapped;
  }
  orbit.turned = highest - lowest;
  const double spread = count * sum_tt - sum_t * sum_t;
  orbit.whirl_speed = spread > 0.0 ? (count * sum_ta - sum_t * sum_a) / spread : 0.0;
  return orbit;
}

}  // namespace

std::string DrillingRegime::Name() const {
  std::string name = stick_slip_severity >= kStickSlipSeverity             ? "stick-slip"
                     : stick_slip_severity >= kTorsionalOscillationSeverity ? "torsional oscillation"
                                                                            : "smooth";
  if (whirl != Whirl::None) name += std::string(", ") + analyses::WhirlName(whirl) + " whirl";
  return name;
}

DrillingRegime ClassifyDrillingRegime(const analyses::TransientResult& result, const std::vector<double>& probe_clearance) {
  DrillingRegime regime;
  const auto& samples = result.samples;
  if (samples.size() < 4) return regime;
  const double severity = StickSlipSeverity(result);
  regime.stick_slip_severity = std::isfinite(severity) ? severity : 0.0;
  const std::size_t first = samples.size() / 2;
  double bit_speed = 0.0;
  for (std::size_t i = first; i < samples.size(); ++i) bit_speed += samples[i].bit_speed;
  const std::size_t probes = std::min(probe_clearance.size(), samples[first].probes.size());
  for (std::size_t p = 0; p < probes; ++p) {
    const ProbeOrbit orbit = ReadOrbit(samples, first, p);
    if (!(probe_clearance[p] > 0.0)) continue;  // no wall there (or none known)
    if (orbit.least_radius < kWhirlRadiusFraction * probe_clearance[p] || orbit.turned < 2.0 * kPi) continue;
    const Whirl whirl = orbit.whirl_speed * bit_speed >= 0.0 ? Whirl::Forward : Whirl::Backward;
    // Backward whirl outranks forward; between probes whirling alike, the faster.
    const bool outranks = regime.whirl == Whirl::None || (whirl == Whirl::Backward && regime.whirl == Whirl::Forward) ||
                          (whirl == regime.whirl && std::abs(orbit.whirl_speed) > std::abs(regime.whirl_speed));
    if (!outranks) continue;
    regime.whirl = whirl;
    regime.whirl_speed = orbit.whirl_speed;
    regime.whirl_probe_s = p < result.probe_s.size() ? result.probe_s[p] : 0.0;
  }
  return regime;
}

}  // namespace drillflex::pipeline
