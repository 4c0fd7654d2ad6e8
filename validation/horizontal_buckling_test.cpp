// V3 of validation.md, sinusoidal buckling onset in a horizontal hole by slow compression
// (v3-horizontal-buckling/slow-compression.yaml): a 40 m pipe on the low side of a horizontal hole, no
// friction, held axially at the far end and pushed by the block at 0.5 mm/s, so that the axial load
// F (uniform: no friction, no inclination) rises slowly through Dawson & Paslay's (1984)
//   F_sin = 2 sqrt(EI w sin I / r)   (r radial clearance, w weight per length, I = 90°),
// the load at which the pipe lying on the low side stops being stable: its lateral stiffness against
// a sinusoid of wavenumber k, EI k⁴ − F k² + w sin I / r (bending, the axial load, gravity holding
// it on the low side as a pendulum of length r), first vanishes at F_sin, for k⁴ = w sin I/(EI r),
// half-wavelength π (EI r/(w sin I))^¼. Both ends are held sideways on the wall (pinned for the
// sinusoid, whose eight half-waves fit the pipe: its lowest buckling load is F_sin to 2e-6); free
// ends would buckle alone first, at √(k EI) = F_sin/2 (Hetényi's end mode, measured 0.55 F_sin).
//
// Onset detection: the first sample at which some probe's lateral displacement across the hole
// (to the right, y) exceeds a tenth of the clearance, i.e. the pipe has rolled sin⁻¹ 0.1 = 5.7° up
// the wall. Why this is the Dawson–Paslay load: a 1 N side force at mid-length (the imperfection)
// moves the pipe by ~1e-3 r while it is stable; below F_sin the lateral displacement stays
// proportional to that imperfection (amplified as 1/(1 − F/F_n) for the string's modes, which all
// keep F_n ≥ F_sin), and only once F passes F_sin is it bounded by the nonlinearity alone and grows
// to O(r). So the displacement crosses 0.1 r within a small fraction of F_sin of the onset: late by
// the post-buckling increment to that amplitude and by the lag of the slow sweep, early by the
// amplification of the imperfection just below F_sin (the figures of docs/validation.md; the same
// criterion at 0.25 r is printed to show how little the load depends on the level). Within 10 %
// of F_sin. At the detected onset the probes show the sinusoid: lateral displacements changing sign
// along the pipe with a mean half-wavelength within 20 % of the theory's (the ends hold no
// particular phase, and the probes are 2 m apart).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "validation_support.hpp"

namespace drillflex::validation {
namespace horizontal_buckling_test {

constexpr double kPi = 3.14159265358979323846;
// The case's figures (SI).
constexpr double kOd = 0.04, kId = 0.03, kHole = 0.07, kE = 2.1e11, kDensity = 7850.0, kGravity = 9.80665;
constexpr const char* kCase = "v3-horizontal-buckling/slow-compression.yaml";

struct Reference {
  double ei, w, r;
  double onset() const { return 2.0 * std::sqrt(ei * w / r); }               // Dawson–Paslay, sin I = 1
  double half_wave() const { return kPi * std::pow(ei * r / w, 0.25); }      // π (EI r / w)^¼
};

Reference DawsonPaslay() {
  Reference ref;
  ref.ei = kE * kPi * (std::pow(kOd, 4) - std::pow(kId, 4)) / 64.0;
  ref.w = kDensity * kGravity * kPi * (kOd * kOd - kId * kId) / 4.0;
  ref.r = 0.5 * (kHole - kOd);
  return ref;
}

struct Onset {
  std::size_t sample = 0;  // the first sample past the level; 0: never
  double load = 0.0;       // the axial compression there, N
};

// The first sample at which the largest |lateral_y| over the probes exceeds `level` (m).
Onset Detect(const CsvColumns& csv, int probes, double level) {
  const auto& time = csv["time"];
  Onset onset;
  for (std::size_t i = 0; i < time.size() && onset.sample == 0; ++i) {
    for (int p = 1; p <= probes; ++p) {
      if (std::abs(csv["probe" + std::to_string(p) + "_lateral_y"][i]) > level) {
        onset.sample = i;
        onset.load = -csv["hook_load"][i];  // the block pushes: the hook load is the compression's negative
        break;
      }
    }
  }
  return onset;
}

TEST(V3HorizontalBuckling, SinusoidalOnsetBySlowCompressionWithin10PercentOfDawsonPaslay) {
  const auto results = RunCaseTimed("transient", kCase);
  ASSERT_TRUE(results.contains("transient"));
  const CsvColumns csv = ReadCsv(ResultsDirectory(kCase) + "/transient.csv");
  const auto& probe_s = results["transient"]["probes"];
  const int probes = static_cast<int>(probe_s.size());
  const Reference ref = DawsonPaslay();
  const Onset onset = Detect(csv, probes, 0.1 * ref.r), later = Detect(csv, probes, 0.25 * ref.r);
  ASSERT_GT(onset.sample, 0u) << "the pipe never left the low side";
  // The sinusoid at onset: where the probes' lateral displacement changes sign (interpolated).
  std::vector<double> zeros;
  double largest = 0.0;
  for (int p = 1; p < probes; ++p) {
    const double a = csv["probe" + std::to_string(p) + "_lateral_y"][onset.sample];
    const double b = csv["probe" + std::to_string(p + 1) + "_lateral_y"][onset.sample];
    const double sa = probe_s[p - 1]["s"].get<double>(), sb = probe_s[p]["s"].get<double>();
    if ((a < 0.0) != (b < 0.0)) zeros.push_back(sa + (sb - sa) * a / (a - b));
    largest = std::max({largest, std::abs(a), std::abs(b)});
  }
  ASSERT_GE(zeros.size(), 2u) << "no sinusoid along the probes at onset";
  const double half_wave = (zeros.back() - zeros.front()) / static_cast<double>(zeros.size() - 1);
  std::printf("V3 horizontal buckling: EI %.1f N*m2, w %.4f N/m, r %.4f m: F_sin %.1f N, half-wavelength %.3f m\n",
              ref.ei, ref.w, ref.r, ref.onset(), ref.half_wave());
  std::printf("V3 horizontal buckling: onset (|y| > 0.1 r) at t = %.2f s, F = %.1f N (%+.2f %%); |y| > 0.25 r at "
              "%.1f N (%+.2f %%); at onset %zu sign changes, mean half-wavelength %.3f m (%+.1f %%), largest |y| "
              "%.2f r\n",
              csv["time"][onset.sample], onset.load, 100.0 * RelativeError(onset.load, ref.onset()), later.load,
              100.0 * RelativeError(later.load, ref.onset()), zeros.size(), half_wave,
              100.0 * RelativeError(half_wave, ref.half_wave()), largest / ref.r);
  EXPECT_LT(std::abs(RelativeError(onset.load, ref.onset())), 0.10);
  EXPECT_LT(std::abs(RelativeError(half_wave, ref.half_wave())), 0.20);
}

}  // namespace horizontal_buckling_test
}  // namespace drillflex::validation
