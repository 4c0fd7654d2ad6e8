// V8 of validation.md, the paper's test 3.5 (v8-transient/eccentric-collar.yaml): a pinned-pinned
// 90 ft collar span with an eccentric mass (m e = 50 lb·in) at mid-span, compressed by 70 klbf (its
// Euler load π²EI/L² is 51 klbf) and carrying a constant 5000 ft·lbf torque while the top drive turns
// it at 100 rpm in a vertical 12.25 in hole without gravity. The start is the straight column; the
// spinning imbalance pushes the mid-span off the axis and the compression bows it onto the wall,
// where the wall friction throws the bow round against the rotation. Asserted, from the mid-span
// probe of transient.csv:
//  * straight at the start (offset < 0.01 in), buckled at the end: over the last 1.5 s the offset
//    stays at the wall, R_h − R_c (2.125 in) within 1 % (the penetration N/k_n is ~0.002 in), with
//    a contact force all the time;
//  * whirling backward: the wall's normal force acts along the offset, so the contact force's
//    direction is the whirl angle; its rate over the last 1.5 s (least squares of the unwrapped
//    angle) is negative, opposite to the clockwise rotation. A section that slides on the wall
//    whirls slower than one that rolls: |ω_w| ≤ Ω R_c/(R_h − R_c) = 188.24 rpm, with equality when the
//    contact point stops slipping (no friction work left). The set-up rolls (as in V8's backward
//    whirl), so the rate is compared with −188.24 rpm at 2 %;
//  * the string turns at the drive's 100 rpm (5 %) and carries the torque: the mean surface torque
//    over the window is the 5000 ft·lbf on bit within 5 % (rolling takes no friction torque).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "validation_support.hpp"
#include "whirl_support.hpp"

namespace drillflex::validation {
namespace eccentric_collar_test {

constexpr double kSpeedRpm = 100.0, kTorque = 5000.0;       // rpm, ft·lbf
constexpr double kCollarRadius = 4.0, kHoleRadius = 6.125;  // in

TEST(V8EccentricCollar, BucklesAndTheContactForceTurnsAgainstTheRotationAtTheRollingRate) {
  const auto results = RunCase("transient", "v8-transient/eccentric-collar.yaml");
  ASSERT_TRUE(results.contains("transient"));
  const CsvColumns csv = ReadCsv(std::string(DRILLFLEX_BINARY_DIR "/validation-results/v8-transient/eccentric-collar/transient.csv"));
  const auto& time = csv["time"];
  const auto& y = csv["probe1_lateral_y"];
  const auto& z = csv["probe1_lateral_z"];
  const auto& force = csv["probe1_contact_force"];
  const auto& bit_rpm = csv["bit_rpm"];
  const auto& torque = csv["surface_torque"];
  const double duration = time.back(), from = duration - 1.5;
  const double clearance = kHoleRadius - kCollarRadius;
  const std::vector<double> angle = Unwrapped(csv["probe1_whirl_angle"]);
  const double whirl_rpm = Slope(time, angle, from) / 6.0;  // deg/s → rpm
  const double rolling = -kSpeedRpm * kCollarRadius / clearance;
  double first_contact = -1.0, least_offset = 1e300, most_offset = 0.0, least_force = 1e300;
  double slowest = 1e300, fastest = -1e300, torque_sum = 0.0, turns_from = 0.0;
  int window = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (first_contact < 0.0 && force[i] > 0.0) first_contact = time[i];
    if (time[i] < from) continue;
    if (window == 0) turns_from = angle[i];
    const double offset = std::hypot(y[i], z[i]);
    least_offset = std::min(least_offset, offset);
    most_offset = std::max(most_offset, offset);
    least_force = std::min(least_force, force[i]);
    slowest = std::min(slowest, bit_rpm[i]);
    fastest = std::max(fastest, bit_rpm[i]);
    torque_sum += torque[i];
    ++window;
  }
  const double mean_torque = torque_sum / window;
  const double start_offset = std::hypot(y.front(), z.front());
  std::printf("V8 eccentric collar (test 3.5): start offset %.2e in, first wall contact at %.3f s; over the last "
              "1.5 s offset %.4f to %.4f in (clearance %.3f), contact force >= %.0f lbf, whirl %.2f rpm against "
              "rolling %.2f rpm (%+.2f %%), %.2f whirl turns, bit %.1f to %.1f rpm, mean surface torque %.0f ft*lbf "
              "(%+.2f %%)\n",
              start_offset, first_contact, least_offset, most_offset, clearance, least_force, whirl_rpm, rolling,
              100.0 * RelativeError(whirl_rpm, rolling), (angle.back() - turns_from) / 360.0, slowest, fastest,
              mean_torque, 100.0 * RelativeError(mean_torque, kTorque));
  EXPECT_LT(start_offset, 0.01);
  EXPECT_GT(first_contact, 0.0);
  EXPECT_GT(least_offset, 0.99 * clearance);
  EXPECT_LT(most_offset, 1.01 * clearance);
  EXPECT_GT(least_force, 0.0);
  EXPECT_LT(whirl_rpm, 0.0);  // against the rotation
  EXPECT_LT(std::abs(RelativeError(whirl_rpm, rolling)), 0.02);
  EXPECT_NEAR(slowest, kSpeedRpm, 0.05 * kSpeedRpm);
  EXPECT_NEAR(fastest, kSpeedRpm, 0.05 * kSpeedRpm);
  EXPECT_LT(std::abs(RelativeError(mean_torque, kTorque)), 0.05);
}

}  // namespace eccentric_collar_test
}  // namespace drillflex::validation
