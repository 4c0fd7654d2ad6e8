#include "fe/modified_bessel.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"

namespace drillflex::fe {
namespace {

constexpr double kEulerGamma = 0.57721566490153286061;
constexpr double kEpsilon = 1e-17;          // relative size of the last term kept
constexpr int kMaxSeriesTerms = 200;
constexpr int kMaxFractionTerms = 100000;   // CF1 needs about |z| terms
constexpr double kAsymptoticRealPart = 40.0;  // Re z above which A&S 9.7.1 is used for I

std::string Describe(Complex z) {
  std::ostringstream text;
  text.precision(17);
  text << "z = (" << z.real() << ", " << z.imag() << ")";
  return text.str();
}

void CheckArgument(Complex z, const char* where) {
  if (!std::isfinite(z.real()) || !std::isfinite(z.imag()) || !(z.real() > 0.0)) {
    throw LogicError(std::string(where) + ": needs a finite argument with Re z > 0, got " +
                     Describe(z));
  }
}

// The ascending series, unscaled, split into leading terms and remainders.
struct SeriesParts {
  Complex i0_less_one, i1_less_linear, k0, k1_less_pole;
};

SeriesParts SumSeries(Complex z) {
  const Complex t = 0.25 * z * z;  // z²/4
  // I₀ = Σ t^k/(k!)², I₁ = (z/2) Σ t^k/(k!(k+1)!)  (A&S 9.6.10);
  // K₀ = −(ln(z/2) + γ) I₀ + Σ_{k≥1} H_k t^k/(k!)²  (A&S 9.6.13, ψ(k+1) = −γ + H_k);
  // K₁ = 1/z + (ln(z/2) + γ) I₁ − (z/4) Σ_{k≥0} (H_k + H_{k+1}) t^k/(k!(k+1)!)  (A&S 9.6.11, n=1).
  Complex i0_rest = 0.0, i1_sum_rest = 0.0, k0_sum = 0.0, k1_sum = 1.0;  // k = 0 of K₁'s sum: H₁
  Complex term0 = 1.0;  // t^k/(k!)²
  Complex term1 = 1.0;  // t^k/(k!(k+1)!)
  double harmonic = 0.0;  // H_k
  for (int k = 1; k < kMaxSeriesTerms; ++k) {
    const double kk = k;
    term0 *= t / (kk * kk);
    term1 *= t / (kk * (kk + 1.0));
    harmonic += 1.0 / kk;                                       // H_k
    const double harmonic_next = 2.0 * harmonic + 1.0 / (kk + 1.0);  // H_k + H_{k+1}
    i0_rest += term0;
    i1_sum_rest += term1;
    k0_sum += harmonic * term0;
    k1_sum += harmonic_next * term1;
    if (std::abs(term0) * (1.0 + harmonic) < kEpsilon * std::abs(1.0 + i0_rest) &&
        std::abs(term1) * (1.0 + harmonic_next) < kEpsilon * std::abs(1.0 + i1_sum_rest)) {
      break;
    }
  }
  const Complex half_z = 0.5 * z;
  const Complex log_term = std::log(half_z) + kEulerGamma;
  const Complex i0 = 1.0 + i0_rest;
  const Complex i1 = half_z * (1.0 + i1_sum_rest);
  return {i0_rest, half_z * i1_sum_rest, -log_term * i0 + k0_sum,
          log_term * i1 - 0.25 * z * k1_sum};
}

// K₀ and K₁ scaled, by Steed's CF2 with the Thompson–Barnett sum (NR bessik, order μ = 0):
// the loop is NR's with x complex.
void ContinuedFractionK(Complex z, Complex& k0_scaled, Complex& k1_scaled) {
  const double a1 = 0.25;  // 1/4 − μ²
  Complex b = 2.0 * (1.0 + z);
  Complex d = 1.0 / b;
  Complex h = d, delh = d;
  Complex q1 = 0.0, q2 = 1.0;
  double q_coefficient = a1, a = -a1;
  Complex q = a1;
  Complex s = 1.0 + q * delh;
  int i = 1;
  for (; i < kMaxFractionTerms; ++i) {
    a -= 2.0 * i;
    q_coefficient = -a * q_coefficient / (i + 1.0);
    const Complex q_new = (q1 - b * q2) / a;
    q1 = q2;
    q2 = q_new;
    q += q_coefficient * q_new;
    b += 2.0;
    d = 1.0 / (b + a * d);
    delh = (b * d - 1.0) * delh;
    h += delh;
    const Complex dels = q * delh;
    s += dels;
    if (std::abs(dels) < kEpsilon * std::abs(s)) break;
  }
  if (i == kMaxFractionTerms) {
    throw SolverError("modified Bessel K: CF2 did not converge at " + Describe(z));
  }
  h *= a1;
  k0_scaled = std::sqrt(kPi / (2.0 * z)) / s;  // NR: K_μ = sqrt(π/2x) e^{−x} / s
  k1_scaled = k0_scaled * (z + 0.5 - h) / z;   // NR: K_{μ+1} = K_μ (μ + x + 1/2 − h)/x
}

// I₁/I₀ = 1/(2/z + 1/(4/z + 1/(6/z + …))) (from I_{ν−1} − I_{ν+1} = (2ν/z) I_ν, A&S 9.6.26),
// by the modified Lentz method (NR §5.2).
Complex RatioI1OverI0(Complex z) {
  constexpr double tiny = 1e-300;
  const Complex inv_z = 1.0 / z;
  Complex f = 2.0 * inv_z;  // b₁
  Complex c = f, dd = 0.0;
  int j = 2;
  for (; j < kMaxFractionTerms; ++j) {
    const Complex bj = 2.0 * j * inv_z;
    dd = bj + dd;
    if (std::abs(dd) < tiny) dd = tiny;
    c = bj + 1.0 / c;
    if (std::abs(c) < tiny) c = tiny;
    dd = 1.0 / dd;
    const Complex delta = c * dd;
    f *= delta;
    if (std::abs(delta - 1.0) < kEpsilon) break;
  }
  if (j == kMaxFractionTerms) {
    throw SolverError("modified Bessel I: CF1 did not converge at " + Describe(z));
  }
  return 1.0 / f;
}

// Σ_k s^k a_k(ν)/z^k of A&S 9.7.1 (s = −1, for I) or 9.7.2 (s = +1, for K), with
// a_k(ν) = Π_{j=1..k} (4ν² − (2j−1)²) / (k! 8^k), summed until the terms stop shrinking.
Complex AsymptoticSum(Complex z, int order, double sign) {
  const double mu = 4.0 * order * order;
  Complex sum = 1.0, term = 1.0;
  double last = 1.0;
  for (int k = 1; k < kMaxSeriesTerms; ++k) {
    const double odd = 2.0 * k - 1.0;
    const Complex next = term * (sign * (mu - odd * odd) / (8.0 * k)) / z;
    const double size = std::abs(next);
    if (size >= last) break;  // the expansion diverges from here on
    term = next;
    last = size;
    sum += term;
    if (size < kEpsilon * std::abs(sum)) break;
  }
  return sum;
}

}  // namespace

ScaledModifiedBessel ComputeScaledModifiedBesselSeries(Complex z) {
  CheckArgument(z, "ComputeScaledModifiedBesselSeries");
  const SeriesParts parts = SumSeries(z);
  const Complex grow = std::exp(z), decay = std::exp(-z);
  return {decay * (1.0 + parts.i0_less_one), decay * (0.5 * z + parts.i1_less_linear),
          grow * parts.k0, grow * (1.0 / z + parts.k1_less_pole)};
}

ScaledModifiedBessel ComputeScaledModifiedBesselAsymptotic(Complex z) {
  CheckArgument(z, "ComputeScaledModifiedBesselAsymptotic");
  // A&S 9.7.1: I_ν(z) ~ e^z/sqrt(2πz) Σ (−1)^k a_k/z^k;
  // A&S 9.7.2: K_ν(z) ~ sqrt(π/2z) e^{−z} Σ a_k/z^k.
  const Complex i_factor = 1.0 / std::sqrt(2.0 * kPi * z);
  const Complex k_factor = std::sqrt(kPi / (2.0 * z));
  return {i_factor * AsymptoticSum(z, 0, -1.0), i_factor * AsymptoticSum(z, 1, -1.0),
          k_factor * AsymptoticSum(z, 0, 1.0), k_factor * AsymptoticSum(z, 1, 1.0)};
}

ScaledModifiedBessel ComputeScaledModifiedBessel(Complex z) {
  CheckArgument(z, "ComputeScaledModifiedBessel");
  if (std::abs(z) <= kBesselSeriesLimit) return ComputeScaledModifiedBesselSeries(z);
  ScaledModifiedBessel values;
  ContinuedFractionK(z, values.k0, values.k1);
  if (z.real() > kAsymptoticRealPart) {
    const ScaledModifiedBessel asymptotic = ComputeScaledModifiedBesselAsymptotic(z);
    values.i0 = asymptotic.i0;
    values.i1 = asymptotic.i1;
    return values;
  }
  // Wronskian I₀K₁ + I₁K₀ = 1/z (A&S 9.6.15) with I₁ = ρ I₀; the exponentials cancel.
  const Complex ratio = RatioI1OverI0(z);
  values.i0 = 1.0 / (z * (values.k1 + ratio * values.k0));
  values.i1 = ratio * values.i0;
  return values;
}

BesselRemainders ComputeSmallArgumentBesselRemainders(Complex z) {
  CheckArgument(z, "ComputeSmallArgumentBesselRemainders");
  if (std::abs(z) > kBesselSeriesLimit) {
    throw LogicError("ComputeSmallArgumentBesselRemainders: |z| > 2 at " + Describe(z));
  }
  const SeriesParts parts = SumSeries(z);
  return {parts.i0_less_one, parts.i1_less_linear, parts.k0, parts.k1_less_pole};
}

}  // namespace drillflex::fe
