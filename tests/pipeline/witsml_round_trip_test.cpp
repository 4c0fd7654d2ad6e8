// The bundled example written to WITSML 1.4.1.1 and 2.0 by the test-only writer (tests/witsml_writer.hpp)
// and read again, both ways a user can: a case whose well and string name the documents
// (`witsml:`), and the case `drillflex import` writes (with the example's fluid, model and
// operation added). Each must build the same model and give the same static equilibrium.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "../witsml_writer.hpp"
#include "io/case.hpp"
#include "io/witsml_case.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex {
namespace witsml_round_trip_test {

namespace fs = std::filesystem;
using test_witsml::Version;

const std::string kExample = DRILLFLEX_SOURCE_DIR "/examples/rotary-bha-build/case.yaml";

struct Written {
  fs::path trajectory, geometry, tubular;
};

Written WriteFiles(const io::Case& c, Version version, const std::string& name) {
  const fs::path directory = fs::temp_directory_path() / "drillflex-witsml-round-trip" / name;
  fs::remove_all(directory);
  fs::create_directories(directory);
  const auto documents = test_witsml::WriteDocuments(c, version);
  const Written written{directory / "trajectory.xml", directory / "wbgeometry.xml", directory / "tubular.xml"};
  std::ofstream(written.trajectory) << documents.trajectory;
  std::ofstream(written.geometry) << documents.geometry;
  std::ofstream(written.tubular) << documents.tubular;
  return written;
}

// The example with its well and string replaced by the documents.
io::Case ReferringCase(const io::Case& original, const Written& files) {
  YAML::Node root = YAML::Load(original.text);
  YAML::Node well;
  well["witsml"].push_back(files.trajectory.string());
  well["witsml"].push_back(files.geometry.string());
  well["bit_md"] = root["well"]["bit_md"];
  root["well"] = well;
  YAML::Node string;
  string["witsml"] = files.tubular.string();
  root["string"] = string;
  return io::ParseCase(YAML::Dump(root), "referring.yaml", ".");
}

// The imported case with every key of the example but its name, units, well and string.
io::Case ImportedCase(const io::Case& original, const Written& files) {
  const std::vector<io::WitsmlDocument> documents = {io::ReadWitsmlFile(files.trajectory.string()),
                                                     io::ReadWitsmlFile(files.geometry.string()),
                                                     io::ReadWitsmlFile(files.tubular.string())};
  YAML::Node imported = YAML::Load(io::ImportedCaseText(documents));
  const YAML::Node root = YAML::Load(original.text);
  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    if (key != "name" && key != "units" && key != "well" && key != "string") imported[key] = entry.second;
  }
  return io::ParseCase(YAML::Dump(imported), "imported.yaml", ".");
}

// Relative difference of two results, against the largest magnitude of the quantity along the string.
class Difference {
 public:
  void Add(double a, double b, double scale) {
    largest_ = std::max(largest_, std::abs(a - b) / std::max(scale, 1e-300));
  }
  double largest() const { return largest_; }

 private:
  double largest_ = 0.0;
};

double StaticDifference(const analyses::StaticResult& a, const analyses::StaticResult& b) {
  EXPECT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(a.contacts.size(), b.contacts.size());
  if (a.nodes.size() != b.nodes.size() || a.contacts.size() != b.contacts.size()) return 1.0;
  double position = 0.0, force = 0.0, moment = 0.0, stress = 0.0, contact = 0.0;
  for (const auto& node : a.nodes) {
    position = std::max(position, node.position.norm());
    force = std::max({force, std::abs(node.axial_force), node.shear_force});
    moment = std::max({moment, std::abs(node.torque), node.bending_moment});
    stress = std::max(stress, node.von_mises_stress);
  }
  for (const auto& report : a.contacts) contact = std::max(contact, std::abs(report.normal_force));
  Difference difference;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const auto& x = a.nodes[i];
    const auto& y = b.nodes[i];
    for (int k = 0; k < 3; ++k) difference.Add(x.position[k], y.position[k], position);
    difference.Add(x.axial_force, y.axial_force, force);
    difference.Add(x.shear_force, y.shear_force, force);
    difference.Add(x.torque, y.torque, moment);
    difference.Add(x.bending_moment, y.bending_moment, moment);
    difference.Add(x.von_mises_stress, y.von_mises_stress, stress);
  }
  for (std::size_t i = 0; i < a.contacts.size(); ++i) {
    difference.Add(a.contacts[i].normal_force, b.contacts[i].normal_force, contact);
  }
  if (a.bit && b.bit) difference.Add(a.bit->side_force, b.bit->side_force, std::abs(a.bit->side_force));
  return difference.largest();
}

