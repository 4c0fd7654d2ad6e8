// V8 of validation.md, backward whirl: an 8 in collar rolling without slip in a 12.25 in hole at
// 100 rpm whirls at −Ω R_c/(R_h − R_c) = −188.24 rpm (the contact point at rest: the centre goes
// round at ω_w e = −Ω R_c, e = R_h − R_c). The case (v8-transient/backward-whirl.yaml): a 90 ft
// collar span buckled onto the wall of a vertical hole by the WOB, turned by the top drive. The whirl
// rate is the slope of the mid-span probe's unwrapped whirl angle over the last 1.5 s (least
// squares), within 2 % of the reference; over that window the probe stays on the wall and the string
// turns at the drive's 100 rpm.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "validation_support.hpp"
#include "whirl_support.hpp"

namespace drillflex::validation {
namespace backward_whirl_test {

constexpr double kSpeedRpm = 100.0;
constexpr double kCollarRadius = 4.0, kHoleRadius = 6.125;  // in

TEST(V8BackwardWhirl, RollingCollarWhirlsAtMinusOmegaRcOverClearanceWithin2Percent) {
  const auto results = RunCase("transient", "v8-transient/backward-whirl.yaml");
  ASSERT_TRUE(results.contains("transient"));
  const CsvColumns csv =
      ReadCsv(std::string(DRILLFLEX_BINARY_DIR "/validation-results/v8-transient/backward-whirl/transient.csv"));
  const auto& time = csv["time"];
  const double duration = time.back(), from = duration - 1.5;
  const std::vector<double> angle = Unwrapped(csv["probe1_whirl_angle"]);
  const double whirl_rpm = Slope(time, angle, from) / 6.0;  // deg/s → rpm
  const double reference = -kSpeedRpm * kCollarRadius / (kHoleRadius - kCollarRadius);
  // Over the window: on the wall all the time, turning at the drive's speed.
  double least_force = 1e300, slowest = 1e300, fastest = -1e300;
  const auto& force = csv["probe1_contact_force"];
  const auto& bit_rpm = csv["bit_rpm"];
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < from) continue;
    least_force = std::min(least_force, force[i]);
    slowest = std::min(slowest, bit_rpm[i]);
    fastest = std::max(fastest, bit_rpm[i]);
  }
  std::printf("V8 backward whirl: %.2f rpm against %.2f rpm (%+.2f %%); over the last 1.5 s the mid-span "
              "contact force >= %.0f lbf, bit %.1f to %.1f rpm; %.1f whirl turns in %.1f s\n",
              whirl_rpm, reference, 100.0 * RelativeError(whirl_rpm, reference), least_force, slowest, fastest,
              (angle.front() - angle.back()) / 360.0, duration);
  EXPECT_LT(std::abs(RelativeError(whirl_rpm, reference)), 0.02);
  EXPECT_GT(least_force, 0.0);
  EXPECT_NEAR(slowest, kSpeedRpm, 0.05 * kSpeedRpm);
  EXPECT_NEAR(fastest, kSpeedRpm, 0.05 * kSpeedRpm);
}

}  // namespace backward_whirl_test
}  // namespace drillflex::validation
