// Small models for the model layer's tests.
#pragma once

#include <random>

#include "fe/material.hpp"
#include "model/builder.hpp"

namespace drillflex::model::testing {

// The V1 rod of validation.md: solid, D = 3 in, L = 200 in, E = 2.1e11 Pa, ρ = 7800 kg/m³.
inline ModelInput RodInput(int bodies, int elements, int modes, double coupling_factor = 100.0) {
  ModelInput input;
  Component rod;
  rod.type = ComponentType::Collar;
  rod.outer_diameter = 0.0762;
  rod.inner_diameter = 0.0;
  rod.length = 5.08;
  rod.material = "rod";
  input.string.components.push_back(rod);
  input.materials["rod"] = fe::Material{"rod", 2.1e11, 0.3, 7800.0};
  input.settings.body_length = 5.08 / bodies + 1e-9;
  input.settings.elements_per_body = elements;
  input.settings.modes_per_body = modes;
  input.settings.coupling_factor = coupling_factor;
  input.settings.structural_damping = 0.01;
  return input;
}

// A random state near the reference: small body rotations, translations and modal coordinates,
// with a random overall rotation so that no frame is special.
inline VecX PerturbedPositions(const SystemModel& model, std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX dv(model.num_velocities());
  for (int i = 0; i < dv.size(); ++i) dv[i] = size * u(rng);
  for (const Body& body : model.bodies()) {
    dv.segment(body.v_offset + 6, body.flexible_count) *= 1e-3;  // modal coordinates are small (mass-normalised)
  }
  return model.Increment(model.ReferencePositions(), dv);
}

}  // namespace drillflex::model::testing
