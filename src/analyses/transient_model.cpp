#include "analyses/transient_model.hpp"

namespace drillflex::analyses {

model::ModelInput TransientModelInput(const model::ModelInput& input, const TransientSettings& settings) {
  model::ModelInput out = input;
  out.bit_rock = settings.bit_rock;  // the builder then leaves out the bit loads the law replaces
  return out;
}

}  // namespace drillflex::analyses
