// V8 fluid in the transient (validation.md): the drilling fluid's lateral mass and damping in the
// time domain (model/fluid_inertia.hpp), on the lateral free vibration of a hollow cantilever
// (v8-fluid/*.yaml: 200 in of 3 in x 1.5 in pipe clamped in a 5 in vertical hole, no gravity, no
// structural or numerical damping), released from its static tip deflection. The frequency is the
// mean over the tip's downward zero crossings of transient.csv.
//  * Air: f₁ = (β₁L)²/(2πL²) sqrt(EI/m_s) (Euler–Bernoulli), within 0.5 %.
//  * Inviscid mud: a uniform pipe's mode keeps its shape when the lateral mass per length grows
//    from m_s to m_s + m_i + C_m ρ_f π a² (bore fluid ρ_f A_i; the annulus's potential-flow added mass
//    with C_m = (b² + a²)/(b² − a²), a = OD/2, b = D_h/2; Chen, Wambsganss & Jendrzejczyk 1976), so
//    f_mud/f_air = sqrt(m_s/(m_s + m_i + C_m ρ_f π a²)) exactly: the transient's ratio within 1 %,
//    and f_mud within 1 % of the linear modes analysis of the same case. The energy is conserved
//    (no damping): the fluid's kinetic energy is in the kinetic energy.
//  * Viscous mud (0.05 Pa·s): C_m(ω), C_v(ω) at the lowest lateral frequency (the transient's default,
//    TransientFluidFrequency); the frequency within 1 % of the modes analysis's and of the same ratio
//    with C_m(ω); the decay's damping ratio ζ = ln(A_1/A_n)/(2π(n − 1)) from the tip's peaks within
//    5 % of the modes analysis's and of ζ = C_v ρ_f π a² / (2 m_total) (a uniform dashpot on a
//    uniform mass: every mode decays at c/(2m)).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "chen_annulus.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace fluid_transient_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLength = 5.08, kOd = 0.0762, kId = 0.0381, kHole = 0.127, kE = 2.1e11, kSteel = 7800.0;
constexpr double kMud = 1500.0, kViscosity = 0.05;

double SteelPerLength() { return kSteel * kPi / 4.0 * (kOd * kOd - kId * kId); }
double BorePerLength() { return kMud * kPi / 4.0 * kId * kId; }

double AirFrequency() {
  const double inertia = kPi / 64.0 * (std::pow(kOd, 4) - std::pow(kId, 4));
  const double beta_l = 1.8751041;
  return beta_l * beta_l / (2.0 * kPi * kLength * kLength) * std::sqrt(kE * inertia / SteelPerLength());
}

struct FreeDecay {
  double frequency = 0.0;      // Hz, over the downward zero crossings
  double damping_ratio = 0.0;  // from the first and last peaks between crossings
  double energy_change = 0.0;  // max |E − E(0)| / max kinetic
};

// `run_name`: a results directory of its own (RunCase), when another test runs the same case.
FreeDecay RunFreeDecay(const std::string& name, const std::string& run_name = "") {
  const auto results = RunCase("transient", "v8-fluid/" + name + ".yaml", run_name);
  EXPECT_TRUE(results.contains("transient"));
  const CsvColumns csv = ReadCsv(ResultsDirectory("v8-fluid/" + name + ".yaml") + (run_name.empty() ? "" : "-" + run_name) +
                                 "/transient.csv");
  const auto& time = csv["time"];
  const auto& tip = csv["probe1_lateral_z"];
  std::vector<double> crossings;
  for (std::size_t i = 1; i < tip.size(); ++i) {
    if (tip[i - 1] > 0.0 && tip[i] <= 0.0) {
      crossings.push_back(time[i - 1] + (time[i] - time[i - 1]) * tip[i - 1] / (tip[i - 1] - tip[i]));
    }
  }
  FreeDecay decay;
  if (crossings.size() < 5) {
    ADD_FAILURE() << name << ": fewer than 5 swings";
    return decay;
  }
  decay.frequency = static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
  // The largest upward deflection between consecutive downward crossings (one a period).
  std::vector<double> peaks;
  for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
    double peak = 0.0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      if (time[i] > crossings[k] && time[i] < crossings[k + 1]) peak = std::max(peak, tip[i]);
    }
    peaks.push_back(peak);
  }
  decay.damping_ratio = std::log(peaks.front() / peaks.back()) / (2.0 * kPi * static_cast<double>(peaks.size() - 1));
  const auto& kinetic = csv["kinetic_energy"];
  const auto& total = csv["total_energy"];
  double largest_kinetic = 0.0;
  for (std::size_t i = 0; i < total.size(); ++i) {
    largest_kinetic = std::max(largest_kinetic, kinetic[i]);
    decay.energy_change = std::max(decay.energy_change, std::abs(total[i] - total.front()));
  }
  decay.energy_change /= largest_kinetic;
  return decay;
}

// The first lateral mode of the case's `modes` analysis: frequency (Hz) and damping ratio.
std::pair<double, double> FirstLateralMode(const std::string& name) {
  const auto results = RunCase("modes", "v8-fluid/" + name + ".yaml", "modes");
  for (const auto& mode : results["modes"]) {
    if (mode["kind"] == "lateral" && !mode["near_zero"].get<bool>()) {
      return {mode["frequency_hz"].get<double>(), mode["damping_ratio"].get<double>()};
    }
  }
  ADD_FAILURE() << name << ": no lateral mode";
  return {0.0, 0.0};
}

