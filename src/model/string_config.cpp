#include "model/string_config.hpp"

#include <algorithm>

namespace drillflex::model {

double ContactDiameter(const Component& component) {
  double diameter = component.outer_diameter;
  if (component.blade_diameter) diameter = std::max(diameter, *component.blade_diameter);
  if (component.joint_diameter) diameter = std::max(diameter, *component.joint_diameter);
  return diameter;
}

double StringLength(const StringConfig& string) {
  double length = 0.0;
  for (const Component& component : string.components) length += component.length * component.count;
  return length;
}

AveragedAreas AverageAreas(const Component& component) {
  auto circle = [](double diameter) { return kPi * diameter * diameter / 4.0; };
  AveragedAreas areas{circle(component.outer_diameter) - circle(component.inner_diameter),
                      circle(component.outer_diameter), circle(component.inner_diameter)};
  if (component.joint_diameter) {
    const double spacing = component.joint_spacing.value_or(std::min(kDefaultJointSpacing, component.length));
    const double fraction = std::min(1.0, component.joint_length.value_or(kDefaultJointLength) / spacing);
    const double joint_bore = component.joint_inner_diameter.value_or(component.inner_diameter);
    const AveragedAreas joint{circle(*component.joint_diameter) - circle(joint_bore),
                              circle(*component.joint_diameter), circle(joint_bore)};
    areas.material += fraction * (joint.material - areas.material);
    areas.outer += fraction * (joint.outer - areas.outer);
    areas.bore += fraction * (joint.bore - areas.bore);
  }
  return areas;
}

const char* ComponentTypeName(ComponentType type) {
  switch (type) {
    case ComponentType::Bit: return "bit";
    case ComponentType::Stabilizer: return "stabilizer";
    case ComponentType::Collar: return "collar";
    case ComponentType::Hwdp: return "hwdp";
    case ComponentType::Pipe: return "pipe";
    case ComponentType::Mwd: return "mwd";
    case ComponentType::Lwd: return "lwd";
    case ComponentType::Jar: return "jar";
    case ComponentType::Motor: return "motor";
    case ComponentType::Sub: return "sub";
    case ComponentType::Crossover: return "crossover";
  }
  return "component";
}

}  // namespace drillflex::model
