#include "fe/annulus_fluid.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Dense>

#include "core/error.hpp"
#include "core/types.hpp"
#include "fe/modified_bessel.hpp"

namespace drillflex::fe {
namespace {

// The problem in the units a = 1, V = 1 (the rod's velocity amplitude): x = r/a ∈ [1, α],
// β = k a = sqrt(iS), stream function ψ = a V f(x) sin θ e^{iωt} (u_r = ψ_θ/r, u_θ = −ψ_r),
//   f(x) = A x + B/x + C w_I(x) + D w_K(x),
// f(1) = f′(1) = 1 (no slip on the rod), f(α) = f′(α) = 0 (no slip on the wall). The pressure
// comes from the potential part only, p = −ρ iω φ, φ = aV (A_h x − B_h/x) cos θ with A_h, B_h the
// coefficients of x and 1/x in f; the force on the rod (Chen et al. 1976)
//   F_x = π a [ρ iω (A_h a − B_h/a) a V + μ V f″(1)/a]
// divided by ρ π a² ω² X = ρ π a² (−iω V) gives
//   H = −[A_h − B_h + f″(1)/β²]   (μ/(ρ iω a²) = 1/β²).
// Inviscid check: A_h − B_h = −(α² + 1)/(α² − 1), so H = C_m > 0.
struct BasisValue {
  Complex f, df;  // w(x), w′(x) (derivative in x)
};

using Matrix4c = Eigen::Matrix<Complex, 4, 4>;
using Vector4c = Eigen::Matrix<Complex, 4, 1>;

// Solves the boundary-value system after equilibrating rows and columns (the Bessel columns
// carry factors up to |β| ~ 1e3 and more against O(1) for x and 1/x).
Vector4c SolveBoundaryConditions(Matrix4c matrix, double radius_ratio, double stokes_number) {
  Vector4c rhs(1.0, 1.0, 0.0, 0.0);
  Eigen::Vector4d column_scale, row_scale;
  for (int j = 0; j < 4; ++j) column_scale(j) = 1.0 / matrix.col(j).cwiseAbs().maxCoeff();
  matrix = matrix * column_scale.asDiagonal();
  for (int i = 0; i < 4; ++i) row_scale(i) = 1.0 / matrix.row(i).cwiseAbs().maxCoeff();
  matrix = row_scale.asDiagonal() * matrix;
  rhs = row_scale.asDiagonal() * rhs;
  const Eigen::FullPivLU<Matrix4c> lu(matrix);
  Vector4c solution = column_scale.asDiagonal() * lu.solve(rhs);
  if (!column_scale.allFinite() || !row_scale.allFinite() || lu.rank() < 4 ||
      !solution.allFinite()) {
    throw SolverError("annulus fluid: the boundary conditions of the confined rod (b/a = " +
                      std::to_string(radius_ratio) + ", S = " + std::to_string(stokes_number) +
                      ") gave a singular system");
  }
  return solution;
}

// Basis {x, 1/x, e^{−βα} I₁(βx), e^{β} K₁(βx)} with the exponentially scaled Bessel functions:
// every entry stays finite for |β| up to 1e6 and more (e^{β(1−α)} underflows harmlessly to 0).
std::complex<double> ForceRatioScaledBasis(double alpha, double stokes_number, Complex beta) {
  Matrix4c matrix;
  auto row_pair = [&](int row, double x) {
    const Complex z = beta * x;
    const ScaledModifiedBessel b = ComputeScaledModifiedBessel(z);
    const Complex i_factor = std::exp(beta * (x - alpha));  // e^{−βα} e^{βx}
    const Complex k_factor = std::exp(-beta * (x - 1.0));   // e^{β} e^{−βx}
    // I₁′ = I₀ − I₁/z, K₁′ = −K₀ − K₁/z (A&S 9.6.27); d/dx = β d/dz.
    matrix.row(row) << x, 1.0 / x, i_factor * b.i1, k_factor * b.k1;
    matrix.row(row + 1) << 1.0, -1.0 / (x * x), i_factor * beta * (b.i0 - b.i1 / z),
        k_factor * beta * (-b.k0 - b.k1 / z);
  };
  row_pair(0, 1.0);
  row_pair(2, alpha);
  const Vector4c c = SolveBoundaryConditions(matrix, alpha, stokes_number);
  // w″ = (1 + 1/z²) w − w′/z for w = I₁, K₁ (the modified Bessel equation, A&S 9.6.1, ν = 1).
  const ScaledModifiedBessel b = ComputeScaledModifiedBessel(beta);
  const Complex inv = 1.0 / beta;
  const Complex di1 = b.i0 - b.i1 * inv, dk1 = -b.k0 - b.k1 * inv;
  const Complex d2i1 = (1.0 + inv * inv) * b.i1 - di1 * inv;
  const Complex d2k1 = (1.0 + inv * inv) * b.k1 - dk1 * inv;
  const Complex f2_over_beta2 =
      2.0 * c(1) * inv * inv + c(2) * std::exp(beta * (1.0 - alpha)) * d2i1 + c(3) * d2k1;
  return -(c(0) - c(1) + f2_over_beta2);
}

// Basis {x, 1/x, g(βx), p(βx)} with g = I₁ − z/2, p = K₁ − 1/z, used when |β|α is small: there
// I₁(βx) and K₁(βx) are nearly copies of x and 1/x and the plain basis loses digits as 1/|β|².
std::complex<double> ForceRatioSmallArgumentBasis(double alpha, double stokes_number,
                                                  Complex beta) {
  // g′ = (I₀ − 1) − g/z, p′ = −K₀ − p/z (from A&S 9.6.27 with the leading terms taken out);
  // g″ = (1 + 1/z²) g − g′/z + z/2, p″ = (1 + 1/z²) p − p′/z + 1/z (from A&S 9.6.1).
  struct Remainder {
    Complex g, dg, p, dp;
  };
  auto remainders = [](Complex z) {
    const BesselRemainders r = ComputeSmallArgumentBesselRemainders(z);
    return Remainder{r.i1_less_linear, r.i0_less_one - r.i1_less_linear / z, r.k1_less_pole,
                     -r.k0 - r.k1_less_pole / z};
  };
  Matrix4c matrix;
  for (const auto& [row, x] : {std::pair{0, 1.0}, std::pair{2, alpha}}) {
    const Remainder w = remainders(beta * x);
    matrix.row(row) << x, 1.0 / x, w.g, w.p;
    matrix.row(row + 1) << 1.0, -1.0 / (x * x), beta * w.dg, beta * w.dp;
  }
  const Vector4c c = SolveBoundaryConditions(matrix, alpha, stokes_number);
  const Remainder w = remainders(beta);
  const Complex inv = 1.0 / beta;
  const Complex d2g = (1.0 + inv * inv) * w.g - w.dg * inv + 0.5 * beta;
  const Complex d2p = (1.0 + inv * inv) * w.p - w.dp * inv + inv;
  // Harmonic parts: f = (A − Cβ/2) x + (B − D/β)/x + C I₁ + D K₁.
  const Complex a_harmonic = c(0) - 0.5 * beta * c(2);
  const Complex b_harmonic = c(1) - c(3) * inv;
  const Complex f2_over_beta2 = 2.0 * c(1) * inv * inv + c(2) * d2g + c(3) * d2p;
  return -(a_harmonic - b_harmonic + f2_over_beta2);
}

void CheckRadiusRatio(double radius_ratio, const char* where) {
  if (!(radius_ratio > 1.0) || !std::isfinite(radius_ratio)) {
    throw LogicError(std::string(where) + ": the hole radius must exceed the rod radius (b/a = " +
                     std::to_string(radius_ratio) + ")");
  }
}

}  // namespace

double InviscidAddedMassCoefficient(double radius_ratio) {
  CheckRadiusRatio(radius_ratio, "InviscidAddedMassCoefficient");
  const double alpha2 = radius_ratio * radius_ratio;
  return (alpha2 + 1.0) / (alpha2 - 1.0);
}

double StokesNumber(double rod_radius, double circular_frequency, double kinematic_viscosity) {
  if (!(rod_radius > 0.0) || !(circular_frequency >= 0.0) || !(kinematic_viscosity > 0.0)) {
    throw LogicError("StokesNumber: needs a > 0, ω ≥ 0 and ν > 0");
  }
  return circular_frequency * rod_radius * rod_radius / kinematic_viscosity;
}

std::complex<double> ConfinedForceRatio(double radius_ratio, double stokes_number) {
  CheckRadiusRatio(radius_ratio, "ConfinedForceRatio");
  if (!(stokes_number > 0.0)) {
    throw LogicError("ConfinedForceRatio: needs a Stokes number S > 0, got " +
                     std::to_string(stokes_number));
  }
  if (stokes_number > kInviscidStokesNumber) return InviscidAddedMassCoefficient(radius_ratio);
  const Complex beta = std::sqrt(stokes_number) * std::polar(1.0, kPi / 4.0);  // sqrt(iS)
  if (std::abs(beta) * radius_ratio <= kBesselSeriesLimit) {
    return ForceRatioSmallArgumentBasis(radius_ratio, stokes_number, beta);
  }
  return ForceRatioScaledBasis(radius_ratio, stokes_number, beta);
}

std::complex<double> UnconfinedForceRatio(double stokes_number) {
  if (!(stokes_number > 0.0) || !std::isfinite(stokes_number)) {
    throw LogicError("UnconfinedForceRatio: needs a finite Stokes number S > 0");
  }
  const Complex beta = std::sqrt(stokes_number) * std::polar(1.0, kPi / 4.0);
  const ScaledModifiedBessel b = ComputeScaledModifiedBessel(beta);
  return 1.0 + 4.0 * b.k1 / (beta * b.k0);  // the scale factors e^{β} cancel
}

AnnulusFluidCoefficients ComputeAnnulusFluidCoefficients(double rod_radius, double hole_radius,
                                                      double circular_frequency,
                                                      double kinematic_viscosity) {
  if (!(rod_radius > 0.0) || !(hole_radius > rod_radius) || !(circular_frequency >= 0.0) ||
      !(kinematic_viscosity >= 0.0) || !std::isfinite(hole_radius)) {
    throw LogicError("ComputeAnnulusFluidCoefficients: needs 0 < a < b, ω ≥ 0 and ν ≥ 0 (a = " +
                     std::to_string(rod_radius) + " m, b = " + std::to_string(hole_radius) +
                     " m, ω = " + std::to_string(circular_frequency) + " rad/s, ν = " +
                     std::to_string(kinematic_viscosity) + " m²/s)");
  }
  const double alpha = hole_radius / rod_radius;
  if (kinematic_viscosity == 0.0) return {InviscidAddedMassCoefficient(alpha), 0.0};
  if (circular_frequency == 0.0) {
    throw LogicError(
        "ComputeAnnulusFluidCoefficients: a viscous fluid has no added-mass and damping "
        "coefficients at ω = 0");
  }
  const Complex h =
      ConfinedForceRatio(alpha, StokesNumber(rod_radius, circular_frequency, kinematic_viscosity));
  return {h.real(), -h.imag()};
}

double AddedMassPerLength(const AnnulusFluidCoefficients& coefficients, double fluid_density,
                          double rod_radius) {
  return coefficients.added_mass * fluid_density * kPi * rod_radius * rod_radius;
}

double DampingPerLength(const AnnulusFluidCoefficients& coefficients, double fluid_density,
                        double rod_radius, double circular_frequency) {
  return coefficients.damping * fluid_density * kPi * rod_radius * rod_radius * circular_frequency;
}

}  // namespace drillflex::fe
