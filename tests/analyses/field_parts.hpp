// String components in field units for the analyses' tests of strings in a well.
#pragma once

#include "model/string_config.hpp"

namespace drillflex::analyses::testing {

inline constexpr double kIn = 0.0254, kFt = 0.3048, kLbf = 4.4482216152605;

// A component of `count` joints of `length_ft`, OD and ID in inches.
inline model::Component Part(model::ComponentType type, double od_in, double id_in, double length_ft, int count = 1) {
  model::Component part;
  part.type = type;
  part.outer_diameter = od_in * kIn;
  part.inner_diameter = id_in * kIn;
  part.length = length_ft * kFt;
  part.count = count;
  return part;
}

}  // namespace drillflex::analyses::testing
