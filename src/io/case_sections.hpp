// The readers of each section of a case file (internal to io/). Each reads one YAML map into
// plain config structs in SI and throws InputError at the offending node.
#pragma once

#include <map>
#include <string>

#include "io/case.hpp"
#include "io/witsml.hpp"
#include "io/yaml_view.hpp"

namespace drillflex::io {

// `warnings` gathers what WITSML documents named by a `witsml:` key give that drillflex does not read.
WellConfig ReadWellSection(const YamlView& node, const std::string& directory, std::vector<std::string>& warnings);
model::FluidConfig ReadFluidSection(const YamlView& node);
void ReadMaterialsSection(const YamlView& node, std::map<std::string, fe::Material>& materials);
// A list of components, or `{witsml: FILE}`: the tubular of a WITSML document (relative to `directory`).
model::StringConfig ReadStringSection(const YamlView& node, const std::map<std::string, fe::Material>& materials,
                                      const std::string& directory, std::vector<std::string>& warnings);
// The WITSML documents a `witsml:` key names (a file or a list of files, relative to `directory`),
// their warnings appended to `warnings` (io/witsml_section.cpp).
std::vector<WitsmlDocument> ReadWitsmlKey(const YamlView& node, const std::string& directory,
                                          std::vector<std::string>& warnings);
model::ModelSettings ReadModelSection(const YamlView& node);
std::vector<model::Support> ReadSupportsSection(const YamlView& node);
std::vector<model::Load> ReadLoadsSection(const YamlView& node);
model::Operation ReadOperationSection(const YamlView& node);
// `operation` gives the drives' defaults (its rpm and hook load).
analyses::AnalysesConfig ReadAnalysesSection(const YamlView& node, const model::Operation& operation);
model::TopDrive ReadTopDrive(const YamlView& node, const model::Operation& operation);
model::BlockDrive ReadBlock(const YamlView& node, const model::Operation& operation);
// `limits:` (io/limits_section.cpp): the design factor and casing wear; `c` read up to its operation
// and well (a wear run needs a cased section and a rotary speed).
LimitsConfig ReadLimitsSection(const YamlView& node, const Case& c);
// `analyses.transient.bit_rock` (io/bit_rock_section.cpp).
model::BitRockParameters ReadBitRockSection(const YamlView& node);

// Writes `values` into the case's YAML tree below `root` (io/case_values.cpp; ParseCaseWithValues).
void SetCaseValues(const YamlView& root, const std::vector<CaseValue>& values);

// Checks that need more than one section: the string fits the hole at every MD, the string does
// not reach above the surface, supports and loads lie on the string. `root` locates messages.
void CheckCaseConsistency(const Case& c, const YamlView& root);

}  // namespace drillflex::io
