// Forced response to a mass imbalance against the closed-form single-mode response of the
// pinned–pinned beam (validation/imbalance-response/collar.yaml): the V5 collar, 30 ft
// pinned–pinned, no well, no gravity, no fluid, m e = 0.02 kg·m at mid-span, swept 280–340 rpm by
// 0.05 rpm. Nothing of the reference comes from drillflex's output.
//
// Derivation. The imbalance whirls with the collar: F(t) = m e Ω² (cos Ωt e_y + sin Ωt e_z) at
// a = L/2. The first lateral mode of the pinned–pinned beam is φ(x) = sin(πx/L) in each of the
// planes x-y and x-z (a double eigenvalue ω₁), φ(a) = 1. The model is Euler–Bernoulli with the
// sections' rotary inertia (its default `rotary_inertia: true`), a Rayleigh beam:
// ω₁² = EI k⁴/(m + ρI k²), generalized mass M₁ = (L/2)(m + ρI k²), k = π/L (validation/pinned_beam.hpp).
// Damping as the model defines it (docs/case-format.md "Modes and damping"): ζ_s =
// `model.structural_damping` (0.01 by default) is a loss factor 2ζ_s on K, and each body's elastic
// modes carry the viscous modal damping diag(2ζ_s ω_j), which this slow mode sees as
// φᵀDφ = 2ζ_s s ω₁ M₁, s = 0.0195 (pinned::BodyModalDampingShare, from the bodies' free–free modes).
// Keeping that mode only, each plane is a 1-DOF oscillator
//   M₁ q̈ + φᵀDφ q̇ + M₁ ω₁² (1 + 2iζ_s) q = φ(a) m e Ω² e^{iΩt}   (and a quarter period later in x-z),
// so the mid-span orbit is the circle of radius
//   |w(a)| = m e Ω² φ(a)² / (M₁ |ω₁² − Ω² + i(2ζ_s ω₁² + 2ζ_s s ω₁ Ω)|),
// the single-mode response of Den Hartog, Mechanical Vibrations (4th ed., 1956) §3.3 (rotating
// unbalance), with hysteretic damping as in Bishop & Johnson, The Mechanics of Vibration (1960).
// Its peak is found on a fine grid of Ω (within 2ζ² of ω₁, ζ = ζ_s(1 + s)).
// Shear is not in the Euler–Bernoulli model; what it would change (Timoshenko, Cowper's κ) is
// checked with `model.beam: timoshenko` against the closed-form Timoshenko frequency.
// Tolerances (the issue's): peak RPM within 0.5 %, amplitudes within 2 % (the other modes (3rd at
// 9 ω₁) and the discretization are far smaller).
#include <cmath>
#include <cstdio>

#include "field_units.hpp"
#include "pinned_beam.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace imbalance_response_test {

constexpr double kImbalance = 0.02;         // kg·m
constexpr double kStructuralDamping = 0.01;  // model.structural_damping, the default
constexpr int kBodies = 4;                  // 30 ft in bodies of at most 3 m (model.body_length)
constexpr int kBodyBendingModes = 4;

pinned::Tube Collar() {
  return {30.0 * kMetresPerFoot, 8.0 * kMetresPerInch, 2.8125 * kMetresPerInch, 207e9, 7850.0, 0.3};
}

// The closed-form single-mode response: the mid-span orbit radius (m) at Ω (rad/s).
struct SingleMode {
  double omega1, modal_mass, loss_factor, viscous;  // rad/s, kg, 2ζ_s, φᵀDφ/M₁ (1/s)
  double Radius(double speed) const {
    const double real = omega1 * omega1 - speed * speed;
    const double imaginary = loss_factor * omega1 * omega1 + viscous * speed;
    return kImbalance * speed * speed / (modal_mass * std::hypot(real, imaginary));
  }
};

SingleMode CollarSingleMode() {
  const pinned::Tube tube = Collar();
  SingleMode mode;
  mode.omega1 = pinned::RayleighFirstFrequency(tube, tube.steel_mass());
  mode.modal_mass = pinned::RayleighModalMass(tube, tube.steel_mass());
  mode.loss_factor = 2.0 * kStructuralDamping;
  mode.viscous = 2.0 * kStructuralDamping * pinned::BodyModalDampingShare(tube, kBodies, kBodyBendingModes) * mode.omega1;
  return mode;
}

