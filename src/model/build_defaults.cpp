#include "model/build_defaults.hpp"

#include <algorithm>
#include <cmath>

namespace drillflex::model {

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

double WallContactStiffness(const ContactSettings& contact, double circle_length, double weight_per_length,
                            double clearance, double carried_length) {
  const double per_metre = contact.stiffness * circle_length;  // N/m per metre × m
  if (!(contact.penetration_fraction > 0.0)) return per_metre;
  const double weight = std::abs(weight_per_length) * carried_length;
  return std::max(per_metre, weight / (contact.penetration_fraction * std::max(clearance, kLeastContactClearance)));
}

double BitBottomStiffness(const BitBottomParameters& bottom, const Body& bit, const ModelSettings& settings) {
  return bottom.stiffness > 0.0 ? bottom.stiffness
                                : kSupportStiffnessFactor * SectionCouplingStiffness(bit, settings.coupling_factor)[kX];
}

}  // namespace drillflex::model
