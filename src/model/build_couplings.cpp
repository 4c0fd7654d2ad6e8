// The builder's couplings (model/build_parts.hpp).
#include "core/so3.hpp"
#include "model/build_parts.hpp"
#include "model/spring_elements.hpp"

namespace drillflex::model {

std::vector<ElementHandle<CouplingElement>> PlaceCouplings(ModelDraft& draft) {
  const ModelInput& input = draft.input;
  const std::vector<Body>& placed = draft.bodies;
  const double factor = input.settings.coupling_factor;
  std::vector<ElementHandle<CouplingElement>> couplings;
  for (Index b = 0; b + 1 < std::ssize(placed); ++b) {
    const Body& lower = placed[b];
    const Body& upper = placed[b + 1];
    const Vec6 stiffness = SectionCouplingStiffness(lower, factor).cwiseMax(SectionCouplingStiffness(upper, factor));
    const Vec6 inertia = ElementInertia(lower).cwiseMin(ElementInertia(upper));
    const Vec3 kink = so3::LogMap(lower.reference_orientation.toRotationMatrix().transpose() *
                                  upper.reference_orientation.toRotationMatrix());
    couplings.push_back(draft.elements.Add<CouplingElement>(&lower, lower.node_count() - 1, &upper, 0, stiffness,
                                                            SpringDamping(stiffness, inertia),
                                                            BentHousingRotation(input.string, upper.s_start), kink));
  }
  return couplings;
}

}  // namespace drillflex::model
