// A bent motor's three-point geometric yield, the field's quick check (tendency.md; Marchand &
// Kalantari, SPE 166457, on where it under-predicts): the circle through the bit, the highest blade
// below the bend (or the bend itself) and the first blade above it, the string rigid and the
// clearances ignored. With the bit at 0, that contact at a, the bend of θ at b and the blade above at
// L (from the bit): the lower section's line through the bit and a, turned by θ at b, meets the
// circle y = κ x²/2 at L when
//   κ = 2 θ (L − b) / (L (L − a))        (2 θ / L with the bend as the contact, a = b),
// toward the bend's toolface. The geometry's own assumption: the line between the contacts stays
// inside the hole (a long span between the bend and the blade above does not: docs/validation.md V9).
#pragma once

#include <optional>

#include "model/string_config.hpp"

namespace drillflex::analyses {

struct ThreePointYield {
  double curvature = 0.0;   // κ, 1/m
  double toolface = 0.0;    // rad: 0 the high side, π/2 the right
  double pad = 0.0;         // a, m from the bit
  double bend = 0.0;        // b, m
  double stabilizer = 0.0;  // L, m
};

// For the string's first bent motor with a blade above its bend; none otherwise.
std::optional<ThreePointYield> ComputeThreePointYield(const model::StringConfig& string);

// For a bend of `angle` (rad) at `bend_to_bit` (m) toward `toolface` (rad) in `string`, its blades the
// contacts (a motor's bent housing, a point-the-bit system's shaft at its fulcrum); none without a blade
// above the bend.
std::optional<ThreePointYield> ThreePointYieldOfBend(const model::StringConfig& string, double bend_to_bit,
                                                     double angle, double toolface);

}  // namespace drillflex::analyses
