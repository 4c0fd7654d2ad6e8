// V5 of validation.md, fluid in the vibration analysis (validation/v5-fluid-frequency/): an
// 8 in x 2.8125 in collar (E = 207 GPa, ρ = 7850 kg/m³), 30 ft, pinned-pinned, concentric in a
// 12.25 in hole with 10 ppg mud (gravity off: no axial load, no wall contact).
// References (validation.md V5, computed): first lateral frequency 5.195 Hz dry, 5.140 Hz with the
// internal mud only, 4.307 Hz with the confined inviscid added mass; tolerance 0.5 %.
// They follow from the pinned-pinned Euler–Bernoulli beam f₁ = (π/2L²) sqrt(EI/m) with the lateral
// mass per length m = ρ_s A (dry), + ρ_f A_i (internal mud), + C_m ρ_f π OD²/4 with
// C_m = (D_h² + OD²)/(D_h² − OD²) = 2.4873 (method.md §7), checked here too.
// The viscous case (20 cP) against the closed-form beam too, nothing of it from drillflex's output:
// the Rayleigh beam (validation/pinned_beam.hpp: the model carries the sections' rotary inertia)
// with the lateral mass m = ρ_s A + ρ_f A_i + C_m(ω) ρ_f π a², C_m and C_v of Chen, Wambsganss &
// Jendrzejczyk (1976) evaluated in the test (validation/chen_annulus.hpp: the exact 2-D solution with
// its own Bessel expansions, not fe/annulus_fluid), at the frequency it gives (a fixed point):
// ω² = EI k⁴/(m(ω) + ρ_s I k²), within 0.5 %. Its damping ratio, as the model defines it (a loss
// factor 2ζ_s on K, the bodies' modal damping, the fluid's c = C_v ρ π a² ω per length):
// ζ = ζ_s + ζ_s s ω_dry M_dry/(ω M) + C_v ρ π a² (L/2)/(2M), M = (L/2)(m + ρ_s I k²), s the bodies'
// modal damping share (pinned::BodyModalDampingShare), within 5 %.
#include <cmath>
#include <cstdio>

#include "chen_annulus.hpp"
#include "field_units.hpp"
#include "pinned_beam.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace fluid_frequency_test {

constexpr double kE = 207e9, kSteel = 7850.0;
constexpr double kOd = 8.0 * kMetresPerInch, kId = 2.8125 * kMetresPerInch, kHole = 12.25 * kMetresPerInch;
constexpr double kLength = 30.0 * kMetresPerFoot;
const double kMud = 10.0 * kKgPerCubicMetrePerPpg;
const double kSteelMass = kSteel * kPi * (kOd * kOd - kId * kId) / 4.0;  // kg/m
const double kInternalMass = kMud * kPi * kId * kId / 4.0;
const double kOuterArea = kPi * kOd * kOd / 4.0;

double PinnedPinnedFrequency(double mass_per_length) {
  const double inertia = kPi * (std::pow(kOd, 4) - std::pow(kId, 4)) / 64.0;
  return kPi / (2.0 * kLength * kLength) * std::sqrt(kE * inertia / mass_per_length);
}

double FirstLateral(const nlohmann::json& results, double* damping_ratio = nullptr) {
  if (!results.contains("modes") || results["modes"].empty()) {
    ADD_FAILURE() << "no modes";
    return 0.0;
  }
  const auto& mode = results["modes"][0];
  EXPECT_EQ(mode["kind"], "lateral");
  if (damping_ratio) *damping_ratio = mode["damping_ratio"].get<double>();
  return mode["frequency_hz"].get<double>();
}

TEST(V5FluidFrequency, BeamFormulaGivesTheReferences) {
  const double cm = (kHole * kHole + kOd * kOd) / (kHole * kHole - kOd * kOd);
  EXPECT_NEAR(cm, 2.4873, 1e-4);
  EXPECT_NEAR(PinnedPinnedFrequency(kSteelMass), 5.195, 5e-4);
  EXPECT_NEAR(PinnedPinnedFrequency(kSteelMass + kInternalMass), 5.140, 5e-4);
  EXPECT_NEAR(PinnedPinnedFrequency(kSteelMass + kInternalMass + cm * kMud * kOuterArea), 4.307, 5e-4);
}

TEST(V5FluidFrequency, DryInternalAndConfinedWithinHalfPercent) {
  const double references[3] = {5.195, 5.140, 4.307};
  const char* cases[3] = {"dry", "internal", "confined"};
  for (int i = 0; i < 3; ++i) {
    double zeta = 0.0;
    const double f = FirstLateral(RunCase("modes", std::string("v5-fluid-frequency/") + cases[i] + ".yaml"), &zeta);
    std::printf("V5 %-9s f1 = %.5f Hz (reference %.3f Hz, %+.3f %%), damping ratio %.5f\n", cases[i], f,
                references[i], 100.0 * RelativeError(f, references[i]), zeta);
    EXPECT_LT(std::abs(RelativeError(f, references[i])), 5e-3) << cases[i];
  }
}

