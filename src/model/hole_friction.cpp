#include "model/hole_friction.hpp"

#include <algorithm>


namespace drillflex::model {

HoleFriction SectionFriction(const well::HoleSection& section, const ContactSettings& contact) {
  HoleFriction result;
  result.cased = section.cased;
  const double tangential = section.friction.value_or(contact.friction);
  // A section's own `friction` is its axial one too unless it gives `axial_friction`.
  const double axial = section.axial_friction.value_or(
      section.friction ? *section.friction : contact.axial_friction.value_or(contact.friction));
  result.friction = {axial, tangential};
  return result;
}

HoleFriction HoleFrictionAt(const well::HoleProfile& hole, const ContactSettings& contact, double md) {
  if (hole.empty()) return SectionFriction(well::HoleSection{}, contact);
  return SectionFriction(hole.SectionAt(md), contact);
}

WallFriction EffectiveFriction(const HoleFriction& built, const LoadParameters& load) {
  const std::optional<WallFriction>& given = built.cased ? load.cased_hole_friction : load.open_hole_friction;
  const WallFriction friction = given.value_or(built.friction);
  return {load.friction_factor * friction.axial, load.friction_factor * friction.tangential};
}

bool HasCasedHole(const std::vector<well::HoleSection>& hole) {
  return std::any_of(hole.begin(), hole.end(), [](const well::HoleSection& s) { return s.cased; });
}

}  // namespace drillflex::model
