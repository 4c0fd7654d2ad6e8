// The drillflex command line run as a user runs it: exit statuses, messages, and result files
// written only when the whole job succeeds.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct RunResult {
  int status = -1;
  std::string output;
};

RunResult RunDrillflex(const std::string& arguments) {
  const fs::path log = fs::temp_directory_path() / "drillflex-cli-test.log";
  const std::string line = std::string(DRILLFLEX_EXE) + " " + arguments + " > " + log.string() + " 2>&1";
  const int raw = std::system(line.c_str());
  std::ifstream file(log);
  std::stringstream text;
  text << file.rdbuf();
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str()};
}

fs::path FreshDirectory(const std::string& name) {
  const fs::path directory = fs::temp_directory_path() / "drillflex-cli" / name;
  fs::remove_all(directory);
  return directory;
}

const std::string kExample = std::string(DRILLFLEX_SOURCE_DIR) + "/examples/rotary-bha-build/case.yaml";

TEST(Cli, CheckSummarizesTheExampleInItsUnits) {
  const RunResult result = RunDrillflex("check " + kExample);
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("TD 7400 ft MD"));
  EXPECT_THAT(result.output, HasSubstr("max inclination 30 deg"));
  EXPECT_THAT(result.output, HasSubstr("max DLS 3 deg/100ft"));
  EXPECT_THAT(result.output, HasSubstr("weight in air"));
  EXPECT_THAT(result.output, HasSubstr("in 10.5 ppg mud"));
  EXPECT_THAT(result.output, HasSubstr("flexible bodies"));
  EXPECT_THAT(result.output, HasSubstr("the case is valid"));
}

TEST(Cli, WellWritesTheTrajectoryInFieldUnits) {
  const fs::path out = FreshDirectory("well");
  const RunResult result = RunDrillflex("well " + kExample + " -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  ASSERT_TRUE(fs::exists(out / "trajectory.csv"));
  std::ifstream csv(out / "trajectory.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "md,inclination,azimuth,north,east,tvd,dls,hole_diameter");
  std::ifstream json_file(out / "results.json");
  const auto json = nlohmann::json::parse(json_file);
  EXPECT_EQ(json["units"], "field");
  const auto& rows = json["well"]["trajectory"];
  // Stations every 30 ft plus the survey stations: the first row at MD 0, the last at TD 7400 ft.
  EXPECT_DOUBLE_EQ(rows.front()["md"].get<double>(), 0.0);
  EXPECT_NEAR(rows.back()["md"].get<double>(), 7400.0, 1e-9);
  EXPECT_NEAR(rows.back()["inclination"].get<double>(), 30.0, 1e-9);
  // In the build section (5000–6000 ft) the DLS is 3°/100 ft.
  bool seen_build = false;
  for (const auto& row : rows) {
    const double md = row["md"].get<double>();
    if (md > 5000.0 && md < 6000.0) {
      EXPECT_NEAR(row["dls"].get<double>(), 3.0, 1e-9);
      seen_build = true;
    }
    if (md > 4500.0) {
      EXPECT_NEAR(row["hole_diameter"].get<double>(), 8.5, 1e-12);
    }
  }
  EXPECT_TRUE(seen_build);
}

// The static analysis of the bundled example: every station's place in the hole, in field units
// (the hole is 8.835 in cased above 4500 ft, 8.5 in below; the smallest contact diameter is the 5 in
// pipe body), and the bit's tendency in words.
TEST(Cli, StaticWritesThePlaceInTheHoleAndTheBitTendency) {
  const fs::path out = FreshDirectory("static");
  const RunResult result = RunDrillflex("static " + kExample + " -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("wall contacts carry force"));
  EXPECT_THAT(result.output, HasSubstr("smallest clearance to the wall"));
  EXPECT_THAT(result.output, HasSubstr("bit: side force"));
  std::ifstream json_file(out / "results.json");
  const auto json = nlohmann::json::parse(json_file);
  for (const char* key : {"hole_offset", "offset_high_side_angle", "clearance", "hole_diameter"}) {
    EXPECT_TRUE(json["column_units"].contains(key)) << key;
  }
  EXPECT_EQ(json["column_units"]["clearance"], "in");
  const auto& nodes = json["static"]["nodes"];
  ASSERT_GT(nodes.size(), 100u);
  for (const auto& node : nodes) {
    for (const char* key : {"md", "hole_offset", "offset_high_side_angle", "clearance", "hole_diameter"}) {
      ASSERT_TRUE(node.contains(key)) << key;
      EXPECT_TRUE(std::isfinite(node[key].get<double>())) << key;
    }
    const double hole = node["hole_diameter"].get<double>();
    EXPECT_TRUE(hole == 8.5 || hole == 8.835) << hole;
    // clearance + offset = (hole − contact diameter)/2: at least 0 (nothing is wider than the hole),
    // at most (8.835 − 5)/2 in.
    const double gap = node["clearance"].get<double>() + node["hole_offset"].get<double>();
    EXPECT_GE(gap, -1e-9);
    EXPECT_LE(gap, 0.5 * (8.835 - 5.0) + 1e-9);
    EXPECT_GE(node["offset_high_side_angle"].get<double>(), 0.0);
    EXPECT_LT(node["offset_high_side_angle"].get<double>(), 360.0);
    // The MD of the node's cross-section: bit MD − s moved by the axial displacement (about an inch).
    EXPECT_NEAR(node["md"].get<double>(), 7400.0 - node["s"].get<double>(), 0.5);
  }
  const auto& tendency = json["static"]["bit"]["tendency"];
  const std::string inclination = tendency["inclination"], azimuth = tendency["azimuth"];
  EXPECT_TRUE(inclination == "build" || inclination == "drop" || inclination == "hold") << inclination;
  EXPECT_TRUE(azimuth == "right" || azimuth == "left" || azimuth == "none") << azimuth;
  for (const auto& contact : json["static"]["contacts"]) EXPECT_TRUE(contact["component"].is_string());
  std::ifstream csv(out / "static.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_THAT(header, HasSubstr(",hole_offset,offset_high_side_angle,clearance,hole_diameter"));
}

TEST(Cli, BadInputExitsWithTwoNamesTheLineAndWritesNothing) {
  const fs::path directory = FreshDirectory("bad-case");
  fs::create_directories(directory);
  const fs::path case_file = directory / "bad.yaml";
  std::ofstream(case_file) << "units: field\nstring:\n  - {type: collar, od: 6.75, id: 7, length: 30}\n";
  const fs::path out = directory / "out";
  const RunResult result = RunDrillflex("well " + case_file.string() + " -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("bad.yaml:3:"));
  EXPECT_THAT(result.output, HasSubstr("string[0].id"));
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, MissingCaseFileExitsWithTwo) {
  const RunResult result = RunDrillflex("check /no/such/case.yaml");
  EXPECT_EQ(result.status, 2);
  EXPECT_THAT(result.output, HasSubstr("/no/such/case.yaml"));
}

TEST(Cli, UnknownSubcommandExitsNonZero) {
  EXPECT_NE(RunDrillflex("fly " + kExample).status, 0);
}

TEST(Cli, RunRefusesAnalysesThisVersionCannotRunBeforeWritingAnything) {
  const fs::path out = FreshDirectory("run-refused");
  const RunResult result = RunDrillflex("run " + kExample + " -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("vibration"));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
