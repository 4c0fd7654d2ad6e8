#include "analyses/transient_model.hpp"

namespace drillflex::analyses {

model::ModelInput TransientModelInput(const model::ModelInput& input, const TransientSettings& settings) {
  model::ModelInput out = input;
  if (!settings.bit_rock) return out;
  out.bit_rock = settings.bit_rock;
  out.operation.torque_on_bit = 0.0;
  if (settings.bit_rock->law == model::BitRockLaw::Detournay) out.operation.weight_on_bit = 0.0;
  return out;
}

}  // namespace drillflex::analyses
