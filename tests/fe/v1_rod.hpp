// The V1 rod of validation.md as one FE body, shared by the fe and cms tests: solid steel,
// L = 5.08 m, D = 0.0762 m, E = 2.1e11 Pa, ρ = 7800 kg/m³, with Euler–Bernoulli inertia (no
// bending rotary inertia) unless asked.
#pragma once

#include "fe/body_fe_model.hpp"

namespace drillflex::fe::testing {

inline BodySpec V1Rod(int elements, MassKind mass = MassKind::kConsistent, bool rotary = false) {
  BodySpec spec;
  spec.section = {0.0762, 0.0};
  spec.material = {"steel", 2.1e11, 0.3, 7800.0};
  spec.length = 5.08;
  spec.element_count = elements;
  spec.options.mass = mass;
  spec.options.bending_rotary_inertia = rotary;
  return spec;
}

}  // namespace drillflex::fe::testing
