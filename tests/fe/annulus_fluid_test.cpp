#include "fe/annulus_fluid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "fe/section.hpp"

namespace drillflex::fe {
namespace annulus_fluid_test {

constexpr double kInch = 0.0254;  // m
constexpr double kFoot = 0.3048;  // m

double RelativeError(double value, double expected) {
  return std::abs(value - expected) / std::abs(expected);
}

TEST(AnnulusFluid, InviscidAddedMassCoefficient) {
  // (α² + 1)/(α² − 1): α = 1.5 → 3.25/1.25 = 2.6; α = 2 → 5/3; α → ∞ → 1.
  EXPECT_DOUBLE_EQ(InviscidAddedMassCoefficient(1.5), 2.6);
  EXPECT_DOUBLE_EQ(InviscidAddedMassCoefficient(2.0), 5.0 / 3.0);
  EXPECT_NEAR(InviscidAddedMassCoefficient(1e4), 1.0, 1e-7);
  EXPECT_THROW(InviscidAddedMassCoefficient(1.0), LogicError);
  EXPECT_THROW(InviscidAddedMassCoefficient(0.5), LogicError);
}

TEST(AnnulusFluid, ValidationV5ViscousCoefficients) {
  // validation.md V5 (issue 5 acceptance: within 1 %): α = 1.5, C_m/C_v = 2.969/0.444 at S = 1e3
  // and 2.719/0.1252 at S = 1e4.
  const std::complex<double> at_1e3 = ConfinedForceRatio(1.5, 1e3);
  const std::complex<double> at_1e4 = ConfinedForceRatio(1.5, 1e4);
  std::printf("V5 alpha = 1.5: S = 1e3: C_m = %.6f (%+.3f %%), C_v = %.6f (%+.3f %%)\n",
              at_1e3.real(), 100 * (at_1e3.real() / 2.969 - 1), -at_1e3.imag(),
              100 * (-at_1e3.imag() / 0.444 - 1));
  std::printf("V5 alpha = 1.5: S = 1e4: C_m = %.6f (%+.3f %%), C_v = %.6f (%+.3f %%)\n",
              at_1e4.real(), 100 * (at_1e4.real() / 2.719 - 1), -at_1e4.imag(),
              100 * (-at_1e4.imag() / 0.1252 - 1));
  EXPECT_LT(RelativeError(at_1e3.real(), 2.969), 0.01);
  EXPECT_LT(RelativeError(-at_1e3.imag(), 0.444), 0.01);
  EXPECT_LT(RelativeError(at_1e4.real(), 2.719), 0.01);
  EXPECT_LT(RelativeError(-at_1e4.imag(), 0.1252), 0.01);
}

TEST(AnnulusFluid, MatchesAHighPrecisionSolutionOverTheWholeRange) {
  // The same 4×4 problem solved with mpmath 1.3 at 80 digits (computed; the script solves
  // F(a) = aV, F′(a) = V, F(b) = F′(b) = 0 in the plain basis {r, 1/r, I₁(kr), K₁(kr)}).
  struct Row {
    double alpha, stokes, added_mass, damping;
  };
  const std::vector<Row> rows = {
      {1.5, 1e-2, 3.48503179432, 19184.9067219}, {1.5, 1.0, 3.4850251483, 191.850917305},
      {1.5, 10.0, 3.48436857909, 19.2033806141}, {1.5, 100.0, 3.42976153182, 2.08040586833},
      {1.5, 1e3, 2.969028545, 0.443900287693},   {1.5, 1e4, 2.71860856095, 0.125248842124},
      {1.5, 1e6, 2.61187921773, 0.0119423691186}, {1000.0, 100.0, 1.2831541541, 0.302494026788},
      {1000.0, 1e3, 1.08945559565, 0.0914317458455}, {3.0, 1e-3, 2.54192773797, 13395.2960738},
  };
  for (const Row& row : rows) {
    const std::complex<double> h = ConfinedForceRatio(row.alpha, row.stokes);
    EXPECT_LT(RelativeError(h.real(), row.added_mass), 1e-9)
        << "alpha " << row.alpha << ", S " << row.stokes;
    EXPECT_LT(RelativeError(-h.imag(), row.damping), 1e-9)
        << "alpha " << row.alpha << ", S " << row.stokes;
  }
  // The two bases agree where the solver switches between them (|β| α = 2, β = sqrt(iS)).
  for (const double alpha : {1.5, 3.0}) {
    const double switch_stokes = std::pow(2.0 / alpha, 2);
    const std::complex<double> below = ConfinedForceRatio(alpha, switch_stokes * (1 - 1e-12));
    const std::complex<double> above = ConfinedForceRatio(alpha, switch_stokes * (1 + 1e-12));
    EXPECT_LT(std::abs(below - above) / std::abs(above), 1e-11) << alpha;
  }
}

TEST(AnnulusFluid, TendsToTheInviscidLimitAsStokesNumberGrows) {
  // At large S the vorticity lives in Stokes layers of thickness sqrt(2ν/ω) on the rod and the
  // wall. Their dissipation, (1/2) ρ sqrt(ων/2) |u_slip|² per area (Landau & Lifshitz, Fluid
  // Mechanics, §24), with the potential-flow slip 2α²/(α²−1) V sin θ on the rod and
  // 2/(α²−1) V sin θ on the wall, gives (derived here)
  //   C_v ≈ 2 sqrt(2) α (1 + α³) / ((α² − 1)² sqrt(S)),
  // and the layers' displacement raises C_m above (α²+1)/(α²−1) by the same amount to first
  // order (α → ∞: 2 sqrt(2/S), Stokes 1851).
  for (const double alpha : {1.2, 1.5, 3.0}) {
    const double inviscid = InviscidAddedMassCoefficient(alpha);
    const double layer =
        2.0 * std::sqrt(2.0) * alpha * (1.0 + alpha * alpha * alpha) /
        std::pow(alpha * alpha - 1.0, 2);
    double last_gap = INFINITY;
    for (const double stokes : {1e4, 1e6, 1e8, 1e10, 1e12}) {
      const std::complex<double> h = ConfinedForceRatio(alpha, stokes);
      const double gap = h.real() - inviscid;
      EXPECT_GT(gap, 0.0) << alpha << " " << stokes;
      EXPECT_LT(gap, 0.2 * last_gap) << alpha << " " << stokes;
      last_gap = gap;
      if (stokes >= 1e8) {  // the next term is smaller by ~1/((α − 1) sqrt(S))
        const double tolerance = std::max(20.0 / std::sqrt(stokes), 1e-5);
        EXPECT_LT(RelativeError(gap * std::sqrt(stokes), layer), tolerance)
            << alpha << " " << stokes;
        EXPECT_LT(RelativeError(-h.imag() * std::sqrt(stokes), layer), tolerance)
            << alpha << " " << stokes;
      }
    }
    // Across the switch to the inviscid value the change is the O(S^{−1/2}) term, ~1e-6.
    const double below = ConfinedForceRatio(alpha, 0.99 * kInviscidStokesNumber).real();
    const double above = ConfinedForceRatio(alpha, 1.01 * kInviscidStokesNumber).real();
    EXPECT_NEAR(below, above, 1e-5 * inviscid);
    EXPECT_EQ(above, inviscid);
  }
}

TEST(AnnulusFluid, WideGapTendsToStokesIsolatedCylinder) {
  // α = 1e3: the wall is ~1e3 radii away; the potential part differs by O(1/α²) = 1e-6 and the
  // vorticity (depth a/sqrt(S)) never reaches it.
  for (const double stokes : {30.0, 100.0, 1e3, 1e4, 1e6}) {
    const std::complex<double> confined = ConfinedForceRatio(1e3, stokes);
    const std::complex<double> stokes_1851 = UnconfinedForceRatio(stokes);
    EXPECT_LT(RelativeError(confined.real(), stokes_1851.real()), 1e-5) << stokes;
    EXPECT_LT(RelativeError(-confined.imag(), -stokes_1851.imag()), 1e-4) << stokes;
  }
  // Stokes' own large-S form: C_m ≈ 1 + 2 sqrt(2/S), C_v ≈ 2 sqrt(2/S) (first order in S^{−1/2}).
  const std::complex<double> h = UnconfinedForceRatio(1e6);
  EXPECT_NEAR(h.real(), 1.0 + 2.0 * std::sqrt(2.0 / 1e6), 1e-5);
  EXPECT_NEAR(-h.imag(), 2.0 * std::sqrt(2.0 / 1e6), 1e-5);
}

TEST(AnnulusFluid, SlowOscillationGivesTheConfinedStokesDrag) {
  // S → 0: quasi-steady Stokes flow between concentric cylinders; the drag per length
  // c = 4πμ / (ln α − (α² − 1)/(α² + 1)) (the classical 2-D Stokes drag of a cylinder moving
  // inside a concentric one; the 80-digit solution above agrees with it to 1e-9 at S = 1e-2),
  // i.e. C_v S → 4/(ln α − (α²−1)/(α²+1)).
  for (const double alpha : {1.5, 3.0, 10.0}) {
    const double limit =
        4.0 / (std::log(alpha) - (alpha * alpha - 1.0) / (alpha * alpha + 1.0));
    const double stokes = 1e-4;
    const std::complex<double> h = ConfinedForceRatio(alpha, stokes);
    EXPECT_LT(RelativeError(-h.imag() * stokes, limit), 1e-3) << alpha;
    EXPECT_GT(h.real(), 0.0);
  }
}

TEST(AnnulusFluid, CoefficientsAndForcesPerLength) {
  const double a = 0.1, b = 0.15;  // α = 1.5
  const double nu = 1e-5;          // m²/s
  const double omega = 1e3 * nu / (a * a);  // S = 1e3
  EXPECT_NEAR(StokesNumber(a, omega, nu), 1e3, 1e-9);
  const AnnulusFluidCoefficients c = ComputeAnnulusFluidCoefficients(a, b, omega, nu);
  EXPECT_NEAR(c.added_mass, 2.969028545, 1e-8);
  EXPECT_NEAR(c.damping, 0.443900287693, 1e-8);
  const double rho = 1198.26;
  EXPECT_NEAR(AddedMassPerLength(c, rho, a), c.added_mass * rho * kPi * a * a, 1e-12);
  EXPECT_NEAR(DampingPerLength(c, rho, a, omega), c.damping * rho * kPi * a * a * omega, 1e-12);
  // Inviscid fluid: the potential-flow value at any frequency, no damping.
  const AnnulusFluidCoefficients inviscid = ComputeAnnulusFluidCoefficients(a, b, 30.0, 0.0);
  EXPECT_DOUBLE_EQ(inviscid.added_mass, 2.6);
  EXPECT_EQ(inviscid.damping, 0.0);
  EXPECT_DOUBLE_EQ(ComputeAnnulusFluidCoefficients(a, b, 0.0, 0.0).added_mass, 2.6);
  EXPECT_THROW(ComputeAnnulusFluidCoefficients(a, a, omega, nu), LogicError);
  EXPECT_THROW(ComputeAnnulusFluidCoefficients(a, b, -1.0, nu), LogicError);
  EXPECT_THROW(ComputeAnnulusFluidCoefficients(a, b, omega, -nu), LogicError);
  EXPECT_THROW(ComputeAnnulusFluidCoefficients(a, b, 0.0, nu), LogicError);
  EXPECT_THROW(ConfinedForceRatio(1.5, 0.0), LogicError);
}

TEST(AnnulusFluid, ValidationV5CollarFrequencies) {
  // validation.md V5: 8 in × 2.8125 in collar, E = 207 GPa, ρ_s = 7850 kg/m³, 30 ft
  // pinned–pinned, 12.25 in hole, 10 ppg mud (1198.26 kg/m³). Euler–Bernoulli:
  // f₁ = (π/L)² sqrt(EI/m)/(2π) with m dry, + internal mud, + confined inviscid added mass.
  const HollowSection collar{8.0 * kInch, 2.8125 * kInch};
  const double youngs = 207e9, steel = 7850.0, mud = 1198.26;
  const double length = 30.0 * kFoot, hole_radius = 0.5 * 12.25 * kInch;
  const double rod_radius = 0.5 * collar.outer_diameter;
  auto frequency = [&](double mass_per_length) {
    return std::pow(kPi / length, 2) * std::sqrt(youngs * collar.second_moment() /
                                                 mass_per_length) / (2.0 * kPi);
  };
  const double dry = steel * collar.area();
  const double with_bore = dry + mud * collar.bore_area();
  const AnnulusFluidCoefficients inviscid =
      ComputeAnnulusFluidCoefficients(rod_radius, hole_radius, 2.0 * kPi * 4.3, 0.0);
  const double with_annulus = with_bore + AddedMassPerLength(inviscid, mud, rod_radius);
  const double f_dry = frequency(dry), f_bore = frequency(with_bore);
  const double f_annulus = frequency(with_annulus);
  std::printf("V5 collar: C_m = %.6f; f = %.4f Hz (%+.3f %%), %.4f Hz (%+.3f %%), "
              "%.4f Hz (%+.3f %%)\n",
              inviscid.added_mass, f_dry, 100 * (f_dry / 5.195 - 1), f_bore,
              100 * (f_bore / 5.140 - 1), f_annulus, 100 * (f_annulus / 4.307 - 1));
  EXPECT_LT(RelativeError(f_dry, 5.195), 0.005);
  EXPECT_LT(RelativeError(f_bore, 5.140), 0.005);
  EXPECT_LT(RelativeError(f_annulus, 4.307), 0.005);
  // method.md §7 writes C_m with diameters: (D_h² + OD²)/(D_h² − OD²).
  const double dh = 12.25 * kInch, od = collar.outer_diameter;
  EXPECT_NEAR(inviscid.added_mass, (dh * dh + od * od) / (dh * dh - od * od), 1e-12);
}

}  // namespace annulus_fluid_test
}  // namespace drillflex::fe
