// Gyroscopic whirl of a spinning pinned-pinned shaft (validation/gyroscopic-shaft/shaft.yaml;
// validation.md "Gyroscopic modes and the Campbell diagram"): `drillflex modes` with
// `gyroscopic: true` and a Campbell sweep 0–60,000 rpm against the closed form of the Rayleigh beam
// (Euler–Bernoulli with rotary inertia) spinning about its axis.
//
// Reference (Genta, "Dynamics of Rotating Systems", Springer 2005, the Rayleigh beam with
// gyroscopic moments; Lalanne & Ferraris, "Rotordynamics Prediction in Engineering", 2nd ed., Wiley
// 1998, the same beam by Rayleigh–Ritz with a sine): in the stationary frame, with the complex lateral
// displacement r = y + i z, mass m = ρA, transverse and polar rotary inertia per length J_d = ρI,
// J_p = 2ρI,
//   EI r'''' + m r̈ − J_d r̈'' + i Ω J_p ṙ'' = 0.
// Pinned ends: r = sin(kx) e^{iλt}, k = nπ/L, exactly (the operator is even in x), so
//   (m + J_d k²) λ² ∓ J_p Ω k² λ − EI k⁴ = 0,
//   λ_F,B = [±J_p Ω k²/2 + sqrt((J_p Ω k²/2)² + (m + J_d k²) EI k⁴)] / (m + J_d k²),
// forward whirl (+, turning with the spin) stiffened, backward softened. At Ω = 0 both are the
// Rayleigh beam's k² sqrt(EI/(m + J_d k²)). The forward branch meets 1× (λ = Ω) at
// Ω² = EI k⁴/(m − J_d k²) (the gyroscopic moment cancels the rotary inertia and more), the backward
// one at Ω² = EI k⁴/(m + 3 J_d k²).
//
// Tolerances: 0.5 % on each frequency (the modal validations' tolerance, V5 and V6; the model's
// error here is that of its beam discretization and stiff couplings: measured 0.005 %) and 0.5 % on
// the split λ_F − λ_B at the top speed, the gyroscopic term alone (6.8 % of the frequency there, so
// a G wrong by 1 % moves the frequencies by only 0.03 % but the split by 1 %; a lumped polar inertia
// per node of 40 elements errs by about (kh)²/12 = 5e-4; measured 0.002 %); a sign error in G
// swaps the branches and fails the whirl labels. 0.5 % on the 1× crossings (linear interpolation on
// the 6000 rpm grid of a nearly straight branch; measured 0.005 %).
#include <cmath>
#include <cstdio>

#include "core/types.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace gyroscopic_shaft_test {

constexpr double kE = 2.1e11, kRho = 7850.0, kOd = 0.1, kId = 0.05, kLength = 1.0;
const double kMass = kRho * kPi * (kOd * kOd - kId * kId) / 4.0;                              // kg/m
const double kSecondMoment = kPi * (std::pow(kOd, 4) - std::pow(kId, 4)) / 64.0;               // m⁴
const double kTransverse = kRho * kSecondMoment, kPolar = 2.0 * kRho * kSecondMoment;          // kg·m
constexpr double kRpm = kPi / 30.0;

double WaveNumber(int n) { return n * kPi / kLength; }

// λ_F (forward) or λ_B of mode n at the spin Ω, rad/s.
double WhirlFrequency(int n, double spin, bool forward) {
  const double k2 = WaveNumber(n) * WaveNumber(n);
  const double inertia = kMass + kTransverse * k2;
  const double half = 0.5 * kPolar * spin * k2;
  const double root = std::sqrt(half * half + inertia * kE * kSecondMoment * k2 * k2);
  return ((forward ? half : -half) + root) / inertia;
}

double SynchronousSpeed(int n, bool forward) {
  const double k2 = WaveNumber(n) * WaveNumber(n);
  return std::sqrt(kE * kSecondMoment * k2 * k2 / (kMass + (forward ? -1.0 : 3.0) * kTransverse * k2));
}

double Hz(double omega) { return omega / (2.0 * kPi); }

TEST(GyroscopicShaft, ClosedFormIsConsistent) {
  // The two roots solve the quadratic, and the 1× speeds are where a root equals the spin.
  for (const bool forward : {true, false}) {
    const double spin = 4000.0;
    const double lambda = WhirlFrequency(1, spin, forward);
    const double k2 = WaveNumber(1) * WaveNumber(1);
    const double residual = (kMass + kTransverse * k2) * lambda * lambda - (forward ? 1.0 : -1.0) * kPolar * spin * k2 * lambda -
                            kE * kSecondMoment * k2 * k2;
    EXPECT_NEAR(residual / (kE * kSecondMoment * k2 * k2), 0.0, 1e-12);
    const double synchronous = SynchronousSpeed(1, forward);
    EXPECT_NEAR(WhirlFrequency(1, synchronous, forward) / synchronous, 1.0, 1e-12);
  }
}

