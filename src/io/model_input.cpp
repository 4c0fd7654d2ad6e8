#include "io/model_input.hpp"

namespace drillflex::io {

model::ModelInput MakeModelInput(const Case& c) {
  model::ModelInput input;
  input.string = c.string;
  input.settings = c.model;
  input.materials = c.materials;
  input.supports = c.supports;
  input.loads = c.loads;
  input.gravity = c.gravity;
  input.fluid = c.fluid;
  input.operation = c.operation;
  if (c.well) {
    input.trajectory.emplace(c.well->survey);
    input.bit_md = c.well->bit_md;
    input.hole = c.well->hole;
  }
  return input;
}

}  // namespace drillflex::io
