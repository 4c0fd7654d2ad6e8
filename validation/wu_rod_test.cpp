// V3 of validation.md, the Wu rod-in-pipe experiment (the paper's test 3.2), its sinusoidal onset
// (v3-wu-rod/sinusoidal-onset.yaml): a 4 m brass rod (3.2 mm, E = 105 GPa, ρ = 8500 kg/m³) on the
// low side of a horizontal 8.3 mm pipe, the blocker end fixed, the loading end pushed in at 0.1 mm/s
// by the block (displacement control, as the screw). From transient.csv:
//  * the straight rod: the load against the loading end's displacement d = ∫ v dt rises at EA/L
//    (least squares below 15 N), within 1 %;
//  * the onset: the load where the curve leaves that line, i.e. where the secant stiffness over the
//    last 0.05 s falls below 90 % of EA/L, within 10 % of Dawson–Paslay's F_sin = 2 sqrt(EI w / r)
//    = 23.84 N; below 0.9 F_sin the rod lies straight (sideways offsets under 0.1 r: the response to
//    the 0.01 N imperfection);
//  * the shape at the end (34 N): sinusoidal, not helical: every contact within 90° of the low side
//    (the rod never passes the pipe's side), sideways offsets up to r/2 or more, and as many
//    half-waves as L over the half-pitch π sqrt(2EI/F) (Lubinski's p = 2π sqrt(2EI/F)), ± 1.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "wu_rod.hpp"

namespace drillflex::validation {
namespace wu_rod_test {

using namespace wu;

TEST(V3WuRod, SinusoidalOnsetWithin10PercentOfDawsonPaslay) {
  const auto results = RunCase("transient", "v3-wu-rod/sinusoidal-onset.yaml");
  ASSERT_TRUE(results.contains("transient"));
  const PushRun run = ReadRun("sinusoidal-onset", 1e-4);  // pushed at 0.1 mm/s
  const Rod rod;
  const double ei = rod.ei, r = rod.r, f_sin = rod.f_sin, axial = rod.axial;
  const auto& time = run.time;
  const auto& load = run.load;
  const auto& travel = run.travel;
  std::vector<double> sideways;
  for (std::size_t i = 0; i < time.size(); ++i) {
    double largest = 0.0;
    for (int p = 1; p <= kProbes; ++p) largest = std::max(largest, std::abs(run.Probe(p, "lateral_y")[i]));
    sideways.push_back(largest);
  }
  // The straight rod's stiffness: least squares of load on travel, after the ramp, below 15 N.
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < 2.0 * kRamp || load[i] > 15.0) continue;
    n += 1.0, sx += travel[i], sy += load[i], sxx += travel[i] * travel[i], sxy += travel[i] * load[i];
  }
  const double stiffness = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  // The onset: the secant stiffness over 5 samples (0.05 s) falls below 0.9 EA/L.
  double onset = -1.0, straight_sideways = 0.0;
  for (std::size_t i = 5; i < time.size() && onset < 0.0; ++i) {
    if (load[i] < 10.0) continue;
    const double secant = (load[i] - load[i - 5]) / (travel[i] - travel[i - 5]);
    if (secant < 0.9 * axial) onset = load[i];
  }
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (load[i] < 0.9 * f_sin) straight_sideways = std::max(straight_sideways, sideways[i]);
  }
  // The shape at the end: half-waves of the sideways offset along the rod, contacts' directions.
  const std::size_t last = time.size() - 1;
  int half_waves = 1;
  double farthest_from_low_side = 0.0;
  for (int p = 1; p <= kProbes; ++p) {
    if (run.Probe(p, "contact_force")[last] > 0.0) {
      farthest_from_low_side = std::max(farthest_from_low_side, std::abs(run.Probe(p, "whirl_angle")[last] - 180.0));
    }
    if (p > 2 && p < kProbes) {  // interior sign changes (the ends sit at y = 0)
      const double a = run.Probe(p - 1, "lateral_y")[last], b = run.Probe(p, "lateral_y")[last];
      if (a * b < 0.0) ++half_waves;
    }
  }
  const double half_pitch = kPi * std::sqrt(2.0 * ei / load[last]);
  std::printf("V3 Wu rod: EA/L %.0f N/m against %.0f (%+.2f %%); onset at %.2f N against F_sin %.2f N (%+.2f %%); "
              "below 0.9 F_sin sideways <= %.3f r; at %.2f N (d = %.3f mm) %d half-waves against L / pi sqrt(2EI/F) = "
              "%.2f, sideways %.2f r, contacts within %.1f deg of the low side\n",
              stiffness, axial, 100.0 * RelativeError(stiffness, axial), onset, f_sin,
              100.0 * RelativeError(onset, f_sin), straight_sideways / r, load[last], 1e3 * travel[last], half_waves,
              kLength / half_pitch, sideways[last] / r, farthest_from_low_side);
  EXPECT_LT(std::abs(RelativeError(stiffness, axial)), 0.01);
  ASSERT_GT(onset, 0.0);
  EXPECT_LT(std::abs(RelativeError(onset, f_sin)), 0.10);
  EXPECT_LT(straight_sideways, 0.1 * r);
  EXPECT_GT(sideways[last], 0.5 * r);
  EXPECT_LT(farthest_from_low_side, 90.0);
  EXPECT_NEAR(half_waves, kLength / half_pitch, 1.0);
}

}  // namespace wu_rod_test
}  // namespace drillflex::validation
