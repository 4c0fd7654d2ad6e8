// The drillflex command line run as a user runs it: exit statuses, messages, and result files
// written only when the whole job succeeds.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
