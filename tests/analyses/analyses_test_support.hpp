// Rods of validation.md (V1, V2) as model inputs for the analyses' tests.
#pragma once

#include <cmath>
#include <initializer_list>

#include "core/types.hpp"
#include "fe/material.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses::testing {

// The V1 rod: solid, D = 3 in, L = 200 in.
inline constexpr double kRodLength = 5.08;      // m
inline constexpr double kRodDiameter = 0.0762;  // m
inline double RodArea() { return kPi * kRodDiameter * kRodDiameter / 4.0; }
inline double RodSecondMoment() { return kPi * std::pow(kRodDiameter, 4) / 64.0; }

// A rod of `bodies` bodies × `elements` elements, `modes` fixed-interface modes per body, with
// Euler–Bernoulli inertia (no bending rotary inertia: the analytic references have none).
inline model::ModelInput RodInput(int bodies, double youngs_modulus, double density, int elements = 10,
                                  int modes = 6) {
  model::ModelInput input;
  model::Component rod;
  rod.type = model::ComponentType::Collar;
  rod.outer_diameter = kRodDiameter;
  rod.inner_diameter = 0.0;
  rod.length = kRodLength;
  rod.material = "rod";
  input.string.components.push_back(rod);
  input.materials["rod"] = fe::Material{"rod", youngs_modulus, 0.3, density};
  input.settings.body_length = kRodLength / bodies + 1e-9;
  input.settings.elements_per_body = elements;
  input.settings.modes_per_body = modes;
  input.settings.coupling_factor = 1000.0;
  input.settings.rotary_inertia = false;
  return input;
}

// The V1 rod (E = 2.1e11 Pa, ρ = 7800 kg/m³) with the paper's model: 4 bodies × 10 elements.
inline model::ModelInput V1Rod() { return RodInput(4, 2.1e11, 7800.0); }

// Fixes DOFs (model::Dof) of the node at s.
inline model::Support SupportAt(double s, std::initializer_list<model::Dof> dofs) {
  model::Support support;
  support.at = s;
  for (model::Dof dof : dofs) support.fixed[dof] = true;
  return support;
}

inline model::Support ClampAt(double s) {
  return SupportAt(s, {model::kX, model::kY, model::kZ, model::kRx, model::kRy, model::kRz});
}

inline model::Load PointLoad(double s, const Vec3& force, const Vec3& moment = Vec3::Zero()) {
  model::Load load;
  load.at = s;
  load.force = force;
  load.moment = moment;
  return load;
}

inline model::Load DistributedLoad(double from, double to, const Vec3& per_length) {
  model::Load load;
  load.distributed = true;
  load.from = from;
  load.to = to;
  load.force_per_length = per_length;
  return load;
}

}  // namespace drillflex::analyses::testing
