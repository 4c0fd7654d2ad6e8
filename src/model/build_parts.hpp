// The builder's parts (model/builder.cpp BuildSystemModel puts them together, in this order, which is
// the order of the model's elements): the bodies cut and placed, then each kind of element placed by
// its own function in its own file. Internal to the builder.
#pragma once

#include <optional>
#include <utility>
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

inline constexpr double kGravityDirection[3] = {0.0, 0.0, 1.0};  // global +z is down

// What the parts build on and add to: the input, the bodies cut from it and placed along the well
// (the elements refer to them by address), the string's length and its top node, and the elements.
struct ModelDraft {
  const ModelInput& input;
  const std::vector<Body>& bodies;
  double length = 0.0;       // of the string, m
  std::pair<Index, Index> top;   // the top node: (body, node)
  ElementList elements;
};

// build_bodies.cpp: the string cut into bodies of at most body_length (cut where bends and supports
// sit), each section reduced once through the cache; offsets into q and v set.
std::vector<Body> CutBodies(const ModelInput& input, cms::ReductionCache& cache);
// Masses (kg) and inertias (kg·m²) of one FE element of a body, for spring damping.
Vec6 ElementInertia(const Body& body);
// c = 2 ζ √(k m), ζ = kCouplingDampingRatio: a spring damped against the inertia it holds.
double SpringDamping(double stiffness, double inertia);
Vec6 SpringDamping(const Vec6& stiffness, const Vec6& inertia);

// build_couplings.cpp: body b to body b + 1, each as stiff as the stiffer section, a bent housing's
// rotation built in.
std::vector<ElementHandle<CouplingElement>> PlaceCouplings(ModelDraft& draft);
// build_supports.cpp: the case's supports (the default well supports without them), adjusted for the
// guided top, the drives and side cutting.
std::vector<ElementHandle<SupportElement>> PlaceSupports(ModelDraft& draft);
// build_top.cpp: the pipe above the top (where the default supports leave it to lie on the wall), and
// the transient's top drive and block.
std::optional<ElementHandle<StringAboveElement>> PlaceStringAbove(ModelDraft& draft);
struct TopDrives {
  std::optional<ElementHandle<TopDriveElement>> top_drive;
  std::optional<ElementHandle<BlockElement>> block;
};
TopDrives PlaceDrives(ModelDraft& draft);
// build_wall_contacts.cpp: a wall contact at every node (a joint once), from the bit upward.
std::vector<ElementHandle<WallContactElement>> PlaceWallContacts(ModelDraft& draft);
// build_loads.cpp: the applied loads, each group its own elements, and the force scale, N (a typical
// applied force: the Newton tolerance's).
struct PlacedLoads {
  std::vector<ElementHandle<NodalLoadElement>> loads;
  double force_scale = 0.0;
};
PlacedLoads PlaceLoads(ModelDraft& draft);
// build_bit.cpp: the bit's elements (the bit-rock law, the bottom contact, side cutting) and the
// imbalances.
struct BitElements {
  std::optional<ElementHandle<BitRockElement>> bit_rock;
  std::optional<ElementHandle<BitBottomElement>> bit_bottom;
  std::optional<ElementHandle<BitSideCuttingElement>> bit_side;
};
BitElements PlaceBitElements(ModelDraft& draft);
std::vector<ElementHandle<ImbalanceElement>> PlaceImbalances(ModelDraft& draft);

}  // namespace drillflex::model
