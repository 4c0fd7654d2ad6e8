#include "model/builder.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cms/reduced_body.hpp"
#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/contact_circles.hpp"
#include "model/drive_elements.hpp"
#include "model/hole_friction.hpp"
#include "model/imbalance_element.hpp"
#include "model/lateral_fluid.hpp"
#include "model/nodal_loads.hpp"
#include "model/placement.hpp"
#include "model/spring_elements.hpp"
#include "model/string_above.hpp"
#include "model/wall_contact.hpp"
#include "well/hole.hpp"

namespace drillflex::model {
namespace {

constexpr double kGravityDirection[3] = {0.0, 0.0, 1.0};  // global +z is down

fe::BodyFeOptions FeOptions(const ModelSettings& settings) {
  fe::BodyFeOptions options;
  options.mass = settings.mass == MassKind::Lumped ? fe::MassKind::kLumped : fe::MassKind::kConsistent;
  options.beam = settings.beam == BeamTheory::Timoshenko ? fe::BeamTheory::kTimoshenko : fe::BeamTheory::kEulerBernoulli;
  options.bending_rotary_inertia = settings.rotary_inertia;
  options.bending_stiffness_factor = settings.bending_stiffness_factor;
  return options;
}

// Masses (kg) and inertias (kg·m²) of one FE element of a body, for spring damping.
Vec6 ElementInertia(const Body& body) {
  const auto& spec = body.reduced->spec;
  const double l = body.element_length;
  const double rho = spec.material.density;
  const double mass = rho * spec.section.area() * l;
  const double bending = rho * spec.section.second_moment() * l + mass * l * l / 12.0;
  Vec6 m;
  m << mass, mass, mass, rho * spec.section.polar_moment() * l, bending, bending;
  return m;
}

// c = 2 ζ sqrt(k m): a spring damped at the coupling's ratio ζ against the inertia it holds.
double SpringDamping(double stiffness, double inertia) {
  return 2.0 * kCouplingDampingRatio * std::sqrt(stiffness * inertia);
}

Vec6 SpringDamping(const Vec6& stiffness, const Vec6& inertia) {
  return (2.0 * kCouplingDampingRatio * (stiffness.cwiseProduct(inertia)).cwiseSqrt());
}

Body MakeBody(const std::shared_ptr<const cms::ReducedBody>& reduced, const fe::BodySpec& spec, int component,
              double s_start, double contact_diameter, const MatX& mass_correction) {
  Body body;
  body.reduced = reduced;
  body.component = component;
  body.s_start = s_start;
  body.flexible_count = reduced->flexible_count;
  body.reference_position = Vec3(s_start, 0.0, 0.0);
  body.reference_orientation = Quat::Identity();
  body.axial_rigidity = spec.material.youngs_modulus * spec.section.area();
  body.bending_rigidity =
      spec.material.youngs_modulus * spec.section.second_moment() * spec.options.bending_stiffness_factor;
  body.torsional_rigidity = spec.material.shear_modulus() * spec.section.polar_moment();
  body.element_length = spec.length / spec.element_count;
  body.outer_diameter = spec.section.outer_diameter;
  body.contact_diameter = contact_diameter;
  // N = EA/L (u_x(L) − u_x(0)) from the axial rows of the end nodes.
  const int last = reduced->node_count() - 1;
  body.axial_force_row = (body.axial_rigidity / spec.length) *
                         (reduced->node_translation_modes[last].row(0) - reduced->node_translation_modes[0].row(0)).transpose();
  body.torque_row = (body.torsional_rigidity / spec.length) *
                    (reduced->node_rotation_modes[last].row(0) - reduced->node_rotation_modes[0].row(0)).transpose();
  body.mass_correction = mass_correction;
  body.reference_mass = cms::NodalReferenceMassMatrix(*reduced) + mass_correction;
  return body;
}

// Where bodies must meet: the bent housing of a motor (its bend sits in a coupling) and every
// case support (it then acts on a node exactly where it is), m from the bit.
std::vector<double> BodyCuts(const ModelInput& input) {
  std::vector<double> cuts;
  for (const Component& component : input.string.components) {
    if (component.bend_angle && component.bend_to_bit) cuts.push_back(*component.bend_to_bit);
  }
  for (const Support& support : input.supports) cuts.push_back(support.at);
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

// The reduction of a component's section. A section whose stiffness or mass the reduction cannot
// tell from rounding (an od of 1e-9 m, a modulus of 1e-300 Pa: found by fuzz/case_file, where the
// reduction's LogicError ended the program) is the case's to fix: an InputError at the component.
std::shared_ptr<const cms::ReducedBody> ReduceSection(cms::ReductionCache& cache, const fe::BodySpec& spec,
                                                      const cms::ReductionOptions& reduction,
                                                      const Component& component, std::size_t index) {
  try {
    return cache.Get(spec, reduction);
  } catch (const LogicError& error) {
    throw InputError({"", component.source_line, 0}, fmt::format("string[{}]", index),
                     fmt::format("the {} (od {:.6g} m, id {:.6g} m, E {:.6g} Pa, density {:.6g} kg/m3) cannot be "
                                 "modelled: {}; check its diameters, length and material",
                                 component.name, spec.section.outer_diameter, spec.section.inner_diameter,
                                 spec.material.youngs_modulus, spec.material.density, error.what()));
  }
}

std::vector<Body> CutBodies(const ModelInput& input, cms::ReductionCache& cache) {
  std::vector<Body> bodies;
  const ModelSettings& settings = input.settings;
  cms::ReductionOptions reduction;
  reduction.modes_per_body = settings.modes_per_body;
  reduction.structural_damping = settings.structural_damping;
  const std::vector<double> cuts = BodyCuts(input);
  double s = 0.0;
  for (std::size_t c = 0; c < input.string.components.size(); ++c) {
    const Component& component = input.string.components[c];
    const double span = component.length * component.count;
    // The component's stretches between the cuts inside it, each split evenly into bodies.
    std::vector<double> ends;
    for (const double cut : cuts) {
      if (cut > s + 1e-6 && cut < s + span - 1e-6 && (ends.empty() || cut > ends.back() + 1e-6)) ends.push_back(cut);
    }
    ends.push_back(s + span);
    double stretch_start = s;
    for (const double stretch_end : ends) {
      const double stretch = stretch_end - stretch_start;
      const int count = std::max(1, static_cast<int>(std::ceil(stretch / settings.body_length - 1e-9)));
      fe::BodySpec spec;
      spec.section = {component.outer_diameter, component.inner_diameter};
      spec.material = input.materials.at(component.material);
      // Tool joints: their steel smeared along the pipe (the adjusted weight of API RP 7G); the
      // stiffness stays the pipe body's. Their displaced and held fluid: BuoyedWeightPerLength.
      spec.material.density *= AverageAreas(component).material / spec.section.area();
      spec.length = stretch / count;
      // A body shorter than body_length gets proportionally fewer elements (at least 2), so that
      // the element length ℓ stays near body_length / elements_per_body: the coupling stiffness
      // grows as 1/ℓ³ and a 1 ft bit cut into 10 elements would make the couplings 1000 times
      // stiffer than the rest of the model for no accuracy (ill-conditioned tangents).
      spec.element_count = std::clamp(
          static_cast<int>(std::lround(settings.elements_per_body * spec.length / settings.body_length)), 2,
          settings.elements_per_body);
      reduction.modes_per_body = std::min(settings.modes_per_body, 6 * (spec.element_count - 1));
      spec.options = FeOptions(settings);
      const auto reduced = ReduceSection(cache, spec, reduction, component, c);
      // Once per section (it was 2/3 of the build time of a 1000-body string when made per body).
      const MatX mass_correction = cms::ReferenceMassMatrix(*reduced) - cms::NodalReferenceMassMatrix(*reduced);
      double body_start = stretch_start;
      for (int i = 0; i < count; ++i) {
        bodies.push_back(
            MakeBody(reduced, spec, static_cast<int>(c), body_start, ContactDiameter(component), mass_correction));
        body_start += spec.length;
      }
      stretch_start = stretch_end;
    }
    s += span;
  }
  int q_offset = 0, v_offset = 0;
  for (Body& body : bodies) {
    body.q_offset = q_offset;
    body.v_offset = v_offset;
    q_offset += body.position_count();
    v_offset += body.velocity_count();
  }
  return bodies;
}

// The work-equivalent nodal forces and moments of a uniform global line load over every element of
// a body (the buoyed weight, N/m).
void AddLineLoad(const Body& body, const Vec3& per_length, std::vector<Vec3>& forces, std::vector<Vec3>& moments) {
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  auto node_position = [&](int k) { return body.reference_position + frame * body.reduced->node_positions[k]; };
  for (int k = 0; k + 1 < body.node_count(); ++k) {
    AddUniformLineLoad(node_position(k), node_position(k + 1), per_length, forces[k], moments[k], forces[k + 1],
                       moments[k + 1]);
  }
}

// The same of one of the case's distributed loads (string frame, over the part of each element inside
// [from, to]). True when the load reaches the body.
bool AddDistributedLoad(const Body& body, const Load& load, std::vector<Vec3>& forces, std::vector<Vec3>& moments) {
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  auto node_position = [&](int k) { return body.reference_position + frame * body.reduced->node_positions[k]; };
  bool any = false;
  for (int k = 0; k + 1 < body.node_count(); ++k) {
    const double a = std::max(load.from, body.NodeS(k)), c = std::min(load.to, body.NodeS(k + 1));
    if (c <= a) continue;
    any = true;
    const Vec3 q = frame * load.force_per_length;
    const Vec3 m = frame * load.moment_per_length;
    const double h = body.NodeS(k + 1) - body.NodeS(k);
    if (c - a >= h * (1.0 - 1e-12)) {
      AddUniformLineLoad(node_position(k), node_position(k + 1), q, forces[k], moments[k], forces[k + 1], moments[k + 1]);
    } else {  // a partly loaded element: the resultant shared by the lever rule
      const double share = (0.5 * (a + c) - body.NodeS(k)) / h;
      forces[k] += (1.0 - share) * (c - a) * q;
      forces[k + 1] += share * (c - a) * q;
    }
    moments[k] += 0.5 * (c - a) * m;
    moments[k + 1] += 0.5 * (c - a) * m;
  }
  return any;
}

}  // namespace

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
  if (!input.trajectory || input.string.components.empty()) return 0.0;
  const double top_md = input.bit_md - StringLength(input.string);
  if (top_md <= input.trajectory->start_md()) return 0.0;
  const double tvd = input.trajectory->Position(top_md).z() - input.trajectory->Position(input.trajectory->start_md()).z();
  return BuoyedWeightPerLength(input.string.components.back(), input) * tvd;
}

double ModelledStringAxialWeight(const ModelInput& input) {
  if (!input.trajectory) return 0.0;
  double weight = 0.0;
  // Each component's weight along the hole: w (TVD at its bottom − TVD at its top).
  double md = input.bit_md;
  for (const Component& component : input.string.components) {
    const double length = component.length * component.count;
    weight += BuoyedWeightPerLength(component, input) *
              (input.trajectory->Position(md).z() - input.trajectory->Position(md - length).z());
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
  if (!input.trajectory || input.hole.empty()) return std::nullopt;
  const double hole = well::HoleProfile(input.hole).Diameter(input.bit_md - s);
  return 0.5 * (hole - ContactDiameterAt(input.string, s));
}

Vec6 SectionCouplingStiffness(const Body& body, double factor) {
  const double l = body.element_length;
  Vec6 k;
  k << body.axial_rigidity / l, 12.0 * body.bending_rigidity / (l * l * l), 12.0 * body.bending_rigidity / (l * l * l),
      body.torsional_rigidity / l, body.bending_rigidity / l, body.bending_rigidity / l;
  return factor * k;
}

std::vector<Support> DefaultWellSupports(double string_length) {
  Support bit;
  bit.at = 0.0;
  bit.fixed[kY] = bit.fixed[kZ] = true;
  Support hook;
  hook.at = string_length;
  hook.fixed[kX] = hook.fixed[kRx] = true;
  return {bit, hook};
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

double BitBottomStiffness(const BitBottomParameters& bottom, const Body& bit, const ModelSettings& settings) {
  return bottom.stiffness > 0.0 ? bottom.stiffness
                                : kSupportStiffnessFactor * SectionCouplingStiffness(bit, settings.coupling_factor)[kX];
}

BuiltModel BuildSystemModel(const ModelInput& input, cms::ReductionCache& cache) {
  if (input.string.components.empty()) throw LogicError("BuildSystemModel: the string has no components");
  std::vector<Body> bodies = CutBodies(input, cache);
  if (input.trajectory) PlaceAlongWell(bodies, *input.trajectory, input.bit_md);
  if (input.transient_fluid_frequency) AttachLateralFluid(input, *input.transient_fluid_frequency, bodies);
  double length = 0.0;
  for (const Body& body : bodies) length = std::max(length, body.s_start + body.length());
  // Elements refer to bodies by address; moving the vector into the SystemModel keeps its buffer.
  const std::vector<Body>& placed = bodies;
  std::vector<std::unique_ptr<ForceElement>> elements;
  const double factor = input.settings.coupling_factor;

  for (std::size_t b = 0; b + 1 < placed.size(); ++b) {
    const Body& lower = placed[b];
    const Body& upper = placed[b + 1];
    const Vec6 stiffness = SectionCouplingStiffness(lower, factor).cwiseMax(SectionCouplingStiffness(upper, factor));
    const Vec6 inertia = ElementInertia(lower).cwiseMin(ElementInertia(upper));
    const Vec3 kink = so3::LogMap(lower.reference_orientation.toRotationMatrix().transpose() *
                                  upper.reference_orientation.toRotationMatrix());
    elements.push_back(std::make_unique<CouplingElement>(&lower, lower.node_count() - 1, &upper, 0, stiffness,
                                                         SpringDamping(stiffness, inertia),
                                                         BentHousingRotation(input.string, upper.s_start), kink));
  }

  std::vector<int> support_elements;
  const bool default_supports = input.trajectory && input.supports.empty();
  std::vector<Support> supports = default_supports ? DefaultWellSupports(length) : input.supports;
  const auto top = FindNodeAt(placed, length);
  const bool side_cutting = input.bit_rock && input.bit_rock->side_cutting;
  // A guided top (model.top: guided) holds its tilt along the hole's axis there, its sideways place free.
  const bool guided_top = default_supports && input.settings.top == TopCondition::Guided;
  for (Support& support : supports) {
    // Side cutting holds the bit laterally instead (model/bit_side_cutting.hpp).
    if (side_cutting && FindNodeAt(placed, support.at) == FindNodeAt(placed, 0.0)) support.fixed[kY] = support.fixed[kZ] = false;
    if (FindNodeAt(placed, support.at) != top) continue;
    if (guided_top) support.fixed[kRy] = support.fixed[kRz] = true;
    if (input.top_drive) support.fixed[kRx] = false;  // the top drive holds the top's rotation
    if (input.block) support.fixed[kX] = false;       // the block holds its axial place
  }
  for (const Support& support : supports) {
    const auto [b, node] = FindNodeAt(placed, support.at);
    const Body& body = placed[b];
    Mat3 frame = body.reference_orientation.toRotationMatrix();
    const Vec3 position = body.reference_position + frame * body.reduced->node_positions[node];
    if (guided_top && std::pair{b, node} == top) {
      // Along the hole's axis at the top, not the top body's chord (which a curved hole turns by half
      // the body's arc): the support's rest frame is the frame turned onto the hole's up-hole tangent.
      const Vec3 up_hole = -input.trajectory->Frame(input.trajectory->ClosestMd(position, input.bit_md - length)).tangent;
      frame = Quat::FromTwoVectors(frame.col(0), up_hole).toRotationMatrix() * frame;
    }
    Vec6 stiffness = support.stiffness_scale * kSupportStiffnessFactor * SectionCouplingStiffness(body, factor);
    for (int d = 0; d < 6; ++d) if (!support.fixed[d]) stiffness[d] = 0.0;
    support_elements.push_back(static_cast<int>(elements.size()));
    const bool holds_bit = std::pair{b, node} == FindNodeAt(placed, 0.0);
    elements.push_back(std::make_unique<SupportElement>(&body, node, position, frame, stiffness,
                                                        SpringDamping(stiffness, ElementInertia(body)), holds_bit));
  }

  // The pipe above the top (model/string_above.hpp), where the default supports leave the top free to
  // lie on the wall.
  int string_above_element = -1;
  if (input.trajectory && !input.hole.empty() && input.supports.empty() &&
      input.settings.top == TopCondition::StringAbove) {
    const Body& body = placed[top.first];
    const Mat3 frame = body.reference_orientation.toRotationMatrix();
    const Vec3 position = body.reference_position + frame * body.reduced->node_positions[top.second];
    const Component& component = input.string.components.back();
    const double top_md = input.bit_md - length;
    StringAboveParameters above;
    above.bending_rigidity = body.bending_rigidity;
    above.weight_per_length = BuoyedWeightPerLength(component, input);
    // Gravity across the hole and the hole's curvature, in the top's string frame (y, z).
    const Vec3 gravity(kGravityDirection[0], kGravityDirection[1], kGravityDirection[2]);
    const Vec3 curvature = input.trajectory->Curvature(top_md);
    above.gravity_across = Eigen::Vector2d(frame.col(1).dot(gravity), frame.col(2).dot(gravity));
    above.curvature = Eigen::Vector2d(frame.col(1).dot(curvature), frame.col(2).dot(curvature));
    const double joint_diameter = component.joint_diameter.value_or(component.outer_diameter);
    above.clearance = 0.5 * (well::HoleProfile(input.hole).Diameter(top_md) - joint_diameter);
    const HoleFriction top_friction = HoleFrictionAt(well::HoleProfile(input.hole), input.settings.contact, top_md);
    above.friction = top_friction.friction;
    above.cased = top_friction.cased;
    above.contact_radius = 0.5 * joint_diameter;
    above.regularization_velocity =
        input.settings.contact.friction_velocity.value_or(kFrictionRegularizationSpin * above.contact_radius);
    above.sliding = input.static_sliding;
    // A block holding a hook load (its target at the model's top: analyses::TransientModelInput).
    if (input.block && input.block->mode == BlockMode::HookLoad) above.top_tension = input.block->setting.target;
    above.axial_weight = ModelledStringAxialWeight(input);
    // A case that gives the surface hook load: the top's balance takes the WOB it leaves.
    above.weight_on_bit = input.operation.hook_load ? WeightOnBitFromHookLoad(input, *input.operation.hook_load)
                                                    : input.operation.weight_on_bit;
    string_above_element = static_cast<int>(elements.size());
    elements.push_back(std::make_unique<StringAboveElement>(&body, top.second, position, frame, above));
  }

  int top_drive_element = -1, block_element = -1;
  if (input.top_drive || input.block) {
    const Body& body = placed[top.first];
    const Mat3 frame = body.reference_orientation.toRotationMatrix();
    const Vec3 position = body.reference_position + frame * body.reduced->node_positions[top.second];
    // As stiff as the support it replaces, so the start equilibrium holds at t = 0 (drives.hpp).
    const Vec6 stiffness = kSupportStiffnessFactor * SectionCouplingStiffness(body, factor);
    const Vec6 damping = SpringDamping(stiffness, ElementInertia(body));
    if (input.top_drive) {
      top_drive_element = static_cast<int>(elements.size());
      elements.push_back(std::make_unique<TopDriveElement>(&body, top.second, frame, *input.top_drive,
                                                           stiffness[kRx], damping[kRx]));
    }
    if (input.block) {
      block_element = static_cast<int>(elements.size());
      // A line softer than the hold starts stretched to the hold's start force k_hold u0 (drives.hpp).
      const double hold = stiffness[kX], line = input.block->line_stiffness.value_or(hold);
      const double line_damping = SpringDamping(line, ElementInertia(body)[kX]);
      const double preload = (hold - line) * input.block->start_top_displacement;
      elements.push_back(std::make_unique<BlockElement>(&body, top.second, position, frame, *input.block, line,
                                                        line_damping, preload));
    }
  }

  // Wall contact at every node (a joint once, on the upper body's start node): tool joints and
  // blades as point contacts, each circle as stiff as the string length it stands for
  // (model/contact_circles.hpp).
  std::vector<int> contact_elements;
  if (input.trajectory && !input.hole.empty()) {
    auto wellbore = std::make_shared<const Wellbore>(Wellbore{*input.trajectory, well::HoleProfile(input.hole)});
    struct ContactNode { const Body* body; int node; double s; };
    std::vector<ContactNode> nodes;
    for (std::size_t b = 0; b < placed.size(); ++b) {
      const Body& body = placed[b];
      // The bit cuts the hole it sits in (its support holds it at the hole centre): no contact.
      if (input.string.components[body.component].type == ComponentType::Bit) continue;
      for (int k = 0; k < body.node_count(); ++k) {
        if (k == body.node_count() - 1 && b + 1 != placed.size()) continue;  // the next body's node 0 carries it
        nodes.push_back({&body, k, body.NodeS(k)});
      }
    }
    std::vector<double> positions;
    for (const ContactNode& node : nodes) positions.push_back(node.s);
    // A string that is a bit alone has no node to touch the wall (found by fuzz/case_file).
    const std::vector<ContactCircle> circles =
        nodes.empty() ? std::vector<ContactCircle>{} : ContactCircles(input.string, positions);
    const ContactSettings& contact = input.settings.contact;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto [body, k, s] = nodes[i];
      const double stiffness = contact.stiffness * circles[i].length;  // N/m per metre × m
      WallContactParameters parameters;
      parameters.contact_radius = 0.5 * circles[i].diameter;
      parameters.normal_stiffness = stiffness;
      parameters.normal_damping = 2.0 * contact.damping_ratio * std::sqrt(stiffness * ElementInertia(*body)[0]);
      // The friction of the hole section the contact starts in (the string moves centimetres in a
      // static, a stand at most in a transient: a contact keeps its section).
      const HoleFriction friction = HoleFrictionAt(wellbore->hole, contact, input.bit_md - s);
      parameters.tangential_friction = friction.friction.tangential;
      parameters.axial_friction = friction.friction.axial;
      parameters.cased = friction.cased;
      parameters.regularization_velocity =
          contact.friction_velocity.value_or(kFrictionRegularizationSpin * parameters.contact_radius);
      parameters.prescribed_sliding = input.static_sliding;
      contact_elements.push_back(static_cast<int>(elements.size()));
      elements.push_back(std::make_unique<WallContactElement>(body, k, wellbore, parameters, input.bit_md - s));
    }
  }

  // Applied loads, each group its own elements (LoadParameters scales or replaces each): the buoyed
  // weight per body; the case's distributed loads per body and point loads; the transient's initial
  // loads; the WOB and the torque on bit per unit of their value.
  double force_scale = 0.0;
  for (const Body& body : placed) {
    std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
    const double weight = BuoyedWeightPerLength(body, input);
    if (weight != 0.0) {
      AddLineLoad(body, weight * Vec3(kGravityDirection[0], kGravityDirection[1], kGravityDirection[2]), forces, moments);
    }
    for (int k = 0; k < body.node_count(); ++k) force_scale += forces[k].norm();
    elements.push_back(std::make_unique<NodalLoadElement>(&body, std::move(forces), std::move(moments), LoadGroup::kWeight));
  }
  for (const auto& [loads, group] : {std::pair{&input.loads, LoadGroup::kCaseLoads},
                                     std::pair{&input.initial_loads, LoadGroup::kInitialLoads}}) {
    for (const Body& body : placed) {
      std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
      bool any = false;
      for (const Load& load : *loads) {
        if (load.distributed) any = AddDistributedLoad(body, load, forces, moments) || any;
      }
      if (!any) continue;
      if (group == LoadGroup::kCaseLoads) {
        for (int k = 0; k < body.node_count(); ++k) force_scale += forces[k].norm();
      }
      elements.push_back(std::make_unique<NodalLoadElement>(&body, std::move(forces), std::move(moments), group));
    }
    for (const Load& load : *loads) {
      if (load.distributed) continue;
      const auto [b, node] = FindNodeAt(placed, load.at);
      const Body& body = placed[b];
      const Mat3 frame = body.reference_orientation.toRotationMatrix();
      std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
      forces[node] = frame * load.force;
      moments[node] = frame * load.moment;
      if (group == LoadGroup::kCaseLoads) force_scale += load.force.norm() + load.moment.norm() / std::max(length, 1e-3);
      elements.push_back(std::make_unique<NodalLoadElement>(&body, std::move(forces), std::move(moments), group));
    }
  }
  // The formation pushes the bit up-hole with the WOB and resists its rotation with the torque on
  // bit: per newton and per N·m, their values the case's (or the parameter block's). A bit-rock law
  // gives the rock's reaction from the bit's motion instead (model/bit_rock.hpp): the torque on bit,
  // and under Detournay's law or with a bottom contact the WOB too.
  const bool rock_wob = input.bit_rock && (input.bit_rock->law == BitRockLaw::Detournay || input.bit_rock->bottom);
  const bool rock_tob = input.bit_rock && input.bit_rock->law != BitRockLaw::None;
  {
    const auto [b, node] = FindNodeAt(placed, 0.0);
    const Body& body = placed[b];
    const Vec3 axis = body.reference_orientation.toRotationMatrix().col(0);
    const double wob = input.operation.weight_on_bit, tob = input.operation.torque_on_bit;
    if (!rock_wob) {
      std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
      forces[node] = axis;
      force_scale += std::abs(wob);
      elements.push_back(std::make_unique<NodalLoadElement>(&body, std::move(forces), std::move(moments),
                                                            LoadGroup::kWeightOnBit, wob));
    }
    if (!rock_tob) {
      std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
      moments[node] = axis;
      force_scale += std::abs(tob) / std::max(length, 1e-3);
      elements.push_back(std::make_unique<NodalLoadElement>(&body, std::move(forces), std::move(moments),
                                                            LoadGroup::kTorqueOnBit, tob));
    }
  }
  int bit_rock_element = -1, bit_bottom_element = -1, bit_side_element = -1;
  if (input.bit_rock && input.bit_rock->law != BitRockLaw::None) {
    BitRockParameters parameters = *input.bit_rock;
    if (parameters.radius == 0.0) parameters.radius = 0.5 * input.string.components.front().outer_diameter;
    bit_rock_element = static_cast<int>(elements.size());
    elements.push_back(std::make_unique<BitRockElement>(&placed.front(), parameters));
  }
  if (input.bit_rock && input.bit_rock->bottom) {
    const BitBottomParameters& bottom = *input.bit_rock->bottom;
    const Body& bit = placed.front();
    const Mat3 frame = bit.reference_orientation.toRotationMatrix();
    const double stiffness = BitBottomStiffness(bottom, bit, input.settings);
    const double damping = 2.0 * bottom.damping_ratio * std::sqrt(stiffness * ElementInertia(bit)[kX]);
    bit_bottom_element = static_cast<int>(elements.size());
    elements.push_back(std::make_unique<BitBottomElement>(&bit, 0, bit.reference_position + frame * bit.reduced->node_positions[0],
                                                          frame.col(0), bottom, stiffness, damping));
  }
  if (side_cutting) {
    bit_side_element = static_cast<int>(elements.size());
    elements.push_back(std::make_unique<BitSideCuttingElement>(
        &placed.front(), BitSideCuttingParameters{*input.bit_rock->side_cutting, input.bit_rock->stick_speed}));
  }
  for (const Imbalance& imbalance : input.imbalances) {
    const auto [b, node] = FindNodeAt(placed, imbalance.at);
    elements.push_back(std::make_unique<ImbalanceElement>(&placed[b], node, imbalance.me, Vec3::UnitZ()));
  }
  if (force_scale == 0.0) force_scale = placed.front().bending_rigidity / (length * length);

  SystemModel system(std::move(bodies), std::move(elements), length);
  system.set_force_scale(force_scale);
  return BuiltModel{std::move(system),   std::move(support_elements), std::move(contact_elements),
                    top_drive_element,   block_element,               force_scale,
                    bit_rock_element,    bit_bottom_element,          bit_side_element,
                    string_above_element};
}

}  // namespace drillflex::model