TEST(GyroscopicShaft, CampbellBranchesMatchTheRayleighBeam) {
  const nlohmann::json results = RunCase("modes", "gyroscopic-shaft/shaft.yaml");
  ASSERT_TRUE(results.contains("campbell"));
  const auto& campbell = results["campbell"];
  ASSERT_EQ(campbell["rpm"].size(), 11u);
  double split_error = 0.0;
  for (std::size_t i = 0; i < campbell["rpm"].size(); ++i) {
    const double rpm = campbell["rpm"][i].get<double>();
    const auto& modes = campbell["modes"][i];
    ASSERT_EQ(modes.size(), 4u) << rpm << " rpm";
    // Sorted by frequency: B1 < F1 < B2 < F2 (the first pair stays below the second up to 60,000 rpm).
    for (int m = 0; m < 4; ++m) {
      const int n = 1 + m / 2;
      const bool forward = m % 2 == 1;
      const double reference = Hz(WhirlFrequency(n, rpm * kRpm, forward));
      const double computed = modes[m]["frequency_hz"].get<double>();
      std::printf("%6.0f rpm  mode %d (%s %d): %.4f Hz, closed form %.4f Hz, %+.4f %% (whirl %s, index %+.3f)\n", rpm,
                  m + 1, forward ? "F" : "B", n, computed, reference, 100.0 * RelativeError(computed, reference),
                  modes[m]["whirl"].get<std::string>().c_str(), modes[m]["whirl_index"].get<double>());
      EXPECT_LT(std::abs(RelativeError(computed, reference)), 5e-3) << rpm << " rpm, mode " << m + 1;
      if (rpm > 0.0) {
        EXPECT_EQ(modes[m]["whirl"], forward ? "forward" : "backward") << rpm << " rpm, mode " << m + 1;
      }
    }
    if (i + 1 == campbell["rpm"].size()) {
      const double computed = modes[1]["frequency_hz"].get<double>() - modes[0]["frequency_hz"].get<double>();
      const double reference = Hz(WhirlFrequency(1, rpm * kRpm, true) - WhirlFrequency(1, rpm * kRpm, false));
      split_error = RelativeError(computed, reference);
      std::printf("split of the first pair at %.0f rpm: %.4f Hz, closed form %.4f Hz, %+.3f %%\n", rpm, computed, reference,
                  100.0 * split_error);
    }
  }
  EXPECT_LT(std::abs(split_error), 5e-3);
}

TEST(GyroscopicShaft, ModesAtTheOperatingSpeedAndTheSynchronousSpeeds) {
  const nlohmann::json results = RunCase("modes", "gyroscopic-shaft/shaft.yaml", "whirl");
  ASSERT_TRUE(results.contains("gyroscopic"));
  EXPECT_NEAR(results["gyroscopic"]["rpm"].get<double>(), 30000.0, 1e-9);
  const auto& modes = results["modes"];
  ASSERT_EQ(modes.size(), 4u);
  EXPECT_EQ(modes[0]["whirl"], "backward");
  EXPECT_EQ(modes[1]["whirl"], "forward");
  EXPECT_LT(std::abs(RelativeError(modes[1]["frequency_hz"].get<double>(), Hz(WhirlFrequency(1, 30000.0 * kRpm, true)))), 5e-3);
  EXPECT_GT(modes[1]["whirl_index"].get<double>(), 0.9);  // an axisymmetric shaft whirls in circles
  EXPECT_LT(modes[0]["whirl_index"].get<double>(), -0.9);
  // The 1× crossings of the first pair: branch 1 (backward) and branch 2 (forward).
  const auto& crossings = results["campbell"]["synchronous"];
  for (const int branch : {1, 2}) {
    const bool forward = branch == 2;
    const double reference = SynchronousSpeed(1, forward) / kRpm;
    bool found = false;
    for (const auto& crossing : crossings) {
      if (crossing["branch"] != branch) continue;
      found = true;
      const double rpm = crossing["rpm"].get<double>();
      std::printf("branch %d (%s) crosses 1x at %.1f rpm, closed form %.1f rpm, %+.3f %%\n", branch,
                  crossing["whirl"].get<std::string>().c_str(), rpm, reference, 100.0 * RelativeError(rpm, reference));
      EXPECT_LT(std::abs(RelativeError(rpm, reference)), 5e-3);
      EXPECT_EQ(crossing["whirl"], forward ? "forward" : "backward");
    }
    EXPECT_TRUE(found) << "branch " << branch;
  }
}

}  // namespace gyroscopic_shaft_test
}  // namespace drillflex::validation
