// Peaks and windows of a critical-speed map (analyses/critical_speeds.hpp) on curves whose answer
// is known by construction.
#include "analyses/critical_speeds.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace drillflex::analyses {
namespace critical_speeds_test {

TEST(CriticalSpeeds, TwoResonancesOfASumOfOscillatorsArePeaksAndARippleIsNot) {
  // |H| of two lightly damped oscillators at 10 and 30, sampled at 0..40 step 0.5, plus a 1 %
  // ripple: two prominent peaks, at the sample nearest each resonance.
  std::vector<double> curve;
  for (int i = 0; i <= 80; ++i) {
    const double w = 0.5 * i;
    auto response = [&](double wn, double zeta) {
      return 1.0 / std::hypot(wn * wn - w * w, 2.0 * zeta * wn * w);
    };
    curve.push_back(100.0 * response(10.0, 0.05) + 1800.0 * response(30.0, 0.05) + 0.01 * std::sin(7.0 * w));
  }
  const auto peaks = FindProminentPeaks(curve, 0.1);
  ASSERT_EQ(peaks.size(), 2u);
  EXPECT_EQ(peaks[0], 20u);
  EXPECT_EQ(peaks[1], 60u);
  // A curve that rises to the end of the sweep has no interior peak.
  EXPECT_TRUE(FindProminentPeaks({1.0, 2.0, 3.0, 4.0}, 0.1).empty());
  // A bump of 5 % of its height does not count at 10 %, does at 1 %.
  const std::vector<double> bump = {1.0, 0.96, 1.0, 0.95, 0.5};
  EXPECT_EQ(FindProminentPeaks(bump, 0.1).size(), 0u);
  EXPECT_EQ(FindProminentPeaks(bump, 0.01).size(), 1u);
}

TEST(CriticalSpeeds, RunsAreMaximalAndInclusive) {
  const auto runs = FindRuns({true, true, false, true, false, false, true});
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].first, 0u);
  EXPECT_EQ(runs[0].last, 1u);
  EXPECT_EQ(runs[1].first, 3u);
  EXPECT_EQ(runs[1].last, 3u);
  EXPECT_EQ(runs[2].first, 6u);
  EXPECT_EQ(runs[2].last, 6u);
  EXPECT_TRUE(FindRuns({false, false}).empty());
}

}  // namespace critical_speeds_test
}  // namespace drillflex::analyses
