// V7's references (validation.md; the derivation in torque_drag_test.cpp's header) and the check of
// a rotating off-bottom static case against them, shared by the 10,000 ft case and the 1000 ft one.
#pragma once

#include <cmath>
#include <cstdio>

#include "v7_pipe.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {

constexpr double kBuoyedWeight = kV7BuoyedWeight;  // lbf/ft
constexpr double kHookLoad = 82615.0;               // lbf, w_b L cos I
constexpr double kJohancsikTorque = 9875.0;         // ft·lbf, μ w_b L sin I r_joint
constexpr double kFriction = kV7Friction;
// 9,580 ft·lbf: the rotating pipe climbs the wall, N = w_b sin I / sqrt(1 + μ²).
inline const double kTorque = kJohancsikTorque / std::sqrt(1.0 + kFriction * kFriction);

// The rotating check on `file`, a `length_ft` long section (the references scale with L).
inline void CheckRotatingOffBottom(const char* file, double length_ft) {
  const double scale = length_ft / 10000.0;
  const auto results = RunCaseTimed("static", file);
  ASSERT_TRUE(results.contains("static"));
  EXPECT_TRUE(results["static"]["converged"].get<bool>());
  const auto& top = results["static"]["nodes"].back();
  // The sign of the torque follows the rotation; the reference is its magnitude.
  const double torque = std::abs(top["torque"].get<double>());
  const double hook = top["axial_force"].get<double>();
  EXPECT_LT(std::abs(RelativeError(torque, scale * kTorque)), 0.02) << torque << " ft*lbf";
  EXPECT_LT(std::abs(RelativeError(hook, scale * kHookLoad)), 0.01) << hook << " lbf";
  const double climb = 180.0 - std::atan(kFriction) / kDegree;  // 165.96°
  for (const auto& contact : results["static"]["contacts"]) {
    EXPECT_NEAR(contact["high_side_angle"].get<double>(), climb, 1.5) << contact;
  }
  std::printf("V7 rotating, %.0f ft: top torque %.1f ft*lbf (reference %.0f, %+.3f %%; Johancsik %.0f, %+.3f %%), "
              "hook load %.1f lbf (%+.3f %%)\n",
              length_ft, torque, scale * kTorque, 100.0 * RelativeError(torque, scale * kTorque),
              scale * kJohancsikTorque, 100.0 * RelativeError(torque, scale * kJohancsikTorque), hook,
              100.0 * RelativeError(hook, scale * kHookLoad));
}

}  // namespace drillflex::validation
