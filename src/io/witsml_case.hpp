// `drillflex import`: WITSML documents written out as a case file, in the units the documents use,
// each line with a comment naming the document and the item it came from.
#pragma once

#include <string>
#include <vector>

#include "io/witsml.hpp"

namespace drillflex::io {

// The case text of one trajectory with its wbGeometry (or neither) and one tubular among the
// documents; the fields not mapped are listed at its head. Throws InputError (at the document's
// object) for a second object of a kind, a trajectory without a wbGeometry or the reverse, and no
// tubular. The text is not checked here: ReadCase it (drillflex import does before writing it).
std::string ImportedCaseText(const std::vector<WitsmlDocument>& documents);

}  // namespace drillflex::io
