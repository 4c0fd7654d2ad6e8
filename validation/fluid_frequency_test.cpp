// V5 of validation.md, fluid in the vibration analysis (validation/v5-fluid-frequency/): an
// 8 in x 2.8125 in collar (E = 207 GPa, ρ = 7850 kg/m³), 30 ft, pinned-pinned, concentric in a
// 12.25 in hole with 10 ppg mud (gravity off: no axial load, no wall contact).
// References (validation.md V5, computed): first lateral frequency 5.195 Hz dry, 5.140 Hz with the
// internal mud only, 4.307 Hz with the confined inviscid added mass; tolerance 0.5 %.
// They follow from the pinned-pinned Euler–Bernoulli beam f₁ = (π/2L²) sqrt(EI/m) with the lateral
// mass per length m = ρ_s A (dry), + ρ_f A_i (internal mud), + C_m ρ_f π OD²/4 with
// C_m = (D_h² + OD²)/(D_h² − OD²) = 2.4873 (method.md §7), checked here too.
// The viscous case (20 cP) has no published figure: it is checked against the same beam with the
// Chen–Wambsganss C_m(ω), C_v(ω) of fe/annulus_fluid (a separately validated unit) at the
// computed frequency: f = f_dry sqrt(m_s / (m_s + m_i + C_m(ω) ρ π a²)) (0.5 %), and its damping
// ratio against ζ = ζ_s + (ζ_dry − ζ_s) m_s ω_dry/(m ω) + C_v ρ π a²/(2 m): the structural loss
// factor's ζ_s = 0.01 (the case's default), the dry mode's viscous part φᵀDφ/(2ω) carried over at
// the wet frequency and mass, plus the fluid's c/(2 m ω), c = C_v ρ π a² ω; 5 %.
#include <cmath>
#include <cstdio>

#include "fe/annulus_fluid.hpp"
#include "field_units.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace {

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

TEST(V5FluidFrequency, ViscousAddedMassAndDampingFollowChenWambsganss) {
  double dry_zeta = 0.0, zeta = 0.0;
  const double dry = FirstLateral(RunCase("modes", "v5-fluid-frequency/dry.yaml"), &dry_zeta);
  const double f = FirstLateral(RunCase("modes", "v5-fluid-frequency/viscous.yaml"), &zeta);
  const double omega = 2.0 * kPi * f;
  const double nu = 20e-3 / kMud;  // 20 cP
  const fe::AnnulusFluidCoefficients c = fe::CalcAnnulusFluidCoefficients(kOd / 2.0, kHole / 2.0, omega, nu);
  const double mass = kSteelMass + kInternalMass + c.added_mass * kMud * kOuterArea;
  const double reference = dry * std::sqrt(kSteelMass / mass);
  const double structural = 0.01;  // model.structural_damping default
  const double zeta_reference = structural + (dry_zeta - structural) * kSteelMass * dry / (mass * f) +
                                c.damping * kMud * kOuterArea / (2.0 * mass);
  std::printf("V5 viscous  f1 = %.5f Hz (beam with C_m(ω) = %.5f: %.5f Hz, %+.3f %%); damping ratio %.5f "
              "(reference %.5f, C_v = %.5f, S = %.4g)\n",
              f, c.added_mass, reference, 100.0 * RelativeError(f, reference), zeta, zeta_reference, c.damping,
              fe::StokesNumber(kOd / 2.0, omega, nu));
  EXPECT_LT(std::abs(RelativeError(f, reference)), 5e-3);
  EXPECT_LT(f, 4.307);  // a viscous fluid adds more mass than the inviscid limit
  EXPECT_LT(std::abs(RelativeError(zeta, zeta_reference)), 0.05);
}

}  // namespace
}  // namespace drillflex::validation
