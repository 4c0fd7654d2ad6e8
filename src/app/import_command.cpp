// `drillflex import FILE... [-o CASE.yaml]`: WITSML documents into a case file. The case is read back
// as `drillflex check` reads it before anything is written; a bad document or a case that would not
// be valid writes nothing.
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"
#include "io/witsml_case.hpp"

namespace drillflex::app {

int RunImport(const CommandOptions& options) {
  std::vector<io::WitsmlDocument> documents;
  for (const std::string& path : options.documents) documents.push_back(io::ReadWitsmlFile(path));
  const std::string text = io::ImportedCaseText(documents);
  const std::string output = options.output_directory;
  const std::filesystem::path directory = std::filesystem::path(output).parent_path();
  io::Case c;
  try {
    c = io::ParseCase(text, output.empty() ? "imported case" : output, directory.empty() ? "." : directory.string());
  } catch (const InputError& error) {
    throw InputError({}, "", fmt::format("the imported case would not be valid, nothing was written: {}", error.what()));
  }
  for (const io::WitsmlDocument& document : documents) {
    for (const std::string& warning : document.warnings) std::cerr << "drillflex: warning: " << warning << "\n";
  }
  if (output.empty()) {
    std::cout << text;
    return kExitOk;
  }
  io::WriteFileAtomically(output, text);
  std::cout << fmt::format("import: {}{} components written to {}\n",
                           c.well ? fmt::format("{} survey stations, {} hole sections, ", c.well->survey.size(),
                                                c.well->hole.size())
                                  : "",
                           c.input.string.components.size(), output);
  return kExitOk;
}

}  // namespace drillflex::app
