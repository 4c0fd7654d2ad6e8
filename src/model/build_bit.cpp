// The builder's elements at the bit, and the imbalances (model/build_parts.hpp).
#include <cmath>

#include "model/bit_bottom.hpp"
#include "model/bit_rock.hpp"
#include "model/bit_side_cutting.hpp"
#include "model/build_parts.hpp"
#include "model/imbalance_element.hpp"
#include "model/node_kinematics.hpp"

namespace drillflex::model {

BitElements PlaceBitElements(ModelDraft& draft) {
  const ModelInput& input = draft.input;
  const Body& bit = draft.bodies.front();
  BitElements placed;
  if (!input.bit_rock) return placed;
  if (input.bit_rock->law != BitRockLaw::None) {
    BitRockParameters parameters = *input.bit_rock;
    if (parameters.radius == 0.0) parameters.radius = 0.5 * input.string.components.front().outer_diameter;
    placed.bit_rock = draft.elements.Add<BitRockElement>(&bit, parameters);
  }
  if (input.bit_rock->bottom) {
    const BitBottomParameters& bottom = *input.bit_rock->bottom;
    const Mat3 frame = bit.reference_orientation.toRotationMatrix();
    const double stiffness = BitBottomStiffness(bottom, bit, input.settings);
    const double damping = 2.0 * bottom.damping_ratio * std::sqrt(stiffness * ElementInertia(bit)[kX]);
    placed.bit_bottom = draft.elements.Add<BitBottomElement>(
        &bit, 0, NodeReferencePosition(bit, 0), frame.col(0), bottom, stiffness, damping);
  }
  if (input.bit_rock->side_cutting) {
    placed.bit_side = draft.elements.Add<BitSideCuttingElement>(
        &bit, BitSideCuttingParameters{*input.bit_rock->side_cutting, input.bit_rock->stick_speed});
  }
  return placed;
}

std::vector<ElementHandle<ImbalanceElement>> PlaceImbalances(ModelDraft& draft) {
  std::vector<ElementHandle<ImbalanceElement>> imbalances;
  for (const Imbalance& imbalance : draft.input.imbalances) {
    const auto [b, node] = FindNodeAt(draft.bodies, imbalance.at);
    imbalances.push_back(draft.elements.Add<ImbalanceElement>(&draft.bodies[b], node, imbalance.me, Vec3::UnitZ()));
  }
  return imbalances;
}

}  // namespace drillflex::model
