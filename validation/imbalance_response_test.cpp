// Forced response to a mass imbalance against the single-mode analytic response
// (validation/imbalance-response/collar.yaml): the V5 collar, 30 ft pinned-pinned, no well, no
// gravity, no fluid, m e = 0.02 kg·m at mid-span, swept 280–340 rpm by 0.05 rpm.
//
// Derivation. The imbalance whirls with the collar: F(t) = m e Ω² (cos Ωt e_y + sin Ωt e_z) at
// mid-span x_m = L/2. The first lateral mode of a pinned-pinned uniform beam is φ(x) = sin(πx/L)
// in each of the planes x-y and x-z (a double eigenvalue ω₁), modal mass m₁ = ∫ m φ² dx = m L/2
// (m = ρA), φ(x_m) = 1. Keeping that mode only, each plane is a 1-DOF oscillator
//   m₁ q̈ + 2ζ ω₁ m₁ q̇ + m₁ ω₁² q = φ(x_m) m e Ω² cos Ωt   (and sin Ωt in x-z),
// so |q| = (m e Ω² φ(x_m)/m₁) / sqrt((ω₁² − Ω²)² + (2ζω₁Ω)²), and the mid-span orbit is the circle
// of radius X = φ(x_m)|q| (the two planes a quarter period apart). With the M-normalised shapes
// this is X = m e Ω² φ(x_m)²/sqrt(...), the same: φ(x_m)²/m₁ does not depend on the scaling.
// X(Ω) = m e r²/(m₁ sqrt((1 − r²)² + (2ζr)²)), r = Ω/ω₁, peaks where d/dr(r⁴/((1−r²)² + 4ζ²r²)) = 0,
// i.e. at r² = 1/(1 − 2ζ²): Ω_peak = ω₁/sqrt(1 − 2ζ²), X_peak = m e/(2ζ m₁ sqrt(1 − ζ²)).
// ω₁ and ζ are the model's (drillflex modes: the pinned-pinned frequency, V5 within 0.03 %, and
// ζ = ζ_s + φᵀDφ/(2ω)); drillflex's structural damping is a loss factor 2ζ_s on K, which equals a
// viscous 2ζ_sω₁ at resonance, so the single-mode form holds near the peak (the peak of a
// loss-factor oscillator sits at r² = 1 + 4ζ_s², not 1/(1 − 2ζ²): both 2e-4 from r = 1).
// Tolerances (the issue's): peak RPM within 0.5 %, peak amplitude within 2 % (the other modes
// (3rd at 9 ω₁) and the model's rotary inertia and discretization are far smaller).
#include <cmath>
#include <cstdio>

#include "field_units.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace {

constexpr double kOd = 8.0 * kMetresPerInch, kId = 2.8125 * kMetresPerInch;
constexpr double kLength = 30.0 * kMetresPerFoot;
constexpr double kImbalance = 0.02;  // kg·m

TEST(ImbalanceResponse, PeakMatchesTheSingleModeResponse) {
  const auto modes = RunCase("modes", "imbalance-response/collar.yaml");
  ASSERT_TRUE(modes.contains("modes"));
  const double omega1 = 2.0 * kPi * modes["modes"][0]["frequency_hz"].get<double>();
  const double zeta = modes["modes"][0]["damping_ratio"].get<double>();
  const auto results = RunCase("vibration", "imbalance-response/collar.yaml");
  ASSERT_TRUE(results.contains("vibration"));
  const auto& vibration = results["vibration"];
  const auto& rpm = vibration["rpm"];
  const auto& displacement = vibration["max_lateral_displacement"];  // in (field output units)
  ASSERT_EQ(rpm.size(), 1201u);
  std::size_t peak = 0;
  for (std::size_t i = 0; i < displacement.size(); ++i) {
    if (displacement[i].get<double>() > displacement[peak].get<double>()) peak = i;
  }
  const double modal_mass = 7850.0 * kPi * (kOd * kOd - kId * kId) / 4.0 * kLength / 2.0;
  const double peak_reference_rpm = omega1 / std::sqrt(1.0 - 2.0 * zeta * zeta) * 30.0 / kPi;
  const double amplitude_reference = kImbalance / (2.0 * zeta * modal_mass * std::sqrt(1.0 - zeta * zeta));
  const double peak_rpm = rpm[peak].get<double>();
  const double amplitude = displacement[peak].get<double>() * kMetresPerInch;
  std::printf("imbalance: peak %.3f rpm (single mode %.3f rpm, %+.3f %%), amplitude %.5g m (%.5g m, %+.2f %%); "
              "zeta %.5f, s of the peak %.3f ft\n",
              peak_rpm, peak_reference_rpm, 100.0 * RelativeError(peak_rpm, peak_reference_rpm), amplitude,
              amplitude_reference, 100.0 * RelativeError(amplitude, amplitude_reference), zeta,
              vibration["s_max_displacement"][peak].get<double>());
  EXPECT_LT(std::abs(RelativeError(peak_rpm, peak_reference_rpm)), 5e-3);
  EXPECT_LT(std::abs(RelativeError(amplitude, amplitude_reference)), 0.02);
  EXPECT_NEAR(vibration["s_max_displacement"][peak].get<double>(), 15.0, 0.5);  // mid-span, ft
  // The one critical RPM is that peak.
  ASSERT_EQ(vibration["critical_rpm"].size(), 1u);
  EXPECT_NEAR(vibration["critical_rpm"][0].get<double>(), peak_rpm, 1e-9);
  // Off the peak (±5 % in speed) the single-mode curve still holds within 2 %.
  for (const double r : {0.95, 1.05}) {
    const double omega = r * omega1;
    const std::size_t i = static_cast<std::size_t>(std::lround((omega * 30.0 / kPi - 280.0) / 0.05));
    const double speed = rpm[i].get<double>() * kPi / 30.0;
    const double reference = kImbalance * speed * speed / modal_mass /
                             std::hypot(omega1 * omega1 - speed * speed, 2.0 * zeta * omega1 * speed);
    const double value = displacement[i].get<double>() * kMetresPerInch;
    std::printf("  at %.2f rpm: %.5g m (single mode %.5g m, %+.2f %%)\n", rpm[i].get<double>(), value, reference,
                100.0 * RelativeError(value, reference));
    EXPECT_LT(std::abs(RelativeError(value, reference)), 0.02) << r;
  }
}

}  // namespace
}  // namespace drillflex::validation
