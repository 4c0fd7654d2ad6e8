#include "model/builder.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "model/build_parts.hpp"
#include "model/lateral_fluid.hpp"
#include "model/placement.hpp"

namespace drillflex::model {

// The parts in the order of the model's elements: couplings, supports, the pipe above, the drives,
// wall contacts, loads, the bit's elements, imbalances (model/build_parts.hpp).
BuiltModel BuildSystemModel(const ModelInput& input, cms::ReductionCache& cache) {
  if (input.string.components.empty()) throw LogicError("BuildSystemModel: the string has no components");
  std::vector<Body> bodies = CutBodies(input, cache);
  if (input.well) PlaceAlongWell(bodies, input.well->trajectory, input.bit_md);
  if (input.transient_fluid_frequency) AttachLateralFluid(input, *input.transient_fluid_frequency, bodies);
  double length = 0.0;
  for (const Body& body : bodies) length = std::max(length, body.s_start + body.length());
  // Elements refer to bodies by address; moving the vector into the SystemModel keeps its buffer.
  ModelDraft draft{input, bodies, length, FindNodeAt(bodies, length), {}};
  auto couplings = PlaceCouplings(draft);
  auto supports = PlaceSupports(draft);
  const auto string_above = PlaceStringAbove(draft);
  const TopDrives drives = PlaceDrives(draft);
  auto contacts = PlaceWallContacts(draft);
  PlacedLoads loads = PlaceLoads(draft);
  const BitElements bit = PlaceBitElements(draft);
  auto imbalances = PlaceImbalances(draft);
  SystemModel system(std::move(bodies), std::move(draft.elements).Release(), length);
  system.set_force_scale(loads.force_scale);
  return BuiltModel{.system = std::move(system),
                    .supports = std::move(supports),
                    .contacts = std::move(contacts),
                    .couplings = std::move(couplings),
                    .imbalances = std::move(imbalances),
                    .nodal_loads = std::move(loads.loads),
                    .top_drive = drives.top_drive,
                    .block = drives.block,
                    .bit_rock = bit.bit_rock,
                    .bit_bottom = bit.bit_bottom,
                    .bit_side = bit.bit_side,
                    .string_above = string_above,
                    .force_scale = loads.force_scale};
}

}  // namespace drillflex::model
