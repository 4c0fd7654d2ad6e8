// One measurement of the model study (docs/model-study.md): the V1 cantilever of validation.md
// built through model::BuildSystemModel with a given discretization, compared with Euler–Bernoulli
// theory (first four bending frequencies, three static tip deflections), plus the highest natural
// frequency of the coupled model (the explicit stability limit).
#pragma once

#include <array>

#include "cms/reduction_cache.hpp"
#include "model/string_config.hpp"

namespace drillflex::study {

// The V1 rod (validation.md): solid steel, D = 3 in, L = 200 in, E = 2.1e11 Pa, ρ = 7800 kg/m³.
inline constexpr double kLength = 5.08;
inline constexpr double kDiameter = 0.0762;
inline constexpr double kYoungsModulus = 2.1e11;
inline constexpr double kPoissonRatio = 0.3;
inline constexpr double kDensity = 7800.0;

struct ModelConfig {
  int bodies = 4;
  int elements_per_body = 10;
  int modes_per_body = 6;  // H: fixed-interface modes (n_f = 6 + H)
  double coupling_factor = model::ModelSettings{}.coupling_factor;  // the library's default
  fe::MassKind mass = fe::MassKind::kConsistent;
  bool rotary_inertia = false;  // the Euler–Bernoulli reference has none
};

// The linear static load cases are sized for a tip deflection of this fraction of L.
inline constexpr double kStaticDeflectionRatio = 1e-5;

enum StaticCase { kTipForce = 0, kUniformLoad = 1, kTipMoment = 2 };
inline constexpr int kFrequencyCount = 4;
inline constexpr int kStaticCaseCount = 3;

struct Measurement {
  int coordinates = 0;                                   // velocities of the whole model
  // Relative errors f / f_exact − 1 of the first four bending frequencies, the larger |error| of
  // the x-y and x-z planes; they differ (plane_split: the largest difference) only when
  // modes_per_body cuts a y/z pair of fixed-interface modes.
  std::array<double, kFrequencyCount> frequency_error{};
  double plane_split = 0.0;
  std::array<double, kStaticCaseCount> static_error{};    // relative: δ / δ_exact − 1
  double omega_max = 0.0;       // highest natural frequency of the clamped coupled model, rad/s
  double omega_max_free = 0.0;  // the same without the clamp: the couplings only, rad/s
  double body_omega_max = 0.0;  // highest frequency of one free-free reduced body, rad/s

  double MaxFrequencyError() const;  // max |error| over the four frequencies
  double MaxStaticError() const;     // max |error| over the three load cases
  // Stable step of central differences (undamped): Δt_crit = 2/ω_max, s.
  double CriticalTimeStep() const { return 2.0 / omega_max; }
  double CriticalTimeStepFree() const { return 2.0 / omega_max_free; }
};

// Builds the models of `config` (the reductions are cached in `cache`) and measures them.
Measurement Measure(const ModelConfig& config, cms::ReductionCache& cache);

// A moderate deflection: tip moment M = EI φ/L (tip rotation φ), tip deflection relative to
// linear theory (φL/2) and to the exact elastica (a circular arc), both as f / f_exact − 1.
struct MomentArcErrors {
  double linear = 0.0;
  double elastica = 0.0;
};
MomentArcErrors MomentArcError(const ModelConfig& config, double tip_rotation, cms::ReductionCache& cache);

// First-order relative shift of cantilever frequency n (0-based) by the bending rotary inertia ρI
// (Rayleigh beam), from the Rayleigh quotient with the Euler–Bernoulli mode shape.
double RotaryInertiaShift(int n);

// Euler–Bernoulli cantilever frequency n (0-based), Hz: (β_n L)²/(2π L²) sqrt(EI/(ρA)).
double ExactFrequencyHz(int n);

}  // namespace drillflex::study
