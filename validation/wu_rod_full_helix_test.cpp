// V3 of validation.md, the Wu rod-in-pipe experiment (the paper's test 3.2) on to the full helix
// (v3-wu-rod/full-helix.yaml; label `validation`, ~5 s): the onset case's rod (16 bodies of
// 0.25 m), wall friction 0.2, pushed at 0.04 mm/s to 0.8 mm (49 N). From transient.csv:
//  * the helical run of a sample: the longest stretch of consecutive probes (0.1 m apart) on the
//    wall whose contact direction turns the same way from each to the next; the helix is full at the
//    first sample whose helical run spans half the rod (the ends, held on the low side, keep about a
//    half pitch each out of it; a helix still forming spans a third or less);
//  * it forms in a snap (under displacement control the load drops as the rod jumps into it): the
//    load at full helix is the peak the load cell reads before that sample, within 10 % of the
//    44 N at which Wu saw the full helix (Wu's theory 2(2√2 − 1) sqrt(EI w / r) = 43.6 N: the load at
//    which the helix forms on loading);
//  * the load after the snap, at the first sample of the full helix, is below that peak (the screw
//    holds the displacement while the helix shortens the rod) and within 10 % of the load at which a
//    formed helix holds, Chen's 2√2 sqrt(EI w / r) = 33.7 N (Chen, Lin & Cheatham 1990; the unloading
//    branch of Wu's own theory). Against Wu's 44 N it is −19 %: reported, not within 10 %
//    (docs/validation.md V3 lists what was tried);
//  * the helix then holds: at the end the helical run still spans half the rod; it winds through at
//    least two coils, its pitch (length / coils) within 15 % of 2π sqrt(2EI/F) at the load there.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "wu_rod.hpp"

namespace drillflex::validation {
namespace {

using namespace wu;

struct HelicalRun {
  double length = 0.0;  // m
  double turn = 0.0;    // degrees, |total turn of the contact direction along it|
};

// The helical run of sample i (header).
HelicalRun LongestHelicalRun(const PushRun& run, std::size_t i) {
  const double spacing = kLength / (kProbes - 1);
  HelicalRun best;
  for (int start = 1; start <= kProbes; ++start) {
    if (!(run.Probe(start, "contact_force")[i] > 0.0)) continue;
    double turn = 0.0, sign = 0.0;
    int end = start;
    while (end < kProbes && run.Probe(end + 1, "contact_force")[i] > 0.0) {
      double step = run.Probe(end + 1, "whirl_angle")[i] - run.Probe(end, "whirl_angle")[i];
      step += step > 180.0 ? -360.0 : step < -180.0 ? 360.0 : 0.0;
      if (sign != 0.0 && step * sign <= 0.0) break;
      sign = step > 0.0 ? 1.0 : -1.0;
      turn += step;
      ++end;
    }
    if ((end - start) * spacing > best.length) best = {(end - start) * spacing, std::abs(turn)};
  }
  return best;
}

TEST(V3WuRod, LoadAtFullHelixWithin10PercentOf44N) {
  const auto results = RunCase("transient", "v3-wu-rod/full-helix.yaml");
  ASSERT_TRUE(results.contains("transient"));
  const PushRun run = ReadRun("full-helix", 4e-5);  // pushed at 0.04 mm/s
  const Rod rod;
  std::size_t full = 0;
  for (std::size_t i = 0; i < run.time.size() && full == 0; ++i) {
    if (LongestHelicalRun(run, i).length >= 0.5 * kLength) full = i;
  }
  ASSERT_GT(full, 0u) << "no full helix";
  const std::size_t peak = std::max_element(run.load.begin(), run.load.begin() + full) - run.load.begin();
  const std::size_t last = run.time.size() - 1;
  const HelicalRun end = LongestHelicalRun(run, last);
  const double coils = end.turn / 360.0, pitch = end.length / coils;
  const double pitch_reference = 2.0 * kPi * std::sqrt(2.0 * rod.ei / run.load[last]);
  const double wu_full_helix = 44.0;  // N, seen in the experiment
  const double chen_helix = 2.0 * std::sqrt(2.0) * std::sqrt(rod.ei * rod.w / rod.r);  // 33.7 N
  const double after = run.load[full];
  std::printf("V3 Wu rod, full helix: spans half the rod at t = %.2f s (d = %.3f mm, load %.2f N after the snap); "
              "peak before it %.2f N at %.2f s against 44 N (%+.2f %%); at the end (%.2f N, d = %.3f mm) %.2f coils "
              "over %.1f m, pitch %.3f m against 2 pi sqrt(2EI/F) = %.3f m (%+.1f %%)\n",
              run.time[full], 1e3 * run.travel[full], run.load[full], run.load[peak], run.time[peak],
              100.0 * RelativeError(run.load[peak], wu_full_helix), run.load[last], 1e3 * run.travel[last], coils,
              end.length, pitch, pitch_reference, 100.0 * RelativeError(pitch, pitch_reference));
  std::printf("  after the snap %.2f N: against Chen's %.2f N %+.1f %%, against Wu's 44 N %+.1f %%\n", after, chen_helix,
              100.0 * RelativeError(after, chen_helix), 100.0 * RelativeError(after, wu_full_helix));
  EXPECT_LT(std::abs(RelativeError(run.load[peak], wu_full_helix)), 0.10);
  EXPECT_LT(after, run.load[peak]);
  // A formed helix holds at or above Chen's load (within 10 %): the lower bound theory gives. How far
  // above it the load sits after the snap depends on the rig's stiffness, which the sources do not give.
  EXPECT_GT(after, 0.9 * chen_helix);
  EXPECT_GE(end.length, 0.5 * kLength);
  EXPECT_GE(coils, 2.0);
  EXPECT_LT(std::abs(RelativeError(pitch, pitch_reference)), 0.15);
}

}  // namespace
}  // namespace drillflex::validation
