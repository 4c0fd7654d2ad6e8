#include "analyses/three_point_yield.hpp"

#include <vector>

namespace drillflex::analyses {

std::optional<ThreePointYield> ComputeThreePointYield(const model::StringConfig& string) {
  for (const model::Component& component : string.components) {
    if (component.bend_angle && component.bend_to_bit && *component.bend_angle > 0.0) {
      return ThreePointYieldOfBend(string, *component.bend_to_bit, *component.bend_angle,
                                   component.toolface.value_or(0.0));
    }
  }
  return std::nullopt;
}

std::optional<ThreePointYield> ThreePointYieldOfBend(const model::StringConfig& string, double bend_to_bit,
                                                     double angle, double toolface) {
  std::vector<double> blades;  // the blades' middles, m from the bit (each item of a count)
  double s = 0.0;
  for (const model::Component& component : string.components) {
    for (int item = 0; item < component.count; ++item) {
      if (component.blade_diameter) blades.push_back(s + (item + 0.5) * component.length);
    }
    s += component.length * component.count;
  }
  ThreePointYield yield;
  yield.bend = bend_to_bit;
  yield.pad = yield.bend;
  bool above = false;
  for (const double blade : blades) {
    if (blade < yield.bend) yield.pad = blade;  // the highest below the bend (they come from the bit up)
    if (blade > yield.bend && !above) {
      yield.stabilizer = blade;
      above = true;
    }
  }
  if (!above) return std::nullopt;
  const double a = yield.pad, b = yield.bend, l = yield.stabilizer;
  yield.curvature = 2.0 * angle * (l - b) / (l * (l - a));
  yield.toolface = toolface;
  return yield;
}

}  // namespace drillflex::analyses
