// The drillflex command line run as a user runs it: exit statuses, messages, and result files
// written only when the whole job succeeds.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace cli_test {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using drillflex::test_cli::RunResult;

RunResult RunDrillflex(const std::string& arguments) {
  return drillflex::test_cli::RunShell(fmt::format("{} {}", DRILLFLEX_EXE, arguments));
}

fs::path FreshDirectory(const std::string& name) { return drillflex::test_cli::FreshDirectory("drillflex-cli", name); }

const std::string kExample = std::string(DRILLFLEX_SOURCE_DIR "/examples/rotary-bha-build/case.yaml");

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
  std::string units;
  std::getline(csv, units);
  EXPECT_EQ(units, "ft,deg,deg,ft,ft,ft,deg/100ft,in");  // the second line: each column's unit
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

// A small case without a well: the imbalance collar of the validation (pinned-pinned, 30 ft).
const std::string kImbalanceCase = std::string(DRILLFLEX_SOURCE_DIR "/validation/imbalance-response/collar.yaml");

// Writes `text` as a case file in a fresh directory and returns its path.
fs::path WriteCase(const std::string& name, const std::string& text) {
  const fs::path directory = FreshDirectory(name + "-case");
  fs::create_directories(directory);
  const fs::path path = directory / "case.yaml";
  std::ofstream(path) << text;
  return path;
}

const char* kCollarYaml = R"(name: cli-collar
units: field
string:
  - {type: collar, od: 8, id: 2.8125, length: 30}
supports:
  - {at: 0, fix: [x, y, z, rx]}
  - {at: 30, fix: [y, z]}
)";

// `transient` on the pinned collar released from a mid-span load: transient.csv with the contract's
// columns and one row per sample, the transient block of results.json, and no progress bar when
// standard error is not a terminal.
TEST(Cli, TransientWritesTheTimeSeriesAndNoProgressBarOffATerminal) {
  const fs::path out = FreshDirectory("transient");
  const fs::path path = WriteCase("transient", std::string(kCollarYaml) + R"(analyses:
  transient:
    duration: 0.05 s
    output_interval: 0.01 s
    time_step: 1 ms
    probes: [15]
    initial_loads:
      - {at: 15, force: [0, 0, 1000]}
)");
  const RunResult result = RunDrillflex("transient " + path.string() + " -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("transient: 0.05 s in 50 steps"));
  EXPECT_THAT(result.output, ::testing::Not(HasSubstr("s left")));
  std::ifstream csv(out / "transient.csv");
  std::string header, units, line;
  std::getline(csv, header);
  std::getline(csv, units);
  EXPECT_EQ(header.rfind("time,surface_rpm,surface_torque,hook_load,bit_rpm,wob,tob,", 0), 0u) << header;
  EXPECT_EQ(units.rfind("s,rpm,", 0), 0u) << units;
  EXPECT_THAT(header, HasSubstr("probe1_lateral_z,probe1_whirl_angle,probe1_contact_force,probe1_bending_moment"));
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 6);  // t = 0, 0.01, ..., 0.05
  const nlohmann::json results = nlohmann::json::parse(std::ifstream(out / "results.json"));
  EXPECT_EQ(results["transient"]["time_series"], "transient.csv");
  EXPECT_EQ(results["transient"]["steps"], 50);
  EXPECT_FALSE(results.contains("static"));
}

TEST(Cli, CheckListsTheTransientsDrives) {
  const fs::path path = WriteCase("check-drives", std::string(kCollarYaml) + R"(analyses:
  transient: {duration: 2 s, top_drive: {rpm: 60, ramp: 0.5 s}, block: {hook_load: 25000}}
)");
  const RunResult result = RunDrillflex("check " + path.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("transient (2 s; top drive 60 rpm in 0.5 s; block hook load 2.5e+04 lbf)"));
  // A velocity block through a line of its own stiffness (lbf/in in field units).
  const fs::path line = WriteCase("check-block-line", std::string(kCollarYaml) + R"(analyses:
  transient: {duration: 2 s, block: {velocity: 0.5, ramp: 1 s, stiffness: 20000}}
)");
  const RunResult with_line = RunDrillflex("check " + line.string());
  ASSERT_EQ(with_line.status, 0) << with_line.output;
  EXPECT_THAT(with_line.output, HasSubstr("block 0.5 ft/s in 1 s through a line of 2e+04 lbf/in"));
}