TEST(V5FluidFrequency, TestBesselAndChenEvaluationHold) {
  // The expansions against mpmath 1.3 (30 digits) at β = sqrt(1000 i) and 20 + 5i: e^{−z} I_n, e^{z} K_n.
  struct Row {
    chen::Complex z, i0, i1, k0, k1;
  };
  const Row rows[2] = {
      {std::sqrt(chen::Complex(0.0, 1000.0)), {0.065648110162887669, -0.027412491728326186},
       {0.065224322759760097, -0.026363735953957436}, {0.2055662966733973, -0.084490637103462832},
       {0.20692975327529, -0.087708228912660177}},
      {{20.0, 5.0}, {0.087715647942440687, -0.010935917478451007}, {0.085693960491881713, -0.010146597709193775},
       {0.27243987585041779, -0.033150107584077799}, {0.27859154981043572, -0.035489105155633059}},
  };
  for (const Row& row : rows) {
    const chen::ScaledBessel b = chen::ComputeScaledBessel(row.z);
    EXPECT_LT(std::abs(b.i0 / row.i0 - 1.0), 1e-13);
    EXPECT_LT(std::abs(b.i1 / row.i1 - 1.0), 1e-13);
    EXPECT_LT(std::abs(b.k0 / row.k0 - 1.0), 1e-13);
    EXPECT_LT(std::abs(b.k1 / row.k1 - 1.0), 1e-13);
    // The ascending series (A&S 9.6.10) and the Wronskian I₀K₁ + I₁K₀ = 1/z (A&S 9.6.15).
    EXPECT_LT(std::abs(std::exp(-row.z) * chen::PowerSeriesBesselI(1, row.z) / b.i1 - 1.0), 1e-11);
    EXPECT_LT(std::abs((b.i0 * b.k1 + b.i1 * b.k0) * row.z - 1.0), 1e-14);
  }
  // Chen's H at V5's α = 1.5 against the 80-digit solution of validation.md V5 (C_m/C_v = 2.969/0.444 at
  // S = 1e3, 2.719/0.1252 at 1e4; mpmath, tests/fe/annulus_fluid_test.cpp), and its large-S limit: the
  // inviscid C_m plus the Stokes layers' C_v ≈ C_m − (α²+1)/(α²−1) ≈ 2√2 α(1 + α³)/((α² − 1)² √S).
  const chen::Complex at_1e3 = chen::ForceRatio(1.5, 1e3), at_1e4 = chen::ForceRatio(1.5, 1e4);
  EXPECT_NEAR(at_1e3.real(), 2.969028545, 1e-8);
  EXPECT_NEAR(-at_1e3.imag(), 0.443900287693, 1e-8);
  EXPECT_NEAR(at_1e4.real(), 2.71860856095, 1e-8);
  EXPECT_NEAR(-at_1e4.imag(), 0.125248842124, 1e-8);
  const double alpha = kHole / kOd, stokes = 1e10;
  const chen::Complex large = chen::ForceRatio(alpha, stokes);
  const double layer = 2.0 * std::sqrt(2.0) * alpha * (1.0 + std::pow(alpha, 3)) /
                       (std::pow(alpha * alpha - 1.0, 2) * std::sqrt(stokes));
  EXPECT_NEAR(large.real(), (alpha * alpha + 1.0) / (alpha * alpha - 1.0) + layer, 1e-3 * layer);
  EXPECT_NEAR(-large.imag(), layer, 1e-3 * layer);
}

TEST(V5FluidFrequency, ViscousAddedMassAndDampingFollowChenWambsganss) {
  double zeta = 0.0;
  const double f = FirstLateral(RunCase("modes", "v5-fluid-frequency/viscous.yaml"), &zeta);
  const pinned::Tube tube{kLength, kOd, kId, kE, kSteel, 0.3};
  const double nu = 20e-3 / kMud;  // 20 cP
  // The wet frequency: ω = ω_R(m(ω)) by fixed point (C_m falls slowly with ω; a few steps converge).
  double omega = pinned::RayleighFirstFrequency(tube, kSteelMass), added_mass = 0.0, damping = 0.0;
  for (int i = 0; i < 50; ++i) {
    const chen::Complex h = chen::ForceRatio(kHole / kOd, omega * kOd * kOd / 4.0 / nu);
    added_mass = h.real(), damping = -h.imag();
    omega = pinned::RayleighFirstFrequency(tube, kSteelMass + kInternalMass + added_mass * kMud * kOuterArea);
  }
  const double mass = kSteelMass + kInternalMass + added_mass * kMud * kOuterArea;
  const double reference = omega / (2.0 * kPi);
  // The damping ratio as the model defines it (header).
  const double structural = 0.01;  // model.structural_damping default
  const double dry_omega = pinned::RayleighFirstFrequency(tube, kSteelMass);
  const double dry_modal_mass = pinned::RayleighModalMass(tube, kSteelMass);
  const double modal_mass = pinned::RayleighModalMass(tube, mass);
  const double share = pinned::BodyModalDampingShare(tube, 4, 4);  // 4 bodies of 7.5 ft
  const double zeta_reference = structural + structural * share * dry_omega * dry_modal_mass / (omega * modal_mass) +
                                damping * kMud * kOuterArea * 0.5 * kLength / (2.0 * modal_mass);
  std::printf("V5 viscous  f1 = %.5f Hz (closed form with Chen's C_m(w) = %.5f: %.5f Hz, %+.3f %%); damping ratio "
              "%.5f (closed form %.5f, %+.2f %%; C_v = %.5f, S = %.4g)\n",
              f, added_mass, reference, 100.0 * RelativeError(f, reference), zeta, zeta_reference,
              100.0 * RelativeError(zeta, zeta_reference), damping, omega * kOd * kOd / 4.0 / nu);
  EXPECT_LT(std::abs(RelativeError(f, reference)), 5e-3);
  EXPECT_LT(f, 4.307);  // a viscous fluid adds more mass than the inviscid limit
  EXPECT_LT(std::abs(RelativeError(zeta, zeta_reference)), 0.05);
}

}  // namespace fluid_frequency_test
}  // namespace drillflex::validation
