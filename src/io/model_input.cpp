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
  // A static analysis of a rotating string (rpm > 0): the wall friction acts around the string
  // (rotating off bottom or drilling; torque and drag).
  if (c.operation.rpm > 0.0) input.static_sliding = model::PrescribedSliding{0.0, c.operation.rpm};
  if (c.well) {
    input.trajectory.emplace(c.well->survey);
    input.bit_md = c.well->bit_md;
    input.hole = c.well->hole;
  }
  return input;
}

}  // namespace drillflex::io
