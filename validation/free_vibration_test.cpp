// V8 of validation.md, the first case: free vibration of the V1 cantilever released from its static
// tip deflection, through `drillflex transient`. The period of the tip's swing against 1/f₁ of the
// Euler–Bernoulli cantilever (f₁ = (β₁L)²/(2πL²) sqrt(EI/ρA) = 2.1434 Hz, β₁L = 1.8751041), within
// 0.2 %; the total energy over 100 periods with no numerical damping (ρ∞ = 1) within 1e-3 of the
// energy of the swing.
#include <cmath>
#include <string>
#include <vector>

#include "validation_support.hpp"

namespace drillflex::validation {
namespace free_vibration_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLength = 5.08, kDiameter = 0.0762, kE = 2.1e11, kRho = 7800.0;

double FirstCantileverFrequency() {
  const double inertia = kPi * std::pow(kDiameter, 4) / 64.0, area = kPi * kDiameter * kDiameter / 4.0;
  const double beta_l = 1.8751041;
  return beta_l * beta_l / (2.0 * kPi * kLength * kLength) * std::sqrt(kE * inertia / (kRho * area));
}

TEST(V8FreeVibration, PeriodWithin02PercentAndEnergyWithin1e3Over100Periods) {
  const auto results = RunCase("transient", "v8-transient/free-vibration.yaml");
  ASSERT_TRUE(results.contains("transient"));
  EXPECT_EQ(results["model"]["coordinates"], 72);
  EXPECT_EQ(results["transient"]["time_series"], "transient.csv");
  const CsvColumns csv =
      ReadCsv(std::string(DRILLFLEX_BINARY_DIR "/validation-results/v8-transient/free-vibration/transient.csv"));
  const auto& time = csv["time"];
  const auto& tip = csv["probe1_lateral_z"];
  ASSERT_GT(time.size(), 1000u);
  // Released from the static tip deflection P L³/(3EI) (12.6 mm under 100 N), at rest.
  const double inertia = kPi * std::pow(kDiameter, 4) / 64.0;
  const double deflection = 100.0 * std::pow(kLength, 3) / (3.0 * kE * inertia);
  EXPECT_NEAR(tip.front(), deflection, 5e-4 * deflection);
  // Mean period between the first and the last downward zero crossing of the tip (linear
  // interpolation within a 2 ms sample: its error is O(ω²Δt²) of the sample, spread over 100 periods).
  std::vector<double> crossings;
  for (std::size_t i = 1; i < tip.size(); ++i) {
    if (tip[i - 1] > 0.0 && tip[i] <= 0.0) {
      crossings.push_back(time[i - 1] + (time[i] - time[i - 1]) * tip[i - 1] / (tip[i - 1] - tip[i]));
    }
  }
  ASSERT_GE(crossings.size(), 99u);
  const double period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double reference = 1.0 / FirstCantileverFrequency();
  std::printf("V8 free vibration: period %.6f s against %.6f s (%+.4f %%) over %zu periods\n", period, reference,
              100.0 * RelativeError(period, reference), crossings.size() - 1);
  EXPECT_LT(std::abs(RelativeError(period, reference)), 2e-3);
  // The swing keeps its amplitude: the last period's largest tip deflection within 1 % of the release.
  double last_peak = 0.0;
  for (std::size_t i = 0; i < tip.size(); ++i) {
    if (time[i] >= crossings[crossings.size() - 2]) last_peak = std::max(last_peak, std::abs(tip[i]));
  }
  EXPECT_NEAR(last_peak, tip.front(), 1e-2 * tip.front());
  // Energy: the total against its start, relative to the energy of the swing (the strain energy at
  // the release, ½ P δ, which turns into kinetic energy at each crossing).
  const auto& total = csv["total_energy"];
  double drift = 0.0;
  for (const double e : total) drift = std::max(drift, std::abs(e - total.front()));
  const double swing = 0.5 * 100.0 * deflection;
  std::printf("V8 free vibration: energy of the swing %.6f J, largest change %.3e J (%.3e)\n", swing, drift,
              drift / swing);
  EXPECT_LT(drift / swing, 1e-3);
  EXPECT_LT(results["transient"]["energy_drift"].get<double>(), 1e-3);
}

}  // namespace free_vibration_test
}  // namespace drillflex::validation
