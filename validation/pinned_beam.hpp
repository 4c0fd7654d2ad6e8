// Closed-form references for the first lateral mode of a uniform pinned–pinned tube (V5's collar:
// validation/imbalance_response_test.cpp, validation/fluid_frequency_test.cpp), independent of
// drillflex's own output. SI throughout.
//
// The mode is w = sin(kx), k = π/L, for every beam theory below (pinned ends: w = w'' = 0).
//  * Rayleigh beam (Euler–Bernoulli plus the sections' rotary inertia J = ρ_s I, which the model
//    carries by default, `model.rotary_inertia: true`): EI w'''' + m ẅ − J ẅ'' = 0 gives
//    ω₁² = EI k⁴/(m + J k²) and the generalized mass ∫(m φ² + J φ'²) dx = (L/2)(m + J k²)
//    (Rayleigh, Theory of Sound §186; Han, Benaroya & Wei 1999, "Dynamics of transversely vibrating
//    beams using four engineering theories", J. Sound Vib. 225:935, Rayleigh beam, pinned–pinned).
//  * Timoshenko beam (plus shear, `model.beam: timoshenko`): the lower root of
//    (J m/κGA) ω⁴ − (m + J k² + m EI k²/κGA) ω² + EI k⁴ = 0 (Han et al. 1999, Timoshenko beam),
//    κ of a thick tube from Cowper (1966), "The shear coefficient in Timoshenko's beam theory",
//    J. Appl. Mech. 33:335: κ = 6(1+ν)(1+n²)² / ((7+6ν)(1+n²)² + (20+12ν)n²), n = ID/OD.
//  * The share of the bodies' modal damping (below).
#pragma once

#include <cmath>

#include "core/types.hpp"

