// Modified Bessel functions I₀, I₁, K₀, K₁ of complex argument z, Re z > 0, exponentially
// scaled so that they neither overflow nor underflow at |z| ~ 1e3 and more: the values returned
// are e^{−z} I_ν(z) and e^{z} K_ν(z), so a product I_ν K_μ is the product of the scaled values.
// The std library has no complex Bessel functions; the confined-fluid forces of a vibrating pipe
// (annulus_fluid.hpp) need them at z = r sqrt(iω/ν), arg z = π/4.
//
// Method, by |z| (A&S = Abramowitz & Stegun 1964; NR = Press et al., Numerical Recipes in C,
// 2nd ed., §6.7):
//   |z| ≤ 2:            the ascending series, A&S 9.6.10 (I) and 9.6.11/9.6.13 (K);
//   |z| > 2, K₀ and K₁: Steed's continued fraction CF2 with the Thompson–Barnett normalization
//                       (NR routine bessik; Thompson & Barnett 1986, J. Comput. Phys. 64:490, show
//                       it converges for complex z off the negative real axis);
//   2 < |z|, Re z ≤ 40: I₁/I₀ by the continued fraction CF1 (NR §6.7, from the recurrence
//                       A&S 9.6.26), then I₀ from the Wronskian I₀K₁ + I₁K₀ = 1/z (A&S 9.6.15);
//   Re z > 40:          the large-argument expansion A&S 9.7.1 (its exponentially small second
//                       part is below e^{−80} there).
// Accuracy (tests/fe/modified_bessel_test.cpp): 1e-14 relative against mpmath along arg z = π/4
// for |z| from 1e-3 to 1e3; the Wronskian holds to 2e-14 up to |z| = 2e4 at arg z = 0, π/4, 1.2.
#pragma once

#include <complex>

namespace drillflex::fe {

using Complex = std::complex<double>;

struct ScaledModifiedBessel {
  Complex i0;  // e^{−z} I₀(z)
  Complex i1;  // e^{−z} I₁(z)
  Complex k0;  // e^{z} K₀(z)
  Complex k1;  // e^{z} K₁(z)
};

// Below this |z| the ascending series are used.
inline constexpr double kBesselSeriesLimit = 2.0;

// All four scaled functions at z. Throws LogicError unless Re z > 0 and z is finite.
ScaledModifiedBessel ComputeScaledModifiedBessel(Complex z);

// The branches on their own (for the tests of continuity between them; any Re z > 0, but each
// is accurate only where ComputeScaledModifiedBessel uses it):
// the ascending series (cancellation grows like e^{|z| + Re z} for K);
ScaledModifiedBessel ComputeScaledModifiedBesselSeries(Complex z);
// the large-argument expansions A&S 9.7.1 and 9.7.2, summed to their smallest term.
ScaledModifiedBessel ComputeScaledModifiedBesselAsymptotic(Complex z);

// For small |z| (≤ kBesselSeriesLimit), the functions less their algebraic leading terms,
// unscaled, from the same series: I₀ − 1, I₁ − z/2, K₁ − 1/z, and K₀. In a basis of solutions
// {r, 1/r, I₁(kr), K₁(kr)} these remove the parts that at small kr are copies of r and 1/r.
struct BesselRemainders {
  Complex i0_less_one;     // I₀(z) − 1
  Complex i1_less_linear;  // I₁(z) − z/2
  Complex k0;              // K₀(z)
  Complex k1_less_pole;    // K₁(z) − 1/z
};
// Throws LogicError unless 0 < |z| ≤ kBesselSeriesLimit and Re z > 0.
BesselRemainders ComputeSmallArgumentBesselRemainders(Complex z);

}  // namespace drillflex::fe
