// Builds the SystemModel of a string: components -> uniform sections -> flexible bodies (each at
// most `body_length`, split evenly) -> Craig–Bampton reductions (cached by section) -> couplings
// between consecutive bodies, supports, loads and gravity. Without a well the string lies straight
// along +x from the origin (the bit end at x = 0), the string frame is the global frame.
#pragma once

#include <optional>
#include <vector>

#include "cms/reduction_cache.hpp"
#include "model/build_defaults.hpp"
#include "model/element_handle.hpp"
#include "model/model_input.hpp"
#include "model/string_geometry.hpp"
#include "model/system_model.hpp"

namespace drillflex::model {

class BitBottomElement;
class BitRockElement;
class BitSideCuttingElement;
class BlockElement;
class CouplingElement;
class ImbalanceElement;
class NodalLoadElement;
class StringAboveElement;
class SupportElement;
class TopDriveElement;
class WallContactElement;

// What the builder made, beside the model itself: a typed handle to each element an analysis reads.
struct BuiltModel {
  SystemModel system;
  std::vector<ElementHandle<SupportElement>> supports = {};     // each support, in the case's order
  std::vector<ElementHandle<WallContactElement>> contacts = {};  // each wall contact, from the bit upward
  std::vector<ElementHandle<CouplingElement>> couplings = {};   // body b to body b + 1, from the bit upward
  std::vector<ElementHandle<ImbalanceElement>> imbalances = {};  // in the input's order
  std::vector<ElementHandle<NodalLoadElement>> nodal_loads = {};  // the dead loads, in the model's order
  std::optional<ElementHandle<TopDriveElement>> top_drive = {};
  std::optional<ElementHandle<BlockElement>> block = {};
  std::optional<ElementHandle<BitRockElement>> bit_rock = {};          // the bit-rock interaction
  std::optional<ElementHandle<BitBottomElement>> bit_bottom = {};      // the bit's bottom contact
  std::optional<ElementHandle<BitSideCuttingElement>> bit_side = {};   // the bit's side cutting
  std::optional<ElementHandle<StringAboveElement>> string_above = {};  // the pipe above the top
  double force_scale = 0.0;  // a typical applied force, N (Newton tolerance)

  // The element a handle names, with its type.
  template <class E>
  const E& Get(ElementHandle<E> handle) const {
    return system.Get(handle);
  }
};

BuiltModel BuildSystemModel(const ModelInput& input, cms::ReductionCache& cache);

}  // namespace drillflex::model