TEST(ImbalanceResponse, PeakMatchesTheClosedFormSingleModeResponse) {
  const SingleMode mode = CollarSingleMode();
  // The peak of the closed form, on a grid 1e-6 ω₁ fine.
  double peak_speed = 0.0, peak_radius = 0.0;
  for (int i = -50000; i <= 50000; ++i) {
    const double speed = mode.omega1 * (1.0 + 1e-6 * i);
    if (mode.Radius(speed) > peak_radius) peak_radius = mode.Radius(speed), peak_speed = speed;
  }
  const double zeta = kStructuralDamping + 0.5 * mode.viscous / mode.omega1;
  // The closed form's own checks: the peak sits within 2ζ² of ω₁ and is about m e/(2ζ M₁).
  EXPECT_NEAR(peak_speed / mode.omega1, 1.0, 2.0 * zeta * zeta);
  EXPECT_NEAR(peak_radius * 2.0 * zeta * mode.modal_mass / kImbalance, 1.0, 2e-3);

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
  const double peak_reference_rpm = peak_speed * 30.0 / kPi;
  const double peak_rpm = rpm[peak].get<double>();
  const double amplitude = displacement[peak].get<double>() * kMetresPerInch;
  std::printf("imbalance: peak %.3f rpm (closed form %.3f rpm, %+.3f %%), amplitude %.5g m (%.5g m, %+.3f %%); "
              "f1 %.5f Hz, zeta %.5f (s = %.5f), s of the peak %.3f ft\n",
              peak_rpm, peak_reference_rpm, 100.0 * RelativeError(peak_rpm, peak_reference_rpm), amplitude,
              peak_radius, 100.0 * RelativeError(amplitude, peak_radius), mode.omega1 / (2.0 * kPi), zeta,
              0.5 * mode.viscous / (kStructuralDamping * mode.omega1), vibration["s_max_displacement"][peak].get<double>());
  EXPECT_LT(std::abs(RelativeError(peak_rpm, peak_reference_rpm)), 5e-3);
  EXPECT_LT(std::abs(RelativeError(amplitude, peak_radius)), 0.02);
  EXPECT_NEAR(vibration["s_max_displacement"][peak].get<double>(), 15.0, 0.5);  // mid-span, ft
  // The one critical RPM is that peak.
  ASSERT_EQ(vibration["critical_rpm"].size(), 1u);
  EXPECT_NEAR(vibration["critical_rpm"][0].get<double>(), peak_rpm, 1e-9);
  // Off the peak (±5 % in speed) the closed form still holds within 2 %, at the sweep's own speeds.
  for (const double r : {0.95, 1.05}) {
    const std::size_t i = static_cast<std::size_t>(std::lround((r * mode.omega1 * 30.0 / kPi - 280.0) / 0.05));
    const double speed = rpm[i].get<double>() * kPi / 30.0;
    const double reference = mode.Radius(speed);
    const double value = displacement[i].get<double>() * kMetresPerInch;
    std::printf("  at %.2f rpm: %.5g m (closed form %.5g m, %+.3f %%)\n", rpm[i].get<double>(), value, reference,
                100.0 * RelativeError(value, reference));
    EXPECT_LT(std::abs(RelativeError(value, reference)), 0.02) << r;
  }
}

TEST(ImbalanceResponse, FirstFrequencyMatchesTheRayleighAndTimoshenkoBeams) {
  // The Euler–Bernoulli model with rotary inertia against the Rayleigh beam; the same collar with
  // `model.beam: timoshenko` against the Timoshenko beam (κ = 0.702, Cowper). The corrections are
  // small here (slenderness L/r_g = 170): rotary inertia −0.017 %, shear another −0.063 %; the
  // tolerance, 0.015 %, is below either correction, so each is seen (the discretization is −0.006 %).
  const pinned::Tube tube = Collar();
  const double euler_bernoulli = pinned::EulerBernoulliFirstFrequency(tube, tube.steel_mass()) / (2.0 * kPi);
  const double rayleigh = pinned::RayleighFirstFrequency(tube, tube.steel_mass()) / (2.0 * kPi);
  const double timoshenko = pinned::TimoshenkoFirstFrequency(tube) / (2.0 * kPi);
  EXPECT_NEAR(pinned::CowperShearCoefficient(tube), 0.702, 5e-4);
  const char* cases[2] = {"imbalance-response/collar.yaml", "imbalance-response/collar-timoshenko.yaml"};
  const double references[2] = {rayleigh, timoshenko};
  for (int c = 0; c < 2; ++c) {
    const auto modes = RunCase("modes", cases[c]);
    ASSERT_TRUE(modes.contains("modes")) << cases[c];
    const double f = modes["modes"][0]["frequency_hz"].get<double>();
    std::printf("%s: f1 = %.5f Hz against %.5f Hz (%+.4f %%; Euler-Bernoulli %.5f Hz, %+.4f %%)\n", cases[c], f,
                references[c], 100.0 * RelativeError(f, references[c]), euler_bernoulli,
                100.0 * RelativeError(f, euler_bernoulli));
    EXPECT_LT(std::abs(RelativeError(f, references[c])), 1.5e-4) << cases[c];
  }
}

}  // namespace imbalance_response_test
}  // namespace drillflex::validation
