// The wall friction along the hole: each hole section's own coefficients (well::HoleSection: cased
// or open, `friction`, `axial_friction`), else the case's `model.contact` ones, and what a parameter
// block (model/load_parameters.hpp) puts in their place: the open hole's and the cased hole's
// coefficients (a roadmap's friction factors, a calibration's fitted values) and a factor on them
// (the static's continuation from a string at rest).
#pragma once

#include <vector>

#include "model/load_parameters.hpp"
#include "model/string_config.hpp"
#include "well/hole.hpp"
#include "well/survey.hpp"

namespace drillflex::model {

// The friction a contact has where it sits, as the case gives it.
struct HoleFriction {
  WallFriction friction;  // μ along the hole axis and around the string
  bool cased = false;     // inside casing (the parameter block's cased-hole coefficients apply)
};

// A hole section's own coefficients, else `contact`'s (axial defaulting to the tangential).
HoleFriction SectionFriction(const well::HoleSection& section, const ContactSettings& contact);
// The case's own coefficients at `md`: the hole section's, else `contact`'s (axial defaulting to the
// tangential). An empty `hole` is open hole with `contact`'s friction. (The profile is built once by
// the caller: the soft string asks at every element.)
HoleFriction HoleFrictionAt(const well::HoleProfile& hole, const ContactSettings& contact, double md);

// The coefficients under a parameter block: its open- or cased-hole coefficients where it gives them
// (each for its own kind of hole), else `built`'s, times its friction factor.
WallFriction EffectiveFriction(const HoleFriction& built, const LoadParameters& load);

// True when `hole` has a cased section.
bool HasCasedHole(const std::vector<well::HoleSection>& hole);

}  // namespace drillflex::model
