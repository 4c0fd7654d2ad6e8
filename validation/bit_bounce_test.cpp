// V8 of validation.md, bit bounce (v8-transient/bit-bounce.yaml): a uniform bar of length L clamped
// at its top rests with its bit on the hole bottom, a contact spring k (damper c), under a static
// WOB W0; the bottom moves as a sin(Ωt). While the contact is closed the bar and the spring are
// linear, and the exact steady response of the continuous bar (longitudinal waves, e.g. Graff, Wave
// Motion in Elastic Solids, 1975, §2.1) gives the contact force's amplitude: the bar's end
// stiffness at Ω is K_d = EA κ cot(κL), κ = Ω/c, c = sqrt(E/ρ), and the spring k̃ = k + iΩc in
// series with it carries F = a k̃ K_d/(K_d + k̃). The contact force W0 + F_a sin(...) reaches zero,
// and the bit leaves the bottom, at a_onset = W0/|k̃ K_d/(K_d + k̃)|. The test runs drillflex's
// transient at 0.95 and 1.05 a_onset: the contact must stay closed below and open above (the onset
// within 5 %), the contact force's amplitude below it must give a_onset within 1 %, and the
// onset bisected between them (whether the contact opens) within 1 %. Each run ~0.2 s.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "validation_support.hpp"

namespace drillflex::validation {
namespace bit_bounce_test {

constexpr double kPi = 3.14159265358979323846;
// The case's figures (SI).
constexpr double kE = 2.1e11, kDensity = 7800.0, kDiameter = 0.1, kLength = 100.0;
constexpr double kContactStiffness = 2e7, kDampingRatio = 0.02, kWob = 50e3;
constexpr double kFrequency = 10.0, kRampEnd = 1.0, kDuration = 2.0;
// The bit body (1 m, 2 elements): the contact's damping c = 2ζ sqrt(k m), m one element's mass.
constexpr double kBitElementLength = 0.5;

// The contact force's amplitude per unit bottom amplitude, N/m.
double ForcePerAmplitude() {
  const double area = kPi * kDiameter * kDiameter / 4.0;
  const double omega = 2.0 * kPi * kFrequency;
  const double kappa = omega / std::sqrt(kE / kDensity);
  const double end_stiffness = kE * area * kappa / std::tan(kappa * kLength);  // K_d
  const double damping = 2.0 * kDampingRatio * std::sqrt(kContactStiffness * kDensity * area * kBitElementLength);
  const std::complex<double> spring(kContactStiffness, omega * damping);
  return std::abs(spring * end_stiffness / (end_stiffness + spring));
}

// The bar's first natural frequency on the bottom spring (EA κ cot κL = −k), by bisection on
// (π/2, π), rad/s: how far the excitation sits below it.
double NaturalFrequency() {
  const double area = kPi * kDiameter * kDiameter / 4.0, wave = std::sqrt(kE / kDensity);
  const auto f = [&](double x) { return kE * area / kLength * x / std::tan(x) + kContactStiffness; };
  double lo = 0.5 * kPi + 1e-9, hi = kPi - 1e-9;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) * wave / kLength;
}

struct Bounce {
  double smallest = 0.0, largest = 0.0;  // the contact force over the steady part, N
  bool opened = false;                   // the contact force reached 0 at some sample
};

// Runs the case with the bottom's amplitude set to `amplitude` (m).
Bounce RunAt(double amplitude, const std::string& name) {
  std::ifstream in(CasePath("v8-transient/bit-bounce.yaml"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string variant = std::regex_replace(text.str(), std::regex(R"(amplitude: [0-9.]+ mm)"),
                                                 fmt::format("amplitude: {:.9g} m", amplitude));
  EXPECT_NE(variant, text.str()) << "the case's bottom amplitude was not found to vary";
  const std::string path = ResultsDirectory("v8-transient/bit-bounce") + "-" + name + ".yaml";
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << variant;
  const auto results = RunCase("transient", path);
  const CsvColumns csv = ReadCsv(std::filesystem::path(path).replace_extension().string() + "/transient.csv");
  Bounce b;
  b.smallest = 1e300;
  b.largest = -1e300;
  const auto& time = csv["time"];
  const auto& wob = csv["wob"];
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (wob[i] <= 0.0) b.opened = true;
    if (time[i] < kRampEnd + 0.2) continue;
    b.smallest = std::min(b.smallest, wob[i]);
    b.largest = std::max(b.largest, wob[i]);
  }
  EXPECT_NEAR(time.back(), kDuration, 1e-9);
  return b;
}

TEST(BitBounce, OnsetAmplitudeMatchesTheContinuousBar) {
  const double per_amplitude = ForcePerAmplitude();
  const double onset = kWob / per_amplitude;
  std::printf("bit bounce: first mode %.3f Hz, excitation %.3f Hz; contact force %.5g N per m of bottom motion; "
              "onset amplitude %.5g mm\n",
              NaturalFrequency() / (2.0 * kPi), kFrequency, per_amplitude, 1e3 * onset);
  ASSERT_NEAR(1e3 * onset, 9.154, 0.001);  // the figure the case file states
  const Bounce below = RunAt(0.95 * onset, "below");
  const Bounce above = RunAt(1.05 * onset, "above");
  // Below the onset the bit stays on bottom; its contact force swings by F_a about W0.
  EXPECT_FALSE(below.opened) << "smallest contact force " << below.smallest << " N";
  const double swing = 0.5 * (below.largest - below.smallest);
  const double mean = 0.5 * (below.largest + below.smallest);
  const double measured_onset = 0.95 * onset * kWob / swing;
  std::printf("  at 0.95 a_onset: contact force %.5g .. %.5g N (mean %.5g, W0 %.5g), swing %.5g N against %.5g: "
              "onset %.5g mm, %+.3f %% off\n",
              below.smallest, below.largest, mean, kWob, swing, 0.95 * onset * per_amplitude, 1e3 * measured_onset,
              100.0 * RelativeError(measured_onset, onset));
  EXPECT_NEAR(RelativeError(measured_onset, onset), 0.0, 0.01);  // measured −0.32 % (validation.md)
  EXPECT_NEAR(RelativeError(mean, kWob), 0.0, 0.01);  // the static WOB the contact took over at t = 0
  // Above it the bit leaves the bottom.
  EXPECT_TRUE(above.opened) << "smallest contact force " << above.smallest << " N";
  std::printf("  at 1.05 a_onset: smallest contact force %.5g N (the contact opened: %s)\n", above.smallest,
              above.opened ? "yes" : "no");
  // The onset itself, bisected between the two (6 halvings: to 0.16 % of a_onset).
  double closed = 0.95 * onset, open = 1.05 * onset;
  for (int i = 0; i < 6; ++i) {
    const double mid = 0.5 * (closed + open);
    (RunAt(mid, "bisection").opened ? open : closed) = mid;
  }
  const double bisected = 0.5 * (closed + open);
  std::printf("  bisected onset %.5g mm (between %.5g and %.5g), %+.3f %% off\n", 1e3 * bisected, 1e3 * closed,
              1e3 * open, 100.0 * RelativeError(bisected, onset));
  // Within 1 % (measured −0.39 %): the bracket itself is ±5 %, so a 5 % check could not fail.
  EXPECT_NEAR(RelativeError(bisected, onset), 0.0, 0.01);
}

}  // namespace bit_bounce_test
}  // namespace drillflex::validation
