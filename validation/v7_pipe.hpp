// The V7 drill pipe of validation.md (validation/v7-torque-drag, v7-hook-load): 5 in × 4.276 in pipe
// with 6-5/8 in tool joints, a uniform pipe of buoyed weight 16.523 lb/ft in a straight hole at 60°,
// μ = 0.25.
#pragma once

#include <gtest/gtest.h>

#include "field_units.hpp"

namespace drillflex::validation {

constexpr double kV7BuoyedWeight = 16.523;  // lbf/ft, validation.md V7
constexpr double kV7Inclination = 60.0 * kDegree;
constexpr double kV7Friction = 0.25;

// The cases' own buoyed weight, lbf/ft: the joints (bore 6.09711 in) have the body's metal area, so
// the pipe is uniform; the cases' material density (8424.0164 kg/m³) in 10 ppg mud, inside and out.
inline double V7CaseBuoyedWeight() {
  const double fraction = 1.5 / 30.0;  // 18 in of joint per 30 ft
  const double body = CircleArea(5.0) - CircleArea(4.276);
  const double joint = CircleArea(6.625) - CircleArea(6.09711);
  EXPECT_NEAR(joint, body, 1e-4 * body);
  const double area = body + fraction * (joint - body);  // 5.274596 in²
  return PoundsPerFoot(area, 8424.0164 - 10.0 * kKgPerCubicMetrePerPpg);
}

}  // namespace drillflex::validation