TEST(Cli, RunWithATransientRunsItAfterTheStatics) {
  const fs::path out = FreshDirectory("run-transient");
  const fs::path path = WriteCase("run-transient", std::string(kCollarYaml) +
                                                       "analyses:\n  static: {}\n  transient: {duration: 0.01 s}\n");
  const RunResult result = RunDrillflex("run " + path.string() + " -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  const nlohmann::json results = nlohmann::json::parse(std::ifstream(out / "results.json"));
  EXPECT_TRUE(results.contains("static"));
  EXPECT_TRUE(results.contains("transient"));
}

TEST(Cli, VibrationWritesTheCriticalSpeedMapAndPrintsCriticalRpmsAndWindows) {
  const fs::path out = FreshDirectory("vibration");
  const RunResult result = RunDrillflex("vibration " + kImbalanceCase + " -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("critical RPMs, most severe first"));
  EXPECT_THAT(result.output, HasSubstr("311.7 rpm: largest amplitude"));
  EXPECT_THAT(result.output, HasSubstr("imbalance 1×"));
  EXPECT_THAT(result.output, HasSubstr("safe windows"));
  EXPECT_THAT(result.output, HasSubstr("reduced basis"));
  std::ifstream csv(out / "vibration.csv");
  std::string header, units;
  std::getline(csv, header);
  std::getline(csv, units);
  EXPECT_EQ(header, "rpm,max_lateral_displacement,s_max_displacement,max_bending_stress,max_contact_force");
  EXPECT_EQ(units, "rpm,in,ft,psi,lbf");  // the case's field units
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 1201);
  std::ifstream json_file(out / "results.json");
  const auto json = nlohmann::json::parse(json_file);
  ASSERT_TRUE(json.contains("vibration"));
  const auto& vibration = json["vibration"];
  for (const char* key : {"rpm", "max_lateral_displacement", "max_bending_stress", "max_contact_force", "critical_rpm",
                          "safe_windows", "critical_speeds", "quietest_windows", "method", "basis_size", "band_modes"}) {
    EXPECT_TRUE(vibration.contains(key)) << key;
  }
  EXPECT_EQ(vibration["rpm"].size(), 1201u);
  // No well: no clearance; the windows follow the bending-stress limit (10 ksi), which the
  // 1 mm whirl at resonance stays far below: one window over the whole sweep.
  EXPECT_FALSE(vibration.contains("max_clearance_ratio"));
  ASSERT_EQ(vibration["safe_windows"].size(), 1u);
  EXPECT_NEAR(vibration["safe_windows"][0]["from"].get<double>(), 280.0, 1e-9);
  ASSERT_EQ(vibration["critical_speeds"].size(), 1u);
  EXPECT_EQ(vibration["critical_speeds"][0]["excitation"].get<int>(), 0);
  EXPECT_EQ(vibration["method"].get<std::string>(), "reduced");
  // The resonance the sweep meets is among the undamped modes counted in its band.
  EXPECT_GE(vibration["band_modes"].get<int>(), 1);
  EXPECT_FALSE(json.contains("modes"));
}

// The bundled example's steady build and turn rates: results.json `tendency` in deg/100 ft, and at
// the steady curvature the bit drills along the hole (d = tilt + S F / WOB = 0, in degrees here);
// tendency.csv one row a static of the search.
TEST(Cli, TendencyWritesTheSteadyBuildAndTurnRates) {
  const fs::path out = FreshDirectory("tendency");
  const RunResult result = RunDrillflex("tendency " + kExample + " --no-report -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("tendency: builds"));
  std::ifstream json_file(out / "results.json");
  const auto json = nlohmann::json::parse(json_file);
  const auto& tendency = json["tendency"];
  const double build = tendency["build_rate"], steerability = tendency["steerability"];
  EXPECT_GT(build, 0.0);  // a near-bit stabilizer's fulcrum: the bundled BHA builds
  EXPECT_LT(build, 10.0);
  const auto& bit = tendency["bit"];
  const double wob_lbf = 1000.0 * tendency["weight_on_bit"].get<double>();
  const double deviation =
      bit["tilt"].get<double>() + steerability * bit["build_force"].get<double>() / wob_lbf * 180.0 / M_PI;
  EXPECT_LT(std::abs(deviation), 1e-4);
  const std::string csv = drillflex::test_cli::ReadFile(out / "tendency.csv");
  EXPECT_THAT(csv, HasSubstr("build_curvature,right_curvature"));
  EXPECT_THAT(csv, HasSubstr("deg/100ft,deg/100ft"));
}

TEST(Cli, TendencyRefusesWhatItCannotTakeBeforeSolving) {
  const fs::path out = FreshDirectory("tendency-bad");
  // No well: named, nothing solved or written.
  const RunResult no_well = RunDrillflex("tendency " + WriteCase("tendency-no-well", kCollarYaml).string() + " -o " +
                                         out.string());
  EXPECT_EQ(no_well.status, 2) << no_well.output;
  EXPECT_THAT(no_well.output, HasSubstr("a tendency needs a well"));
  EXPECT_FALSE(fs::exists(out));
  // A steerability below 0: the file, its line and the key.
  const fs::path path = WriteCase("tendency-steerability",
                                  std::string(kCollarYaml) + "analyses:\n  tendency: {steerability: -0.1}\n");
  const RunResult negative = RunDrillflex("tendency " + path.string() + " -o " + out.string());
  EXPECT_EQ(negative.status, 2) << negative.output;
  EXPECT_THAT(negative.output, HasSubstr("case.yaml:9:"));
  EXPECT_THAT(negative.output, HasSubstr("analyses.tendency.steerability"));
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, VibrationWithAnUnknownMotorSpeedExitsWithTwoAndWritesNothing) {
  const fs::path out = FreshDirectory("vibration-motor");
  const fs::path path = WriteCase(
      "vibration-motor", std::string(kCollarYaml) +
                             "analyses:\n  vibration:\n    excitations:\n      - {type: motor, lobes: 5, lateral: 100, at: 10}\n");
  const RunResult result = RunDrillflex("vibration " + path.string() + " -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("motor speed"));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace cli_test
using namespace cli_test;  // the tests below are outside it

// Every command that solves writes report.html and the VTK files beside results.json; --no-report and
// the case's `output: {report: false, vtk: false}` turn them off; a bad `output` key is bad input.
TEST(Cli, StaticWritesTheReportAndVtkUnlessTurnedOff) {
  const fs::path out = FreshDirectory("report");
  RunResult result = RunDrillflex("static " + kExample + " -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("report.html"));
  for (const char* name : {"report.html", "string.vtp", "well.vtp", "contacts.vtp"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  const fs::path quiet = FreshDirectory("no-report");
  result = RunDrillflex("static " + kExample + " --no-report -o " + quiet.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(fs::exists(quiet / "results.json"));
  for (const char* name : {"report.html", "string.vtp", "well.vtp", "contacts.vtp"}) {
    EXPECT_FALSE(fs::exists(quiet / name)) << name;
  }

  const fs::path directory = FreshDirectory("output-key");
  fs::create_directories(directory);
  std::ifstream example(kExample);
  std::stringstream text;
  text << example.rdbuf();
  fs::copy_file(fs::path(kExample).parent_path() / "survey.csv", directory / "survey.csv");
  std::ofstream(directory / "no-vtk.yaml") << text.str() << "output: {vtk: false}\n";
  const fs::path only_report = directory / "out";
  result = RunDrillflex("static " + (directory / "no-vtk.yaml").string() + " -o " + only_report.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(fs::exists(only_report / "report.html"));
  EXPECT_FALSE(fs::exists(only_report / "string.vtp"));
  std::ofstream(directory / "bad-output.yaml") << text.str() << "output: {report: maybe}\n";
  const fs::path bad = directory / "bad";
  result = RunDrillflex("static " + (directory / "bad-output.yaml").string() + " -o " + bad.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("output.report"));
  EXPECT_FALSE(fs::exists(bad));
}

// `roadmap`: roadmap.csv as the contract gives it (bit MD, friction, the three hook loads, the two
// torques, a line of units), one row a depth and friction factor, pulling out above rotating above
// running in. (Its numbers against Johancsik: validation/roadmap_test.cpp.)
const std::string kRoadmapCase = std::string(DRILLFLEX_SOURCE_DIR "/validation/v7-roadmap/pipe-60-deg.yaml");

TEST(Cli, RoadmapWritesOneRowADepthAndFrictionFactor) {
  // The V7 roadmap case cut to 2,000 ft (its well and pipe), to run quickly.
  std::ifstream v7(kRoadmapCase);
  std::stringstream text;
  text << v7.rdbuf();
  std::string short_case = text.str();
  for (std::size_t at = short_case.find("10000"); at != std::string::npos; at = short_case.find("10000")) {
    short_case.replace(at, 5, "2000");
  }
  const fs::path out = FreshDirectory("roadmap");
  const RunResult result = RunDrillflex("roadmap " + WriteCase("roadmap", short_case).string() +
                                        " --from 1000 --step 1000 --friction 0.2,0.3 --no-report -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("roadmap: 2 depths × 2 friction factors"));
  EXPECT_FALSE(fs::exists(out / "report.html"));
  std::ifstream csv(out / "roadmap.csv");
  std::string header, units, line;
  std::getline(csv, header);
  std::getline(csv, units);
  EXPECT_EQ(header, "bit_md,friction,pick_up,slack_off,rotating,off_bottom_torque,on_bottom_torque,message,hook_load_limit,"
            "torque_limit,helical_slack_off,fatigue_rotating,fatigue_rotating_md,fatigue_on_bottom,fatigue_on_bottom_md,"
            "wear_rotating_time,wear_md,wear_side_force_per_length,wear_groove_depth,wear_remaining_wall,wear_utilisation");
  EXPECT_EQ(units, "ft,-,lbf,lbf,lbf,ft*lbf,ft*lbf,-,lbf,ft*lbf,lbf,-,ft,-,ft,s,ft,lbf/ft,in,in,-");
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',') && row.size() < 7;) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), 4u);
  const double expected[4][2] = {{1000, 0.2}, {1000, 0.3}, {2000, 0.2}, {2000, 0.3}};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 7u);
    EXPECT_EQ(rows[k][0], expected[k][0]);
    EXPECT_EQ(rows[k][1], expected[k][1]);
    EXPECT_GT(rows[k][2], rows[k][4]);  // pick-up above rotating
    EXPECT_GT(rows[k][4], rows[k][3]);  // rotating above slack-off
    EXPECT_GT(rows[k][6], rows[k][5]);  // the torque on bit adds on bottom
  }
  EXPECT_TRUE(fs::exists(out / "roadmap.json"));
}

TEST(Cli, RoadmapBadSettingsExitWithTwoAndWriteNothing) {
  const fs::path out = FreshDirectory("roadmap-bad");
  RunResult result = RunDrillflex("roadmap " + kRoadmapCase + " --from 20000 -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("analyses.roadmap.from"));
  result = RunDrillflex("roadmap " + kRoadmapCase + " --friction 0.2,x -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("analyses.roadmap.friction[1]"));
  result = RunDrillflex("roadmap " + WriteCase("roadmap-no-well", kCollarYaml).string() + " -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("a roadmap needs a well"));
  EXPECT_FALSE(fs::exists(out));
  // `run` leaves the roadmap to its own command.
  result = RunDrillflex("run " + kRoadmapCase + " -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("drillflex roadmap"));
  EXPECT_FALSE(fs::exists(out));
}

// `stability`: a case without a transient, or no --rpm, is bad input (exit 2), nothing written. (The
// map's regimes against known ones: validation/stability_map_test.cpp.)
TEST(Cli, StabilityNeedsATransientAndItsAxes) {
  const fs::path out = FreshDirectory("stability-bad");
  RunResult result = RunDrillflex("stability " + kExample + " --rpm 60,120 --wob 20 -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("analyses.transient"));
  result = RunDrillflex("stability " + kExample + " --wob 20 -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("--rpm"));
  const std::string rotating = std::string(DRILLFLEX_SOURCE_DIR "/examples/rotary-bha-build/rotating.yaml");
  result = RunDrillflex("stability " + rotating + " --rpm 60:10:5 --wob 20 -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("operation.rpm"));
  EXPECT_FALSE(fs::exists(out));
}

// `run` stops at an analysis that fails and writes nothing (docs/case-format.md); with --keep-finished
// it writes the analyses that finished, names the failed one in results.json and the report, and
// exits 3 (issue 33 item 5).
TEST(Cli, RunKeepFinishedWritesTheAnalysesThatFinished) {
  const fs::path path = DRILLFLEX_SOURCE_DIR "/tests/cases/keep-finished.yaml";  // its buckling fails
  const fs::path stopped = FreshDirectory("run-stopped");
  const RunResult plain = RunDrillflex("run " + path.string() + " -o " + stopped.string());
  EXPECT_EQ(plain.status, 3) << plain.output;
  EXPECT_FALSE(fs::exists(stopped));
  const fs::path out = FreshDirectory("run-kept");
  const RunResult kept = RunDrillflex("run " + path.string() + " -o " + out.string() + " --keep-finished");
  EXPECT_EQ(kept.status, 3) << kept.output;
  EXPECT_THAT(kept.output, HasSubstr("the buckling analysis did not finish: the string's lowest lateral frequency"));
  ASSERT_TRUE(fs::exists(out / "results.json")) << kept.output;
  EXPECT_TRUE(fs::exists(out / "modes.csv"));
  EXPECT_TRUE(fs::exists(out / "static.csv"));
  EXPECT_FALSE(fs::exists(out / "buckling.csv"));
  const auto json = nlohmann::json::parse(drillflex::test_cli::ReadFile(out / "results.json"));
  ASSERT_EQ(json["failures"].size(), 1u);
  EXPECT_EQ(json["failures"][0]["analysis"], "buckling");
  EXPECT_TRUE(json.contains("modes"));
  EXPECT_FALSE(json.contains("buckling"));
  EXPECT_TRUE(fs::exists(out / "report.html"));  // drawn in Chromium: tests/CMakeLists.txt report.KeepFinished
}

namespace cli_test {

const std::string kCalibrationCase = std::string(DRILLFLEX_SOURCE_DIR "/examples/calibration/case.yaml");
const std::string kCalibrationReadings = std::string(DRILLFLEX_SOURCE_DIR "/examples/calibration/readings.csv");

// A readings row with an activity the model has none for: exit 2, the file, line and column named, no
// result written.
TEST(Cli, CalibrateRefusesABadReadingAndWritesNothing) {
  const fs::path directory = FreshDirectory("calibrate-bad");
  fs::create_directories(directory);
  const fs::path readings = directory / "readings.csv";
  std::ofstream(readings) << "bit_md,activity,hook_load,surface_torque,wob,rpm\nft,-,klbf,ft*lbf,klbf,rpm\n"
                             "4000,drilling,120,3000,15,80\n4100,tripping,120,,0,0\n";
  const fs::path out = directory / "out";
  const RunResult result =
      RunDrillflex("calibrate " + kCalibrationCase + " --readings " + readings.string() + " -o " + out.string());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("readings.csv:4:"));
  EXPECT_THAT(result.output, HasSubstr("activity"));
  EXPECT_FALSE(fs::exists(out));
  // A parameter name --fit does not know.
  const RunResult unknown = RunDrillflex("calibrate " + kCalibrationCase + " --readings " + kCalibrationReadings +
                                         " --fit open_hole_frction -o " + out.string());
  EXPECT_EQ(unknown.status, 2) << unknown.output;
  EXPECT_THAT(unknown.output, HasSubstr("open_hole_frction"));
  EXPECT_FALSE(fs::exists(out));
}

// The soft string's calibration of the example's synthetic readings (written by the soft string at an
// open-hole friction of 0.32, a cased 0.18, an offset of 80 klbf and a bit coefficient 0.4235, 1 %
// noise: examples/calibration/make_readings.py): every value within its interval of what wrote them.
TEST(Cli, CalibrateFindsWhatWroteTheExamplesReadings) {
  const fs::path out = FreshDirectory("calibrate-example");
  const RunResult result = RunDrillflex("calibrate " + kCalibrationCase + " --readings " + kCalibrationReadings +
                                        " --model soft --no-report -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  const nlohmann::json json = nlohmann::json::parse(drillflex::test_cli::ReadFile(out / "results.json"));
  const nlohmann::json& parameters = json["calibration"]["parameters"];
  const std::pair<const char*, double> truth[] = {{"open_hole_friction", 0.32},
                                                  {"cased_hole_friction", 0.18},
                                                  {"hook_load_offset", 80000.0},  // lbf: the case's force unit
                                                  {"bit_torque_coefficient", 0.4235}};
  for (const auto& [name, value] : truth) {
    EXPECT_TRUE(parameters[name]["fitted"].get<bool>()) << name;
    EXPECT_LE(parameters[name]["low"].get<double>(), value) << name;
    EXPECT_GE(parameters[name]["high"].get<double>(), value) << name;
  }
  EXPECT_TRUE(fs::exists(out / "calibration.csv"));
}

}  // namespace cli_test
