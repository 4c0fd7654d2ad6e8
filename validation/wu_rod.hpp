// The Wu rod-in-pipe cases of V3 (validation/v3-wu-rod/): the rod's data, its references and the
// load against displacement read from a run's transient.csv.
#pragma once

#include <filesystem>
#include <cmath>
#include <string>
#include <vector>

#include "validation_support.hpp"

namespace drillflex::validation::wu {

constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 105e9, kDensity = 8500.0, kGravity = 9.81;  // Pa, kg/m³, m/s² (the cases')
constexpr double kRodDiameter = 3.2e-3, kPipeDiameter = 8.3e-3, kLength = 4.0;  // m
constexpr double kRamp = 0.1;  // s: the block's ramp to its velocity
constexpr int kProbes = 41;    // every 0.1 m from the blocker

struct Rod {
  double area = kPi * kRodDiameter * kRodDiameter / 4.0;
  double ei = kE * kPi * std::pow(kRodDiameter, 4) / 64.0;
  double w = kDensity * kGravity * area;          // N/m
  double r = 0.5 * (kPipeDiameter - kRodDiameter);  // radial clearance, m
  double f_sin = 2.0 * std::sqrt(ei * w / r);     // Dawson–Paslay
  double axial = kE * area / kLength;             // EA/L, N/m
};

// A run: the load at the loading end (compression, the block's force) against the block's travel
// ∫ v dt under the linear ramp to `speed` (m/s) over kRamp.
struct PushRun {
  CsvColumns csv;
  std::vector<double> time, load, travel;
  const std::vector<double>& Probe(int p, const char* what) const {
    return csv["probe" + std::to_string(p) + "_" + what];
  }
};

inline PushRun ReadRun(const std::string& case_name, double speed) {
  PushRun run;
  run.csv = ReadCsv((std::filesystem::path(DRILLFLEX_BINARY_DIR "/validation-results/v3-wu-rod") / case_name /
                     "transient.csv")
                        .string());
  run.time = run.csv["time"];
  for (std::size_t i = 0; i < run.time.size(); ++i) {
    const double t = run.time[i];
    run.load.push_back(-run.csv["hook_load"][i]);
    run.travel.push_back(t < kRamp ? 0.5 * speed * t * t / kRamp : speed * (t - 0.5 * kRamp));
  }
  return run;
}

}  // namespace drillflex::validation::wu
