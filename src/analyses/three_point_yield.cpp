#include "analyses/three_point_yield.hpp"

#include <vector>

namespace drillflex::analyses {

std::optional<ThreePointYield> ComputeThreePointYield(const model::StringConfig& string) {
  const model::Component* motor = nullptr;
  std::vector<double> blades;  // the blades' middles, m from the bit (each item of a count)
  double s = 0.0;
  for (const model::Component& component : string.components) {
    if (!motor && component.bend_angle && component.bend_to_bit && *component.bend_angle > 0.0) motor = &component;
    for (int item = 0; item < component.count; ++item) {
      if (component.blade_diameter) blades.push_back(s + (item + 0.5) * component.length);
    }
    s += component.length * component.count;
  }
  if (!motor) return std::nullopt;
  ThreePointYield yield;
  yield.bend = *motor->bend_to_bit;
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
  yield.curvature = 2.0 * *motor->bend_angle * (l - b) / (l * (l - a));
  yield.toolface = motor->toolface.value_or(0.0);
  return yield;
}

}  // namespace drillflex::analyses
