// A test-only evaluation of the added mass and damping of a rod vibrating in a confined viscous
// fluid (V5, validation/fluid_frequency_test.cpp), independent of fe/annulus_fluid and
// fe/modified_bessel: Chen, Wambsganss & Jendrzejczyk (1976), "Added mass and damping of a vibrating
// rod in confined viscous fluids", J. Appl. Mech. 43:325, with the modified Bessel functions from
// their large-argument expansions (Abramowitz & Stegun 9.7.1, 9.7.2) written here.
//
// The problem (units a = 1, rod velocity amplitude V = 1): the stream function ψ = f(x) sin θ e^{iωt},
// x = r/a ∈ [1, α], α = b/a, of the linearized Navier–Stokes equations, (iω − ν∇²)∇²ψ = 0, is
//   f(x) = A x + B/x + C I₁(βx) + D K₁(βx),   β = sqrt(iS), S = ω a²/ν,
// with no slip on the rod, f(1) = f′(1) = 1, and on the wall, f(α) = f′(α) = 0. Only the potential
// part A x + B/x carries pressure, p = −ρ iω (A r − B a²/r) V cos θ; the force on the rod per length,
// F = π a [ρ iω (A − B) a V + μ f″(1) V/a], divided by ρ π a² ω² X (X = V/iω) is
//   H = C_m − i C_v = −(A − B + f″(1)/β²),
// so the fluid acts as the added mass C_m ρ π a² and the damping C_v ρ π a² ω per length.
// Inviscid check: C, D → 0 and the slip allowed give H = (α² + 1)/(α² − 1).
#pragma once

#include <stdexcept>

#include <array>
#include <cmath>
#include <complex>

#include <Eigen/Dense>

namespace drillflex::validation::chen {

using Complex = std::complex<double>;

// e^{−z} I_n(z) and e^{z} K_n(z) for n = 0, 1 from the asymptotic series (A&S 9.7.1, 9.7.2):
//   I_n(z) ≈ e^z/sqrt(2πz) Σ_k (−1)^k a_k(n)/z^k,   K_n(z) ≈ sqrt(π/2z) e^{−z} Σ_k a_k(n)/z^k,
//   a_k(n) = (4n² − 1²)(4n² − 3²)…(4n² − (2k − 1)²)/(k! 8^k),
// summed to the smallest term (|arg z| < π/2; the error is then about e^{−2|z|}, below 1e-15 for
// |z| ≥ 20; I's exponentially small companion term, e^{−z}, is below that too).
struct ScaledBessel {
  Complex i0, i1, k0, k1;
};

inline ScaledBessel ComputeScaledBessel(Complex z) {
  const double pi = 3.14159265358979323846;
  auto series = [&](int n, double sign) {
    const double mu = 4.0 * n * n;
    Complex sum = 1.0, term = 1.0;
    double last = 1.0;
    for (int k = 1; k < 200; ++k) {
      term *= sign * (mu - (2.0 * k - 1) * (2.0 * k - 1)) / (8.0 * k) / z;
      if (std::abs(term) >= last) break;  // the series starts to diverge: stop at the smallest term
      last = std::abs(term);
      sum += term;
      if (last < 1e-17 * std::abs(sum)) break;
    }
    return sum;
  };
  const Complex i_factor = 1.0 / std::sqrt(2.0 * pi * z), k_factor = std::sqrt(pi / (2.0 * z));
  return {i_factor * series(0, -1.0), i_factor * series(1, -1.0), k_factor * series(0, 1.0),
          k_factor * series(1, 1.0)};
}

// I_n(z) (n = 0, 1) from the ascending series (A&S 9.6.10), for checking the expansion above where
// both hold: I_n(z) = (z/2)^n Σ_k (z²/4)^k / (k! (n + k)!).
inline Complex PowerSeriesBesselI(int n, Complex z) {
  Complex term = n == 0 ? Complex(1.0) : 0.5 * z, sum = term;
  for (int k = 1; k < 500; ++k) {
    term *= 0.25 * z * z / (static_cast<double>(k) * (n + k));
    sum += term;
    if (std::abs(term) < 1e-18 * std::abs(sum)) break;
  }
  return sum;
}

// H = C_m − i C_v for the radius ratio α = b/a > 1 and Stokes number S = ω a²/ν with |β| ≥ 20
// (S ≥ 400: the expansions' range; V5's S is 1.7e4).
inline Complex ForceRatio(double alpha, double stokes) {
  if (stokes < 400.0) throw std::invalid_argument("ForceRatio: the scaled columns hold for S >= 400 only");
  const Complex beta = std::sqrt(Complex(0.0, stokes));
  // The Bessel columns scaled by e^{−βα} (I₁) and e^{β} (K₁) so that every entry is O(1) or less:
  // at x, I₁(βx) e^{−βα} = e^{β(x − α)} [e^{−βx} I₁(βx)], K₁(βx) e^{β} = e^{−β(x − 1)} [e^{βx} K₁(βx)].
  // Derivatives in x: I₁′ = I₀ − I₁/z, K₁′ = −K₀ − K₁/z (A&S 9.6.26), d/dx = β d/dz;
  // second: Z″ = (1 + 1/z²) Z − Z′/z for Z = I₁, K₁ (the modified Bessel equation, A&S 9.6.1).
  struct Column {
    Complex value, slope, curvature;  // in x
  };
  auto columns = [&](double x) {
    const Complex z = beta * x;
    const ScaledBessel s = ComputeScaledBessel(z);
    const Complex ie = std::exp(beta * (x - alpha)), ke = std::exp(-beta * (x - 1.0));
    const Complex i1 = ie * s.i1, i0 = ie * s.i0, k1 = ke * s.k1, k0 = ke * s.k0;
    const Complex di = i0 - i1 / z, dk = -k0 - k1 / z;
    const Column i{i1, beta * di, beta * beta * ((1.0 + 1.0 / (z * z)) * i1 - di / z)};
    const Column k{k1, beta * dk, beta * beta * ((1.0 + 1.0 / (z * z)) * k1 - dk / z)};
    return std::array<Column, 2>{i, k};
  };
  const auto at_rod = columns(1.0), at_wall = columns(alpha);
  Eigen::Matrix4cd m;
  m << 1.0, 1.0, at_rod[0].value, at_rod[1].value,                  // f(1) = 1
      1.0, -1.0, at_rod[0].slope, at_rod[1].slope,                   // f′(1) = 1
      alpha, 1.0 / alpha, at_wall[0].value, at_wall[1].value,        // f(α) = 0
      1.0, -1.0 / (alpha * alpha), at_wall[0].slope, at_wall[1].slope;  // f′(α) = 0
  const Eigen::Vector4cd c = m.fullPivLu().solve(Eigen::Vector4cd(1.0, 1.0, 0.0, 0.0));
  const Complex curvature = 2.0 * c(1) + c(2) * at_rod[0].curvature + c(3) * at_rod[1].curvature;  // f″(1)
  return -(c(0) - c(1) + curvature / (beta * beta));
}

}  // namespace drillflex::validation::chen
