// The builder's supports (model/build_parts.hpp).
#include "model/build_parts.hpp"
#include "model/node_kinematics.hpp"
#include "model/spring_elements.hpp"

namespace drillflex::model {

std::vector<ElementHandle<SupportElement>> PlaceSupports(ModelDraft& draft) {
  const ModelInput& input = draft.input;
  const std::vector<Body>& placed = draft.bodies;
  const double factor = input.settings.coupling_factor;
  const bool default_supports = input.well && input.supports.empty();
  std::vector<Support> supports = default_supports ? DefaultWellSupports(draft.length) : input.supports;
  const auto top = draft.top;
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
  std::vector<ElementHandle<SupportElement>> handles;
  for (const Support& support : supports) {
    const auto [b, node] = FindNodeAt(placed, support.at);
    const Body& body = placed[b];
    Mat3 frame = body.reference_orientation.toRotationMatrix();
    const Vec3 position = NodeReferencePosition(body, node);
    if (guided_top && std::pair{b, node} == top) {
      // Along the hole's axis at the top, not the top body's chord (which a curved hole turns by half
      // the body's arc): the support's rest frame is the frame turned onto the hole's up-hole tangent.
      const Vec3 up_hole =
          -input.well->trajectory.Frame(input.well->trajectory.ClosestMd(position, input.bit_md - draft.length))
               .tangent;
      frame = Quat::FromTwoVectors(frame.col(0), up_hole).toRotationMatrix() * frame;
    }
    Vec6 stiffness = support.stiffness_scale * kSupportStiffnessFactor * SectionCouplingStiffness(body, factor);
    for (Index d = 0; d < 6; ++d) if (!support.fixed[d]) stiffness[d] = 0.0;
    const bool holds_bit = std::pair{b, node} == FindNodeAt(placed, 0.0);
    handles.push_back(draft.elements.Add<SupportElement>(&body, node, position, frame, stiffness,
                                                         SpringDamping(stiffness, ElementInertia(body)), holds_bit));
  }
  return handles;
}

}  // namespace drillflex::model
