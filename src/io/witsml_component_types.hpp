// typeTubularComp (2.0 TypeTubularComponent) -> a drillflex component type and its material
// (internal to io/; the table is docs/case-format.md "Import").
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "model/string_config.hpp"

namespace drillflex::io {

struct MappedComponentType {
  model::ComponentType type;
  std::string_view material;  // "" = the type's default
};

// The drillflex type of a WITSML component type (case-insensitive), or nullopt when none fits.
std::optional<MappedComponentType> MapTubularComponentType(std::string_view witsml_type);

// The drillflex material of a WITSML typeMaterial, or nullopt when none fits.
std::optional<std::string_view> MapMaterialType(std::string_view witsml_material);

}  // namespace drillflex::io
