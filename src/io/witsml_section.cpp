// A case's `witsml:` key (`well: {witsml: ...}`, `string: {witsml: ...}`): the documents it names.
#include <filesystem>

#include "io/case_sections.hpp"

namespace drillflex::io {

std::vector<WitsmlDocument> ReadWitsmlKey(const YamlView& node, const std::string& directory,
                                          std::vector<std::string>& warnings) {
  std::vector<YamlView> files;
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) files.push_back(node.Item(i));
  } else {
    files.push_back(node);
  }
  if (files.empty()) node.Fail("expected a WITSML document (a file name) or a list of them");
  std::vector<WitsmlDocument> documents;
  for (const YamlView& file : files) {
    const std::filesystem::path given(file.AsString());
    const std::filesystem::path path = given.is_absolute() ? given : std::filesystem::path(directory) / given;
    if (!std::filesystem::is_regular_file(path)) file.Fail("cannot read the WITSML document '" + path.string() + "'");
    documents.push_back(ReadWitsmlFile(path.string()));
    warnings.insert(warnings.end(), documents.back().warnings.begin(), documents.back().warnings.end());
  }
  return documents;
}

}  // namespace drillflex::io
