// The bit's directional tendency in words (case-format.md "Frames and signs"): whether the lateral
// force the bit exerts on the formation builds, drops or holds inclination and turns the well right,
// left or not at all.
//
// A component counts only above a threshold
//   F_min = kTendencyRelativeThreshold · side_force + kTendencyForceFloor
// (1 % of the side force, so that a component that is a mere fraction of a large side force is not
// read as a tendency, plus 50 N: an equilibrium in a well is converged to a residual of tens of
// newtons on a long string (stiff couplings and supports × position round-off; the bundled example
// measured |R| = 54 N), and the bit support's reaction is uncertain by as much; the walk force of
// a case symmetric about the vertical plane came out at 1e-27 N in tests/analyses/wall_offsets_test.cpp
// and ~4 N in validation/invariance_test.cpp).
#pragma once

#include <string_view>

#include "analyses/static_analysis.hpp"

namespace drillflex::analyses {

inline constexpr double kTendencyRelativeThreshold = 0.01;  // of the side force
inline constexpr double kTendencyForceFloor = 50.0;         // N

enum class InclinationTendency { Build, Drop, Hold };
enum class AzimuthTendency { Right, Left, None };

struct BitTendency {
  InclinationTendency inclination = InclinationTendency::Hold;  // from build_force
  AzimuthTendency azimuth = AzimuthTendency::None;              // from walk_force
  double threshold = 0.0;                                       // F_min, N
};

// The smallest force component that counts as a tendency, N (see above).
double TendencyThreshold(double side_force);

// build_force > F_min: Build, < −F_min: Drop, else Hold; walk_force > F_min: Right, < −F_min: Left,
// else None.
BitTendency ClassifyBitTendency(const BitReport& bit);

// "build" | "drop" | "hold" and "right" | "left" | "none".
std::string_view TendencyName(InclinationTendency tendency);
std::string_view TendencyName(AzimuthTendency tendency);

}  // namespace drillflex::analyses
