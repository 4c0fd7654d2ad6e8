// Exact unit factors for the validation references written in field units (NIST SP 811).
#pragma once

#include "core/types.hpp"

namespace drillflex::validation {

constexpr double kMetresPerFoot = 0.3048;
constexpr double kMetresPerInch = 0.0254;
constexpr double kNewtonsPerPoundForce = 4.4482216152605;      // lbf = lb x 9.80665 m/s²
constexpr double kKgPerCubicMetrePerPpg = 119.826427316897;    // lb/US gal: 0.45359237 / 3.785411784e-3
constexpr double kKgPerCubicMetrePerPoundPerCubicInch = 27679.9047102;  // 0.45359237 / 0.0254³
constexpr double kStandardGravity = 9.80665;                  // m/s², the cases' `gravity`

// With g = 9.80665 m/s², a weight per length in lbf/ft is the mass per length in lb/ft:
// area (in²) × 12 in/ft × density (lb/in³).
inline double PoundsPerFoot(double area_in2, double density_kg_m3) {
  return area_in2 * 12.0 * density_kg_m3 / kKgPerCubicMetrePerPoundPerCubicInch;
}

inline double CircleArea(double diameter) { return kPi * diameter * diameter / 4.0; }

}  // namespace drillflex::validation
