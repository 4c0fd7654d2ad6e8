// Reads a case file: the top-level keys, in an order that lets every section see what it needs
// (the unit system first, the materials before the string).
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "io/case.hpp"
#include "io/case_sections.hpp"
#include "io/model_input.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

constexpr double kStandardGravity = 9.81;  // m/s², the case contract's default with a well

units::System ReadSystem(const YamlView& root, const char* key, units::System fallback) {
  const auto node = root.OptionalChild(key);
  if (!node) return fallback;
  try {
    return units::ParseSystem(node->AsString());
  } catch (const UnitError&) {
    node->Fail(fmt::format("expected SI or field, got '{}'", node->AsString()));
  }
}

Case ReadRoot(const YamlView& root, const std::string& file, const std::string& directory) {
  root.ExpectMap("a case (a map of keys: name, units, well, string, ...)", false);
  root.AllowOnlyKeys({"name", "units", "output_units", "well", "fluid", "gravity", "materials",
                      "string", "model", "supports", "loads", "operation", "analyses", "output", "limits"});
  Case c;
  c.file = file;
  c.directory = directory;
  c.name = root.StringOr("name", std::filesystem::path(file).stem().string());
  if (c.name.empty()) root.Child("name").Fail("the case name must not be empty");
  c.units = ReadSystem(root, "units", units::System::SI);
  c.output_units = ReadSystem(root, "output_units", c.units);

  // Every node below reads bare numbers in the case's unit system.
  const auto context = std::make_shared<ReadContext>(ReadContext{file, c.units});
  const YamlView top(root.node(), "", context);

  if (const auto well = top.OptionalChild("well")) c.well = ReadWellSection(*well, directory, c.warnings);
  if (const auto fluid = top.OptionalChild("fluid")) c.input.fluid = ReadFluidSection(*fluid);
  c.input.gravity = top.QuantityOr("gravity", Quantity::Acceleration, c.well ? kStandardGravity : 0.0);
  if (c.input.gravity < 0.0) top.Child("gravity").Fail("gravity acts along +z (down): give its magnitude, >= 0");
  for (const std::string& name : fe::BuiltInMaterialNames()) {
    if (const auto material = fe::FindBuiltInMaterial(name)) c.input.materials[name] = *material;
  }
  if (const auto materials = top.OptionalChild("materials")) ReadMaterialsSection(*materials, c.input.materials);
  c.input.string = ReadStringSection(top.Child("string"), c.input.materials, directory, c.warnings);
  if (const auto model = top.PresentChild("model")) c.input.settings = ReadModelSection(*model);
  if (const auto supports = top.OptionalChild("supports")) c.input.supports = ReadSupportsSection(*supports);
  if (const auto loads = top.OptionalChild("loads")) c.input.loads = ReadLoadsSection(*loads);
  if (const auto operation = top.PresentChild("operation")) c.input.operation = ReadOperationSection(*operation);
  if (const auto analyses = top.PresentChild("analyses")) c.analyses = ReadAnalysesSection(*analyses, c.input.operation);
  if (const auto output = top.PresentChild("output")) {
    output->ExpectMap("the output files (report: true|false, vtk: true|false)");
    output->AllowOnlyKeys({"report", "vtk"});
    if (const auto report = output->OptionalChild("report")) c.output.report = report->AsBool();
    if (const auto vtk = output->OptionalChild("vtk")) c.output.vtk = vtk->AsBool();
  }
  if (const auto limits = top.PresentChild("limits")) c.limits = ReadLimitsSection(*limits, c);
  CheckCaseConsistency(c, top);
  CompleteModelInput(c);
  return c;
}

}  // namespace

Case ParseCaseWithValues(const std::string& text, const std::string& file, const std::string& directory,
                         const std::vector<CaseValue>& values) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw InputError({file, error.mark.line + 1, error.mark.column + 1}, "",
                     fmt::format("not valid YAML: {}", error.msg));
  }
  const auto context = std::make_shared<ReadContext>(ReadContext{file, units::System::SI});
  const YamlView view(root, "", context, {file, 1, 1});
  view.RefuseRepeatedKeys();
  SetCaseValues(view, values);
  Case c = ReadRoot(view, file, directory);
  c.text = text;
  return c;
}

Case ParseCase(const std::string& text, const std::string& file, const std::string& directory) {
  return ParseCaseWithValues(text, file, directory, {});
}

Case WithValues(const Case& c, const std::vector<CaseValue>& values) {
  return ParseCaseWithValues(c.text, c.file, c.directory, values);
}

Case ReadCase(const std::string& path) {
  std::ifstream stream(path);
  if (!stream) throw InputError({path, 0, 0}, "", "cannot open the case file");
  std::ostringstream text;
  text << stream.rdbuf();
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  return ParseCase(text.str(), path, directory.empty() ? "." : directory.string());
}

double StringLength(const Case& c) { return model::StringLength(c.input.string); }

std::string DefaultOutputDirectory(const Case& c) {
  std::string name;
  for (const char ch : c.name) {
    const bool safe = std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' || ch == '.';
    name.push_back(safe ? ch : '-');
  }
  return (std::filesystem::path("results") / name).string();
}

}  // namespace drillflex::io
