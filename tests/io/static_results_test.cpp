// The static results written in the case's output units: the place of each station in the hole
// (hole_offset, offset_high_side_angle, clearance, hole_diameter; the contact's MD), the bit's
// tendency in words and the contacts' component names, from a constructed result.
#include "io/analysis_results.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace drillflex::io {
namespace static_results_test {

namespace fs = std::filesystem;

constexpr double kFt = 0.3048;
constexpr double kIn = 0.0254;
constexpr double kLbf = 4.4482216152605;

Case FieldCaseInAWell() {
  Case c;
  c.name = "static results";
  c.units = c.output_units = units::System::Field;
  c.well.emplace();
  c.well->bit_md = 1000.0 * kFt;
  model::Component collar;
  collar.name = "short collar";
  c.input.string.components = {collar};
  return c;
}

analyses::StaticNodeResult NodeInHole(double s, double md) {
  analyses::StaticNodeResult node;
  node.s = s;
  node.has_wall = node.wall_contact = true;
  node.md = md;
  node.hole_offset = 1.5 * kIn;
  node.offset_high_side_angle = 0.75 * kPi;
  node.clearance = -0.002 * kIn;
  node.hole_diameter = 8.5 * kIn;
  return node;
}

struct Written {
  nlohmann::json json;
  std::string static_csv;
};

Written Write(const Case& c, const analyses::StaticResult& result, const std::string& name) {
  const fs::path directory = fs::temp_directory_path() / "drillflex-static-results-test" / name;
  fs::remove_all(directory);
  ResultFiles files(directory.string());
  AddStaticResults(c, result, files);
  files.Commit();
  std::ifstream json_file(directory / "results.json");
  std::ifstream csv_file(directory / "static.csv");
  std::stringstream csv;
  csv << csv_file.rdbuf();
  return {nlohmann::json::parse(json_file), csv.str()};
}

std::string FirstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(StaticResults, NodesInAHoleCarryTheirPlaceInTheHoleInOutputUnits) {
  const Case c = FieldCaseInAWell();
  analyses::StaticResult result;
  // MD of the node's cross-section 0.1 ft deeper than bit MD − s (the string slid down-hole).
  result.nodes = {NodeInHole(0.0, 1000.1 * kFt), NodeInHole(10.0 * kFt, 990.1 * kFt)};
  const Written written = Write(c, result, "in-hole");
  const auto& nodes = written.json["static"]["nodes"];
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_NEAR(nodes[1]["md"].get<double>(), 990.1, 1e-9);  // the contact's MD, not bit MD − s
  EXPECT_NEAR(nodes[1]["hole_offset"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(nodes[1]["offset_high_side_angle"].get<double>(), 135.0, 1e-12);
  EXPECT_NEAR(nodes[1]["clearance"].get<double>(), -0.002, 1e-15);
  EXPECT_NEAR(nodes[1]["hole_diameter"].get<double>(), 8.5, 1e-12);
  EXPECT_EQ(FirstLine(written.static_csv),
            "s,md,x,y,z,ux,uy,uz,rx,ry,rz,lateral_offset,axial_force,torque,shear_force,bending_moment,"
            "bending_stress,von_mises_stress,hole_offset,offset_high_side_angle,clearance,hole_diameter");
}

TEST(StaticResults, WithoutAWellTheHoleColumnsAreAbsentAndMdIsS) {
  Case c = FieldCaseInAWell();
  c.well.reset();
  analyses::StaticResult result;
  analyses::StaticNodeResult node;
  node.s = 12.0 * kFt;
  result.nodes = {node};
  const Written written = Write(c, result, "no-well");
  const auto& json_node = written.json["static"]["nodes"][0];
  EXPECT_NEAR(json_node["md"].get<double>(), 12.0, 1e-12);
  EXPECT_FALSE(json_node.contains("hole_offset"));
  EXPECT_FALSE(json_node.contains("clearance"));
  EXPECT_EQ(FirstLine(written.static_csv).find("clearance"), std::string::npos);
  EXPECT_FALSE(written.json["static"].contains("bit"));
}

// Side force 1000 lbf: the threshold is 1 % of it + 50 N = 10 lbf + 11.24 lbf.
TEST(StaticResults, BitTendencyAndContactComponent) {
  const Case c = FieldCaseInAWell();
  analyses::StaticResult result;
  result.nodes = {NodeInHole(0.0, 1000.0 * kFt)};
  analyses::BitReport bit;
  bit.build_force = -800.0 * kLbf;
  bit.walk_force = 600.0 * kLbf;
  bit.side_force = 1000.0 * kLbf;
  result.bit = bit;
  analyses::ContactReport contact;
  contact.s = 3.0 * kFt;
  contact.normal_force = 500.0 * kLbf;
  contact.component = 0;
  result.contacts = {contact};
  const Written written = Write(c, result, "bit");
  const auto& tendency = written.json["static"]["bit"]["tendency"];
  EXPECT_EQ(tendency["inclination"], "drop");
  EXPECT_EQ(tendency["azimuth"], "right");
  EXPECT_NEAR(tendency["threshold"].get<double>(), 10.0 + 50.0 / kLbf, 1e-9);
  EXPECT_EQ(written.json["static"]["contacts"][0]["component"], "short collar");
}

}  // namespace static_results_test
}  // namespace drillflex::io
