#include "model/string_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "well/hole.hpp"

namespace drillflex::model {

// Buoyed weight per length, N/m (method.md §7): g (ρ_s A − ρ_f A_o + ρ_f,i A_i).
// Areas averaged over tool joints (model/string_config.hpp AverageAreas); the density of the body
// already holds the joints' steel.
double BuoyedWeightPerLength(const Body& body, const ModelInput& input) {
  const auto& spec = body.reduced->spec;
  double mass_per_length = spec.material.density * spec.section.area();
  if (input.fluid) {
    const AveragedAreas areas = AverageAreas(input.string.components.at(body.component));
    const double inside = input.fluid->internal_density.value_or(input.fluid->density);
    mass_per_length += inside * areas.bore - input.fluid->density * areas.outer;
  }
  return input.gravity * mass_per_length;
}

double BuoyedWeightPerLength(const Component& component, const ModelInput& input) {
  const AveragedAreas areas = AverageAreas(component);
  double mass_per_length = input.materials.at(component.material).density * areas.material;
  if (input.fluid) {
    const double inside = input.fluid->internal_density.value_or(input.fluid->density);
    mass_per_length += inside * areas.bore - input.fluid->density * areas.outer;
  }
  return input.gravity * mass_per_length;
}

double StringAboveWeight(const ModelInput& input) {
  if (!input.well || input.string.components.empty()) return 0.0;
  const double top_md = input.bit_md - StringLength(input.string);
  if (top_md <= input.well->trajectory.start_md()) return 0.0;
  const double tvd = input.well->trajectory.Position(top_md).z() -
                     input.well->trajectory.Position(input.well->trajectory.start_md()).z();
  return BuoyedWeightPerLength(input.string.components.back(), input) * tvd;
}

double ModelledStringAxialWeight(const ModelInput& input) {
  if (!input.well) return 0.0;
  double weight = 0.0;
  // Each component's weight along the hole: w (TVD at its bottom − TVD at its top).
  double md = input.bit_md;
  for (const Component& component : input.string.components) {
    const double length = component.length * component.count;
    weight += BuoyedWeightPerLength(component, input) *
              (input.well->trajectory.Position(md).z() - input.well->trajectory.Position(md - length).z());
    md -= length;
  }
  return weight;
}

double WeightOnBitFromHookLoad(const ModelInput& input, double hook_load) {
  return StringAboveWeight(input) + ModelledStringAxialWeight(input) - hook_load;
}

// The component at a distance s from the bit; at a connection the lower one, except on top of
// the bit, where it is the upper one (the bit's gauge is at its bottom, where its support holds it
// at the hole centre: a full-gauge contact at its top would be a false fulcrum).
const Component& ComponentAt(const StringConfig& string, double s) {
  double start = 0.0;
  for (const Component& component : string.components) {
    const double span = component.length * component.count;
    const bool above_bit = component.type == ComponentType::Bit && s >= start + span - 1e-9;
    if (s > start + span + 1e-9 || (above_bit && &component != &string.components.back())) {
      start += span;
      continue;
    }
    return component;
  }
  return string.components.back();
}

// The contact diameter at a distance s from the bit: the blade OD over a stabilizer's blades
// (centred on the stabilizer when their length is given, else over all of it), the tool-joint OD
// within half a joint length of a pipe connection, the body OD elsewhere (ComponentAt).
double ContactDiameterAt(const StringConfig& string, double s) {
  const Component& component = ComponentAt(string, s);
  double start = 0.0;
  for (const Component& c : string.components) {
    if (&c == &component) break;
    start += c.length * c.count;
  }
  const double span = component.length * component.count;
  const double local = std::clamp(s - start, 0.0, span);
  const double within_item = std::fmod(local, component.length);
  if (component.blade_diameter) {
    const double blades = component.blade_length.value_or(component.length);
    if (std::abs(within_item - 0.5 * component.length) <= 0.5 * blades + 1e-9) return *component.blade_diameter;
  }
  if (component.joint_diameter) {
    const double spacing = component.joint_spacing.value_or(std::min(kDefaultJointSpacing, component.length));
    const double half_joint = 0.5 * component.joint_length.value_or(kDefaultJointLength);
    const double to_connection = std::fmod(local, spacing);
    if (std::min(to_connection, spacing - to_connection) <= half_joint + 1e-9) return *component.joint_diameter;
  }
  return component.outer_diameter;
}

std::optional<double> RadialClearanceAt(const ModelInput& input, double s) {
  if (!input.well || input.well->hole.empty()) return std::nullopt;
  const double hole = input.well->hole.Diameter(input.bit_md - s);
  return 0.5 * (hole - ContactDiameterAt(input.string, s));
}

Mat3 BentHousingRotation(const StringConfig& string, double s) {
  for (const Component& component : string.components) {
    if (!component.bend_angle || !component.bend_to_bit || std::abs(*component.bend_to_bit - s) > 1e-6) continue;
    // The bit side of the bend points toward the toolface d = cos(tf) z + sin(tf) y (z high side,
    // y right: the string frame): the upper body's axis, seen from the lower body, is its own x
    // turned by the bend angle about x × d.
    const double toolface = component.toolface.value_or(0.0);
    const Vec3 toward = std::cos(toolface) * Vec3::UnitZ() + std::sin(toolface) * Vec3::UnitY();
    return Eigen::AngleAxisd(*component.bend_angle, Vec3::UnitX().cross(toward)).toRotationMatrix();
  }
  return Mat3::Identity();
}

}  // namespace drillflex::model
