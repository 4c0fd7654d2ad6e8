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
//    holds the displacement while the helix shortens the rod) and not more than 10 % below the load at
//    which a formed helix holds, Chen's 2√2 sqrt(EI w / r) = 33.7 N (Chen, Lin & Cheatham 1990; the unloading
//    branch of Wu's own theory). Against Wu's 44 N it is −19 %: reported, not within 10 %
//    (docs/validation.md V3 lists what was tried);
//  * the helix then holds: at the end the helical run still spans half the rod; it winds through at
//    least two coils, its pitch (length / coils) within 15 % of 2π sqrt(2EI/F) at the load there.
// The second test runs the same rod under a slow load ramp instead (full-helix-load-control.yaml):
// see its comment.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "wu_rod.hpp"

namespace drillflex::validation {
namespace wu_rod_full_helix_test {

using namespace wu;

struct HelicalRun {
  double length = 0.0;  // m
  double turn = 0.0;    // degrees, |total turn of the contact direction along it|
  double hand = 0.0;    // the sign of the turn from the blocker on (0: no turn)
};

// The helical run of sample i (header), over probes first to last (1 to kProbes: the whole rod).
HelicalRun LongestHelicalRun(const PushRun& run, std::size_t i, int first = 1, int last = kProbes) {
  const double spacing = kLength / (kProbes - 1);
  HelicalRun best;
  for (int start = first; start <= last; ++start) {
    if (!(run.Probe(start, "contact_force")[i] > 0.0)) continue;
    double turn = 0.0, sign = 0.0;
    int end = start;
    while (end < last && run.Probe(end + 1, "contact_force")[i] > 0.0) {
      double step = run.Probe(end + 1, "whirl_angle")[i] - run.Probe(end, "whirl_angle")[i];
      step += step > 180.0 ? -360.0 : step < -180.0 ? 360.0 : 0.0;
      if (sign != 0.0 && step * sign <= 0.0) break;
      sign = step > 0.0 ? 1.0 : -1.0;
      turn += step;
      ++end;
    }
    if ((end - start) * spacing > best.length) best = {(end - start) * spacing, std::abs(turn), sign};
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
  // A formed helix holds at or above Chen's load (within 10 %): the lower bound theory gives. A softer
  // loading train hardly lifts it (35.1–36.3 N from the hold down to 1e5 N/m; softer trains form no
  // one-handed helix: docs/validation.md V3).
  EXPECT_GT(after, 0.9 * chen_helix);
  EXPECT_GE(end.length, 0.5 * kLength);
  EXPECT_GE(coils, 2.0);
  EXPECT_LT(std::abs(RelativeError(pitch, pitch_reference)), 0.15);
}

// The same rod under a slow load ramp instead (v3-wu-rod/full-helix-load-control.yaml: the block's
// hook load −50 N ramped over 20 s, 2.5 N/s, a dead force at the loading end; docs/validation.md
// V3). The load cell reads the ramp; the rod turns through its first coil (a helical run turning
// 360°) at a load within 10 % of Wu's 44 N, but under the dead load both halves coil at once, as
// mirror images about the mid-length imperfection: two helices of opposite hand meeting at the
// middle, and no helical run spans half the rod by 50 N (the full helix of the test above does
// not form). The last checks pin that documented outcome: if they fail the model's behaviour has
// changed and docs/validation.md V3 with it.
TEST(V3WuRod, UnderALoadRampBothHalvesCoilAtOnceWithOppositeHands) {
  const auto results = RunCaseTimed("transient", "v3-wu-rod/full-helix-load-control.yaml");
  ASSERT_TRUE(results.contains("transient"));
  const PushRun run = ReadRun("full-helix-load-control", 0.0);  // a load ramp: no block travel
  const Rod rod;
  const double rate = 50.0 / 20.0;  // N/s
  double drive_error = 0.0;
  for (std::size_t i = 0; i < run.time.size(); ++i) {
    drive_error = std::max(drive_error, std::abs(run.load[i] - rate * run.time[i]));
  }
  EXPECT_LT(drive_error, 1e-6) << "the load cell does not read the ramp";
  std::size_t coiled = 0, full = 0;
  for (std::size_t i = 1; i < run.time.size(); ++i) {
    const HelicalRun helix = LongestHelicalRun(run, i);
    if (coiled == 0 && helix.turn >= 360.0) coiled = i;
    if (full == 0 && helix.length >= 0.5 * kLength) full = i;
  }
  ASSERT_GT(coiled, 0u) << "no coil by 50 N";
  const std::size_t last = run.time.size() - 1;
  const int middle = (kProbes + 1) / 2;  // the probe at 2 m
  const HelicalRun whole = LongestHelicalRun(run, last), blocker_half = LongestHelicalRun(run, last, 1, middle),
                   block_half = LongestHelicalRun(run, last, middle, kProbes);
  const double wu_full_helix = 44.0;                                                     // N
  const double chen_helix = 2.0 * std::sqrt(2.0) * std::sqrt(rod.ei * rod.w / rod.r);  // 33.7 N
  std::printf("V3 Wu rod, load ramp: the first coil at t = %.2f s, %.2f N (against Wu's 44 N %+.1f %%, Chen's %.2f N "
              "%+.1f %%); at %.2f N the longest helical run %.1f m (%.2f coils), the blocker's half %.1f m (%.2f coils), "
              "the block's half %.1f m (%.2f coils), %s hands\n",
              run.time[coiled], run.load[coiled], 100.0 * RelativeError(run.load[coiled], wu_full_helix), chen_helix,
              100.0 * RelativeError(run.load[coiled], chen_helix), run.load[last], whole.length, whole.turn / 360.0,
              blocker_half.length, blocker_half.turn / 360.0, block_half.length, block_half.turn / 360.0,
              blocker_half.hand * block_half.hand < 0.0 ? "opposite" : "the same");
  EXPECT_LT(std::abs(RelativeError(run.load[coiled], wu_full_helix)), 0.10);
  EXPECT_EQ(full, 0u) << "a full helix formed under the load ramp (at " << run.load[full] << " N): update V3";
  EXPECT_GE(blocker_half.turn, 360.0);
  EXPECT_GE(block_half.turn, 360.0);
  EXPECT_LT(blocker_half.hand * block_half.hand, 0.0);
}

}  // namespace wu_rod_full_helix_test
}  // namespace drillflex::validation
