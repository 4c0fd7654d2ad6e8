#include "io/model_input.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace drillflex::io {

void CompleteModelInput(Case& c) {
  model::ModelInput& input = c.input;
  // A static analysis of a rotating string (rpm > 0): the wall friction acts around the string
  // (rotating off bottom or drilling; torque and drag).
  if (input.operation.rotary_speed > 0.0) input.static_sliding = model::PrescribedSliding{0.0, input.operation.rotary_speed};
  if (c.well) {
    input.well = model::MakeWellbore(well::Trajectory(c.well->survey), c.well->hole);
    input.bit_md = c.well->bit_md;
  }
  // A surface hook load instead of a WOB (a string in a well on the default supports): the WOB is
  // what the hook leaves of the string's buoyed weight along the hole (model/builder.hpp).
  if (input.operation.hook_load && input.well && input.supports.empty()) {
    const double hook_load = *input.operation.hook_load;
    const double wob = model::WeightOnBitFromHookLoad(input, hook_load);
    if (wob < 0.0) {
      const double weight = wob + hook_load;
      throw InputError({c.file, 0, 0}, "operation.hook_load",
                       fmt::format("the hook load {:.6g} {} is more than the string's buoyed weight along the hole, "
                                   "{:.6g} {} (with the pipe above the model to the surface): the bit would be off bottom",
                                   units::FromSI(hook_load, units::Quantity::Force, c.units),
                                   units::DefaultUnit(units::Quantity::Force, c.units),
                                   units::FromSI(weight, units::Quantity::Force, c.units),
                                   units::DefaultUnit(units::Quantity::Force, c.units)));
    }
    input.operation.weight_on_bit = wob;
  }
}

}  // namespace drillflex::io
