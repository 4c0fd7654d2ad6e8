// From a case to what the model builder needs.
#pragma once

#include "io/case.hpp"
#include "model/builder.hpp"

namespace drillflex::io {

model::ModelInput MakeModelInput(const Case& c);

}  // namespace drillflex::io
