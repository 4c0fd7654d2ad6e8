// What the reader adds to a case's model input once every section is read: the trajectory, hole and
// bit MD of its well, a rotating string's sliding friction, the WOB a hook load leaves.
#pragma once

#include "io/case.hpp"
#include "model/builder.hpp"

namespace drillflex::io {

// Throws InputError (operation.hook_load) when the hook load is more than the string's buoyed
// weight along the hole.
void CompleteModelInput(Case& c);

}  // namespace drillflex::io
