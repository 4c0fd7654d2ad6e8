// The WITSML enumeration values (TubularComponent, MaterialType of the 1.4.1.1 schema; 2.0 keeps the
// values) that drillflex's component types and materials stand for.
#include "io/witsml_component_types.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace drillflex::io {
namespace {

using model::ComponentType;

struct TypeEntry {
  std::string_view witsml;
  MappedComponentType mapped;
};

constexpr std::array kTypes{
    TypeEntry{"bit core diamond", {ComponentType::Bit, ""}},
    TypeEntry{"bit core PDC", {ComponentType::Bit, ""}},
    TypeEntry{"bit diamond fixed cut", {ComponentType::Bit, ""}},
    TypeEntry{"bit insert roller cone", {ComponentType::Bit, ""}},
    TypeEntry{"bit mill tooth roller cone", {ComponentType::Bit, ""}},
    TypeEntry{"bit PDC fixed cutter", {ComponentType::Bit, ""}},
    TypeEntry{"stabilizer", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer near bit", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer string", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer inline", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer non-rotating", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer steerable", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer variable blade", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer turbo back", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer near bit roller reamer", {ComponentType::Stabilizer, ""}},
    TypeEntry{"stabilizer string roller reamer", {ComponentType::Stabilizer, ""}},
    TypeEntry{"non-magnetic stabilizer", {ComponentType::Stabilizer, "nonmag"}},
    TypeEntry{"drill collar", {ComponentType::Collar, ""}},
    TypeEntry{"drill collar short", {ComponentType::Collar, ""}},
    TypeEntry{"non-magnetic collar", {ComponentType::Collar, "nonmag"}},
    TypeEntry{"MWD pulser", {ComponentType::Mwd, ""}},
    TypeEntry{"logging while drilling tool", {ComponentType::Lwd, ""}},
    TypeEntry{"jar", {ComponentType::Jar, ""}},
    TypeEntry{"motor", {ComponentType::Motor, ""}},
    TypeEntry{"motor steerable", {ComponentType::Motor, ""}},
    TypeEntry{"motor instrumented", {ComponentType::Motor, ""}},
    TypeEntry{"turbine", {ComponentType::Motor, ""}},
    TypeEntry{"heavy weight drill pipe", {ComponentType::Hwdp, ""}},
    TypeEntry{"heavy weight drill pipe LH", {ComponentType::Hwdp, ""}},
    TypeEntry{"drill pipe", {ComponentType::Pipe, ""}},
    TypeEntry{"drill pipe LH", {ComponentType::Pipe, ""}},
    TypeEntry{"drill pipe compressive", {ComponentType::Pipe, ""}},
    TypeEntry{"sub-crossover", {ComponentType::Crossover, ""}},
};

constexpr std::array<std::pair<std::string_view, std::string_view>, 5> kMaterials{{
    {"steel", "steel"},
    {"steel alloy", "steel"},
    {"chrome alloy", "steel"},
    {"non-magnetic steel", "nonmag"},
    {"aluminum", "aluminium"},
}};

bool EqualIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

std::optional<MappedComponentType> MapTubularComponentType(std::string_view witsml_type) {
  for (const TypeEntry& entry : kTypes) {
    if (EqualIgnoringCase(entry.witsml, witsml_type)) return entry.mapped;
  }
  // Every other sub ("sub-bit", "sub-float", "sub-shock", ...): a plain tube of its OD, ID and length.
  if (witsml_type.size() > 4 && EqualIgnoringCase(witsml_type.substr(0, 4), "sub-")) {
    return MappedComponentType{ComponentType::Sub, ""};
  }
  return std::nullopt;
}

std::optional<std::string_view> MapMaterialType(std::string_view witsml_material) {
  for (const auto& [witsml, material] : kMaterials) {
    if (EqualIgnoringCase(witsml, witsml_material)) return material;
  }
  return std::nullopt;
}

}  // namespace drillflex::io