namespace drillflex::validation::pinned {

struct Tube {
  double length;          // m, between the pins
  double outer_diameter;  // m
  double inner_diameter;  // m
  double youngs_modulus;  // Pa
  double density;         // kg/m³
  double poisson_ratio;
  double area() const { return kPi * (outer_diameter * outer_diameter - inner_diameter * inner_diameter) / 4.0; }
  double second_moment() const {
    return kPi * (std::pow(outer_diameter, 4) - std::pow(inner_diameter, 4)) / 64.0;
  }
  double steel_mass() const { return density * area(); }               // kg/m
  double rotary_inertia() const { return density * second_moment(); }  // J, kg·m
  double wavenumber() const { return kPi / length; }                   // k, 1/m
};

// ω₁ (rad/s) of the Euler–Bernoulli beam with the lateral mass m (kg/m): k² sqrt(EI/m).
inline double EulerBernoulliFirstFrequency(const Tube& tube, double mass_per_length) {
  const double k = tube.wavenumber();
  return k * k * std::sqrt(tube.youngs_modulus * tube.second_moment() / mass_per_length);
}

// ω₁ (rad/s) of the Rayleigh beam: sqrt(EI k⁴/(m + J k²)), m the lateral mass per length (steel and
// fluid; the fluid adds no rotary inertia).
inline double RayleighFirstFrequency(const Tube& tube, double mass_per_length) {
  const double k = tube.wavenumber();
  return std::sqrt(tube.youngs_modulus * tube.second_moment() * std::pow(k, 4) /
                   (mass_per_length + tube.rotary_inertia() * k * k));
}

// The generalized mass (kg) of φ = sin(kx) on the Rayleigh beam: (L/2)(m + J k²).
inline double RayleighModalMass(const Tube& tube, double mass_per_length) {
  const double k = tube.wavenumber();
  return 0.5 * tube.length * (mass_per_length + tube.rotary_inertia() * k * k);
}

// Cowper's (1966) shear coefficient of a thick-walled circular tube.
inline double CowperShearCoefficient(const Tube& tube) {
  const double n2 = std::pow(tube.inner_diameter / tube.outer_diameter, 2), nu = tube.poisson_ratio;
  const double square = (1.0 + n2) * (1.0 + n2);
  return 6.0 * (1.0 + nu) * square / ((7.0 + 6.0 * nu) * square + (20.0 + 12.0 * nu) * n2);
}

// ω₁ (rad/s) of the dry Timoshenko beam (lower root of the quadratic in ω² above).
inline double TimoshenkoFirstFrequency(const Tube& tube) {
  const double k = tube.wavenumber(), m = tube.steel_mass(), j = tube.rotary_inertia();
  const double ei = tube.youngs_modulus * tube.second_moment();
  const double shear = CowperShearCoefficient(tube) * tube.youngs_modulus / (2.0 * (1.0 + tube.poisson_ratio)) *
                       tube.area();  // κGA, N
  const double a = j * m / shear, b = m + j * k * k + m * ei * k * k / shear, c = ei * std::pow(k, 4);
  return std::sqrt((b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a));
}

// The bodies' modal damping seen by the first mode, per unit ζ_s, on the dry steel:
//   s = φᵀDφ / (2 ζ_s ω₁ m₁)  with  D = diag(2 ζ_s ω_j) on each body's elastic modes,
// so that this mode's damping ratio is ζ_s (the loss factor 2ζ_s on K, docs/case-format.md "Modes and
// damping") + ζ_s s ω₁ m₁/(ω m) at a frequency ω and generalized mass m (wet: the same φᵀDφ).
// Each of `bodies` equal bodies of length l = L/bodies deforms by the mode's part in it, w = sin(kx)
// less its rigid motion; that deformation's coordinate on the body's elastic mode j (free–free,
// mass-normalized, ω_j = (β_j/l)² sqrt(EI/m), cos β cosh β = 1: Blevins, Formulas for Natural
// Frequency and Mode Shape, Table 8-1) is η_j = ∫ m w ψ_j dx, so φᵀDφ = Σ_bodies Σ_j 2ζ_s ω_j η_j².
// The first `modes` bending modes of a plane are summed; s hardly depends on how many (V5's collar in
// 4 bodies: 0.01863, 0.01885, 0.01946, 0.01949, 0.01958 with 1–5 of them: the stiffer modes see
// little of this slow mode's damping, ζ_s ω₁/ω_j of their share of its strain energy). The rotary inertia is left out here
// (its 3e-4 in ω₁ is far below what this small term needs).
inline double BodyModalDampingShare(const Tube& tube, int bodies, int modes) {
  constexpr int kSteps = 400;  // Simpson intervals a body
  const double l = tube.length / bodies, k = tube.wavenumber();
  double sum = 0.0;  // Σ ω_j η_j² / (m sqrt(EI/m)) over the bodies and modes
  for (int j = 0; j < modes; ++j) {
    double beta = (j + 1.5) * kPi;  // Newton on cos β cosh β − 1 from the asymptotic root
    for (int it = 0; it < 50; ++it) {
      const double g = std::cos(beta) * std::cosh(beta) - 1.0;
      const double dg = -std::sin(beta) * std::cosh(beta) + std::cos(beta) * std::sinh(beta);
      beta -= g / dg;
    }
    const double sigma = (std::cosh(beta) - std::cos(beta)) / (std::sinh(beta) - std::sin(beta));
    auto shape = [&](double xi) {  // ξ = x/l ∈ [0, 1]; ∫₀¹ ψ² dξ = 1 (Blevins)
      return std::cosh(beta * xi) + std::cos(beta * xi) - sigma * (std::sinh(beta * xi) + std::sin(beta * xi));
    };
    for (int b = 0; b < bodies; ++b) {
      double norm = 0.0, projection = 0.0;
      for (int i = 0; i <= kSteps; ++i) {
        const double xi = static_cast<double>(i) / kSteps;
        const double weight = (i == 0 || i == kSteps) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
        norm += weight * shape(xi) * shape(xi);
        projection += weight * shape(xi) * std::sin(k * (b + xi) * l);
      }
      norm /= 3.0 * kSteps;
      projection /= 3.0 * kSteps;
      // Mass-normalized ψ_j = shape/sqrt(m l norm): η_j² = m l projection²/norm, ω_j = (β/l)² c.
      sum += std::pow(beta / l, 2) * l * projection * projection / norm;
    }
  }
  // s = Σ ω_j η_j² / (ω₁ m₁) with ω₁ = k² c, m₁ = m L/2 (c = sqrt(EI/m) and m cancel).
  return sum / (k * k * 0.5 * tube.length);
}

}  // namespace drillflex::validation::pinned