void ExpectSameModelAndStatic(const io::Case& original, const io::Case& again, const std::string& what) {
  pipeline::CaseModel expected = pipeline::BuildCaseModel(original);
  pipeline::CaseModel model = pipeline::BuildCaseModel(again);
  EXPECT_EQ(model.built.system.bodies().size(), expected.built.system.bodies().size()) << what;
  EXPECT_EQ(model.built.system.num_velocities(), expected.built.system.num_velocities()) << what;
  EXPECT_EQ(model.built.contacts.size(), expected.built.contacts.size()) << what;
  const auto reference = pipeline::RunCaseStatic(original, expected);
  const auto result = pipeline::RunCaseStatic(again, model);
  ASSERT_TRUE(result.converged) << what;
  const double difference = StaticDifference(reference, result);
  std::cout << fmt::format("{}: {} bodies, {} coordinates, largest relative difference of the static results {:.3g}\n",
                           what, model.built.system.bodies().size(), model.built.system.num_velocities(), difference);
  EXPECT_LE(difference, 1e-9) << what;
}

void RoundTrip(Version version, const std::string& name) {
  const io::Case original = io::ReadCase(kExample);
  const Written files = WriteFiles(original, version, name);
  ExpectSameModelAndStatic(original, ReferringCase(original, files), name + " (a case naming the documents)");
  ExpectSameModelAndStatic(original, ImportedCase(original, files), name + " (drillflex import's case)");
}

TEST(WitsmlRoundTrip, BundledExampleThroughWitsml1411) { RoundTrip(Version::V1411, "WITSML 1.4.1.1"); }

TEST(WitsmlRoundTrip, BundledExampleThroughWitsml20) { RoundTrip(Version::V20, "WITSML 2.0"); }

// The string as the documents give it, component by component, against the case's own.
TEST(WitsmlRoundTrip, ComponentsComeBackAsTheCaseGaveThem) {
  const io::Case original = io::ReadCase(kExample);
  const Written files = WriteFiles(original, Version::V20, "components");
  const io::Case again = ReferringCase(original, files);
  ASSERT_EQ(again.input.string.components.size(), original.input.string.components.size());
  for (std::size_t i = 0; i < original.input.string.components.size(); ++i) {
    const auto& a = original.input.string.components[i];
    const auto& b = again.input.string.components[i];
    EXPECT_EQ(a.type, b.type) << i;
    EXPECT_EQ(a.name, b.name) << i;
    EXPECT_EQ(a.material, b.material) << i;
    EXPECT_EQ(a.count, b.count) << i;
    EXPECT_DOUBLE_EQ(a.outer_diameter, b.outer_diameter) << i;
    EXPECT_DOUBLE_EQ(a.inner_diameter, b.inner_diameter) << i;
    EXPECT_DOUBLE_EQ(a.length, b.length) << i;
    EXPECT_EQ(a.blade_diameter.has_value(), b.blade_diameter.has_value()) << i;
    EXPECT_EQ(a.joint_diameter.has_value(), b.joint_diameter.has_value()) << i;
    EXPECT_EQ(a.joint_length.has_value(), b.joint_length.has_value()) << i;
  }
  ASSERT_EQ(again.well->hole.size(), original.well->hole.size());
  for (std::size_t i = 0; i < original.well->hole.size(); ++i) {
    EXPECT_DOUBLE_EQ(again.well->hole[i].diameter, original.well->hole[i].diameter);
    EXPECT_EQ(again.well->hole[i].to_md.has_value(), original.well->hole[i].to_md.has_value());
  }
}

}  // namespace witsml_round_trip_test
}  // namespace drillflex