TEST(V8FluidTransient, AirFrequencyIsEulerBernoullis) {
  const FreeDecay air = RunFreeDecay("air");
  std::printf("V8 fluid, air: %.5f Hz against %.5f Hz (%+.3f %%), energy change %.2e\n", air.frequency, AirFrequency(),
              100.0 * RelativeError(air.frequency, AirFrequency()), air.energy_change);
  EXPECT_LT(std::abs(RelativeError(air.frequency, AirFrequency())), 5e-3);
  EXPECT_LT(air.energy_change, 1e-4);
}

TEST(V8FluidTransient, InviscidMudLowersTheFrequencyByTheMassRatio) {
  const FreeDecay mud = RunFreeDecay("mud-inviscid");
  const double a = 0.5 * kOd, b = 0.5 * kHole;
  const double added_mass = (b * b + a * a) / (b * b - a * a) * kMud * kPi * a * a;  // C_m ρ π a², potential flow
  const double ratio = std::sqrt(SteelPerLength() / (SteelPerLength() + BorePerLength() + added_mass));
  const double expected = AirFrequency() * ratio;
  const double measured_ratio = mud.frequency / RunFreeDecay("air", "ratio").frequency;
  const auto [modes_frequency, modes_damping] = FirstLateralMode("mud-inviscid");
  std::printf("V8 fluid, inviscid mud: %.5f Hz; f_mud/f_air %.5f against sqrt(m_s/m_total) %.5f (%+.3f %%); "
              "against %.5f Hz analytic (%+.3f %%) and %.5f Hz of the modes analysis (%+.3f %%); energy change %.2e; "
              "masses per length steel %.3f, bore %.3f, annulus %.3f kg/m\n",
              mud.frequency, measured_ratio, ratio, 100.0 * RelativeError(measured_ratio, ratio), expected,
              100.0 * RelativeError(mud.frequency, expected), modes_frequency,
              100.0 * RelativeError(mud.frequency, modes_frequency), mud.energy_change, SteelPerLength(), BorePerLength(),
              added_mass);
  EXPECT_LT(std::abs(RelativeError(measured_ratio, ratio)), 1e-2);
  EXPECT_LT(std::abs(RelativeError(mud.frequency, expected)), 1e-2);
  EXPECT_LT(std::abs(RelativeError(mud.frequency, modes_frequency)), 1e-2);
  EXPECT_LT(modes_damping, 1e-6);  // none but round-off
  // No damping anywhere: the fluid's kinetic energy is conserved with the steel's.
  EXPECT_LT(mud.energy_change, 1e-4);
  EXPECT_LT(mud.damping_ratio, 1e-3);
}

TEST(V8FluidTransient, ViscousMudDampsAtTheAnnulusRateAndRingsAtTheModesFrequency) {
  const FreeDecay mud = RunFreeDecay("mud-viscous");
  const auto [modes_frequency, modes_damping] = FirstLateralMode("mud-viscous");
  // C_m(ω), C_v(ω) of Chen, Wambsganss & Jendrzejczyk (1976), evaluated by the test's own series
  // (chen_annulus.hpp, not fe/annulus_fluid.hpp), at the wet frequency found as the fixed point
  // ω = ω_air sqrt(m_s / m(ω)), m(ω) = m_s + m_bore + C_m(ω) ρ π a² (as V5 finds it).
  const double a = 0.5 * kOd, b = 0.5 * kHole;
  struct Annulus {
    double added_mass = 0.0, damping = 0.0;  // C_m, C_v
  } c;
  double omega = 2.0 * kPi * AirFrequency(), total = SteelPerLength();
  for (int i = 0; i < 50; ++i) {
    const chen::Complex h = chen::ForceRatio(b / a, omega * a * a / (kViscosity / kMud));
    c = {h.real(), -h.imag()};
    total = SteelPerLength() + BorePerLength() + c.added_mass * kMud * kPi * a * a;
    omega = 2.0 * kPi * AirFrequency() * std::sqrt(SteelPerLength() / total);
  }
  const double expected = omega / (2.0 * kPi);
  const double zeta = c.damping * kMud * kPi * a * a / (2.0 * total);
  std::printf("V8 fluid, viscous mud: %.5f Hz against %.5f Hz of the modes analysis (%+.3f %%) and %.5f Hz of the "
              "mass ratio at C_m(omega) = %.4f (%+.3f %%); damping ratio %.5f against %.5f of the modes analysis "
              "(%+.2f %%) and C_v rho pi a^2 / 2m = %.5f (C_v %.4f; %+.2f %%)\n",
              mud.frequency, modes_frequency, 100.0 * RelativeError(mud.frequency, modes_frequency), expected,
              c.added_mass, 100.0 * RelativeError(mud.frequency, expected), mud.damping_ratio, modes_damping,
              100.0 * RelativeError(mud.damping_ratio, modes_damping), zeta, c.damping,
              100.0 * RelativeError(mud.damping_ratio, zeta));
  EXPECT_LT(std::abs(RelativeError(mud.frequency, modes_frequency)), 1e-2);
  EXPECT_LT(std::abs(RelativeError(mud.frequency, expected)), 1e-2);
  EXPECT_LT(std::abs(RelativeError(mud.damping_ratio, modes_damping)), 5e-2);
  EXPECT_LT(std::abs(RelativeError(mud.damping_ratio, zeta)), 5e-2);
}

}  // namespace fluid_transient_test
}  // namespace drillflex::validation
