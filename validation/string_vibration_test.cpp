// V6 of validation.md (validation/v6-string-vibration/): axial and torsional vibration of a
// fixed–free string, 1000 m of 5 in × 4.276 in drill pipe without tool joints, built-in steel
// (E = 2.1e11 Pa, ν = 0.3, ρ = 7850 kg/m³), no well, no gravity, no fluid:
//   axial f_n = (2n − 1)/(4L) sqrt(E/ρ), torsional f_n = (2n − 1)/(4L) sqrt(G/ρ), G = E/(2(1 + ν)),
// the first three of each within 0.5 % (`analyses.modes.kind: axial` / `torsional`).
// The rule-of-thumb critical RPM 33,055 sqrt(OD² + ID²)/L² (in, ft; ±15 %) is reported beside the
// computed lateral one (60 f₁): checked on one 30 ft pinned-pinned span, where it is the pinned-pinned
// beam's 60 (π/2L²) sqrt(EI/m) with the field constants of 30e6 psi steel; computed within 0.5 % of
// that beam with drillflex's steel, and the rule within its ±15 % of the computed.
#include <cmath>
#include <cstdio>

#include "field_units.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace string_vibration_test {

constexpr double kE = 2.1e11, kNu = 0.3, kRho = 7850.0, kLength = 1000.0;

void ExpectFixedFreeFrequencies(const char* kind, double wave_speed) {
  const auto results = RunCase("modes", std::string("v6-string-vibration/") + kind + ".yaml");
  ASSERT_TRUE(results.contains("modes"));
  const auto& modes = results["modes"];
  ASSERT_EQ(modes.size(), 3u);
  for (int n = 1; n <= 3; ++n) {
    const double reference = (2.0 * n - 1.0) / (4.0 * kLength) * wave_speed;
    const double f = modes[n - 1]["frequency_hz"].get<double>();
    std::printf("V6 %-9s f%d = %.6f Hz (reference %.6f Hz, %+.4f %%)\n", kind, n, f, reference,
                100.0 * RelativeError(f, reference));
    EXPECT_EQ(modes[n - 1]["kind"], kind);
    EXPECT_LT(std::abs(RelativeError(f, reference)), 5e-3) << kind << " mode " << n;
  }
}

TEST(V6StringVibration, FixedFreeAxialFrequenciesWithinHalfPercent) {
  ExpectFixedFreeFrequencies("axial", std::sqrt(kE / kRho));
}

TEST(V6StringVibration, FixedFreeTorsionalFrequenciesWithinHalfPercent) {
  ExpectFixedFreeFrequencies("torsional", std::sqrt(kE / (2.0 * (1.0 + kNu)) / kRho));
}

TEST(V6StringVibration, RuleOfThumbCriticalRpmIsReportedBesideTheComputedOne) {
  const auto results = RunCase("modes", "v6-string-vibration/lateral-span.yaml");
  ASSERT_TRUE(results.contains("critical_rpm"));
  const auto& critical = results["critical_rpm"];
  const double od = 5.0, id = 4.276, span = 30.0;  // in, ft
  const double rule = 33055.0 * std::sqrt(od * od + id * id) / (span * span);
  EXPECT_NEAR(critical["rule_of_thumb"].get<double>(), rule, 1e-9 * rule);
  EXPECT_NEAR(critical["rule_of_thumb_span"].get<double>(), span, 1e-9);
  // Pinned-pinned: 60 (π/2L²) sqrt(EI/(ρA)), sqrt(I/A) = sqrt(OD² + ID²)/4.
  const double length = span * kMetresPerFoot;
  const double radius_of_gyration = std::sqrt(od * od + id * id) * kMetresPerInch / 4.0;
  const double beam = 60.0 * kPi / (2.0 * length * length) * std::sqrt(kE / kRho) * radius_of_gyration;
  const double computed = critical["first_lateral"].get<double>();
  std::printf("V6 critical RPM of a 30 ft span: computed %.2f rpm (pinned-pinned beam %.2f, %+.3f %%), rule of "
              "thumb %.2f rpm (%+.2f %% of the computed)\n",
              computed, beam, 100.0 * RelativeError(computed, beam), rule, 100.0 * RelativeError(rule, computed));
  EXPECT_LT(std::abs(RelativeError(computed, beam)), 5e-3);
  EXPECT_LT(std::abs(RelativeError(rule, computed)), 0.15);
}

}  // namespace string_vibration_test
}  // namespace drillflex::validation
