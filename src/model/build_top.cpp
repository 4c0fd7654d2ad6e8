// The builder's elements at the top: the pipe above and the drives (model/build_parts.hpp).
#include "model/build_parts.hpp"
#include "model/drive_elements.hpp"
#include "model/hole_friction.hpp"
#include "model/node_kinematics.hpp"
#include "model/string_above.hpp"
#include "well/hole.hpp"

namespace drillflex::model {

// The pipe above the top (model/string_above.hpp), where the default supports leave the top free to
// lie on the wall.
std::optional<ElementHandle<StringAboveElement>> PlaceStringAbove(ModelDraft& draft) {
  const ModelInput& input = draft.input;
  if (!input.well || input.well->hole.empty() || !input.supports.empty() ||
      input.settings.top != TopCondition::StringAbove) {
    return std::nullopt;
  }
  const Body& body = draft.bodies[draft.top.first];
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  const Vec3 position = NodeReferencePosition(body, draft.top.second);
  const Component& component = input.string.components.back();
  const double top_md = input.bit_md - draft.length;
  StringAboveParameters above;
  above.bending_rigidity = body.bending_rigidity;
  above.weight_per_length = BuoyedWeightPerLength(component, input);
  // Gravity across the hole and the hole's curvature, in the top's string frame (y, z).
  const Vec3 gravity(kGravityDirection[0], kGravityDirection[1], kGravityDirection[2]);
  const Vec3 curvature = input.well->trajectory.Curvature(top_md);
  above.gravity_across = Eigen::Vector2d(frame.col(1).dot(gravity), frame.col(2).dot(gravity));
  above.curvature = Eigen::Vector2d(frame.col(1).dot(curvature), frame.col(2).dot(curvature));
  const double joint_diameter = component.joint_diameter.value_or(component.outer_diameter);
  above.clearance = 0.5 * (input.well->hole.Diameter(top_md) - joint_diameter);
  const HoleFriction top_friction = HoleFrictionAt(input.well->hole, input.settings.contact, top_md);
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
  return draft.elements.Add<StringAboveElement>(&body, draft.top.second, position, frame, above);
}

TopDrives PlaceDrives(ModelDraft& draft) {
  const ModelInput& input = draft.input;
  TopDrives drives;
  if (!input.top_drive && !input.block) return drives;
  const Body& body = draft.bodies[draft.top.first];
  const Index node = draft.top.second;
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  const Vec3 position = NodeReferencePosition(body, node);
  // As stiff as the support it replaces, so the start equilibrium holds at t = 0 (drives.hpp).
  const Vec6 stiffness = kSupportStiffnessFactor * SectionCouplingStiffness(body, input.settings.coupling_factor);
  const Vec6 damping = SpringDamping(stiffness, ElementInertia(body));
  if (input.top_drive) {
    drives.top_drive =
        draft.elements.Add<TopDriveElement>(&body, node, frame, *input.top_drive, stiffness[kRx], damping[kRx]);
  }
  if (input.block) {
    // A line softer than the hold starts stretched to the hold's start force k_hold u0 (drives.hpp).
    const double hold = stiffness[kX], line = input.block->line_stiffness.value_or(hold);
    const double line_damping = SpringDamping(line, ElementInertia(body)[kX]);
    const double preload = (hold - line) * input.block->start_top_displacement;
    drives.block =
        draft.elements.Add<BlockElement>(&body, node, position, frame, *input.block, line, line_damping, preload);
  }
  return drives;
}

}  // namespace drillflex::model
