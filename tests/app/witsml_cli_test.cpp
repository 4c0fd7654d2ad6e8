// `drillflex import` and the `witsml:` keys run as a user runs them: the sample documents imported
// to the golden case files (tests/app/golden), a bad document refused with exit 2 and nothing
// written, and a 5 km build-and-turn trajectory given in WITSML (ft, dega) placed by `drillflex well`
// where an independent minimum-curvature computation puts its stations.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace witsml_cli_test {

namespace fs = std::filesystem;
using drillflex::test_cli::ReadFile;
using drillflex::test_cli::RunResult;
using drillflex::test_cli::RunShell;
using ::testing::HasSubstr;

constexpr double kFt = 0.3048;  // m
constexpr double kPi = 3.14159265358979323846;

fs::path Directory(const std::string& name) {
  const fs::path directory = drillflex::test_cli::FreshDirectory("drillflex-witsml-cli", name);
  fs::create_directories(directory);
  return directory;
}

// The import of the samples, run from the source tree with relative paths as the golden file was
// made (`cd SOURCE && drillflex import examples/witsml/V/*.xml -o OUT`), must equal the golden case.
void ExpectGoldenImport(const std::string& version) {
  const fs::path out = Directory("import-" + version) / "case.yaml";
  const RunResult result = RunShell(fmt::format(
      "cd {} && {} import examples/witsml/{v}/trajectory.xml examples/witsml/{v}/wbgeometry.xml "
      "examples/witsml/{v}/tubular.xml -o {}",
      DRILLFLEX_SOURCE_DIR, DRILLFLEX_EXE, out.string(), fmt::arg("v", version)));
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("warning:"));  // the fields not mapped, said aloud
  EXPECT_THAT(result.output, HasSubstr("19 survey stations, 2 hole sections, 8 components written"));
  const fs::path golden = fs::path(DRILLFLEX_SOURCE_DIR) / "tests/app/golden" / ("import-" + version + ".yaml");
  EXPECT_EQ(ReadFile(out), ReadFile(golden)) << "the import differs from " << golden << "; see " << out;
  const RunResult check = RunShell(fmt::format("{} check {}", DRILLFLEX_EXE, out.string()));
  EXPECT_EQ(check.status, 0) << check.output;
  EXPECT_THAT(check.output, HasSubstr("the case is valid"));
}

TEST(WitsmlCli, ImportOfThe1411SamplesIsTheGoldenCase) { ExpectGoldenImport("1.4.1.1"); }

TEST(WitsmlCli, ImportOfThe20SamplesIsTheGoldenCase) { ExpectGoldenImport("2.0"); }

TEST(WitsmlCli, ABadDocumentIsBadInputAndNothingIsWritten) {
  const fs::path directory = Directory("bad");
  const fs::path document = directory / "tubular.xml";
  std::ofstream(document) << "<tubulars xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.1\">\n"
                             "<tubular uid=\"t\"><name>t</name>\n"
                             "<tubularComponent uid=\"c1\"><typeTubularComp>drill collar</typeTubularComp>"
                             "<sequence>1</sequence><id uom=\"in\">2.8125</id><len uom=\"ft\">30</len></tubularComponent>\n"
                             "</tubular></tubulars>\n";
  const fs::path out = directory / "case.yaml";
  const RunResult result = RunShell(fmt::format("{} import {} -o {}", DRILLFLEX_EXE, document.string(), out.string()));
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr(document.string() + ":3:"));
  EXPECT_THAT(result.output, HasSubstr("tubularComponent[uid=c1]: expected a <od> element"));
  EXPECT_FALSE(fs::exists(out));
  // The same document named by a case: the same message, exit 2.
  const fs::path case_file = directory / "uses.yaml";
  std::ofstream(case_file) << "name: uses\nstring: {witsml: tubular.xml}\n";
  const RunResult check = RunShell(fmt::format("{} check {}", DRILLFLEX_EXE, case_file.string()));
  EXPECT_EQ(check.status, 2) << check.output;
  EXPECT_THAT(check.output, HasSubstr("expected a <od> element"));
}

TEST(WitsmlCli, ATrajectoryWithoutItsHoleIsRefused) {
  const fs::path out = Directory("no-hole") / "case.yaml";
  const RunResult result = RunShell(fmt::format("cd {} && {} import examples/witsml/2.0/trajectory.xml "
                                                "examples/witsml/2.0/tubular.xml -o {}",
                                                DRILLFLEX_SOURCE_DIR, DRILLFLEX_EXE, out.string()));
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_THAT(result.output, HasSubstr("a trajectory without a wbGeometry"));
  EXPECT_FALSE(fs::exists(out));
}

struct Station {
  double md, inclination, azimuth;  // ft, deg, deg
};

// 5 km: vertical to 1500 ft, then building 2°/100 ft and turning right 1.5°/100 ft to 60° at 4500 ft,
// then holding 60° and turning 0.5°/100 ft to TD, a station every 100 ft and at 5000 m.
std::vector<Station> BuildAndTurn() {
  std::vector<double> depths;
  for (double md = 0.0; md < 16404.0; md += 100.0) depths.push_back(md);
  depths.push_back(5000.0 / kFt);
  std::vector<Station> stations;
  for (const double md : depths) {
    const double build = std::clamp(md - 1500.0, 0.0, 3000.0);
    const double hold = std::max(md - 4500.0, 0.0);
    const double inclination = 2.0 * build / 100.0;
    const double azimuth = md <= 1500.0 ? 0.0 : 10.0 + 1.5 * build / 100.0 + 0.5 * hold / 100.0;
    // What the document says, to the digits it says it with.
    stations.push_back({std::stod(fmt::format("{:.10g}", md)), std::stod(fmt::format("{:.10g}", inclination)),
                        std::stod(fmt::format("{:.10g}", azimuth))});
  }
  return stations;
}

// Minimum curvature (Bourgoyne et al., Applied Drilling Engineering, SPE 1986, §8.1; SPE's standard
// method): between stations 1 and 2 the dogleg DL = acos(cos(I2 − I1) − sin I1 sin I2 (1 − cos(A2 − A1)))
// and the ratio factor RF = 2/DL tan(DL/2) (1 on a straight course); ΔN = ΔMD/2 (sin I1 cos A1 +
// sin I2 cos A2) RF, ΔE = ΔMD/2 (sin I1 sin A1 + sin I2 sin A2) RF, ΔTVD = ΔMD/2 (cos I1 + cos I2) RF.
std::vector<std::array<double, 3>> MinimumCurvature(const std::vector<Station>& stations) {
  std::vector<std::array<double, 3>> positions = {{0.0, 0.0, 0.0}};
  for (std::size_t i = 1; i < stations.size(); ++i) {
    const double i1 = stations[i - 1].inclination * kPi / 180, i2 = stations[i].inclination * kPi / 180;
    const double a1 = stations[i - 1].azimuth * kPi / 180, a2 = stations[i].azimuth * kPi / 180;
    const double cosine = std::cos(i2 - i1) - std::sin(i1) * std::sin(i2) * (1.0 - std::cos(a2 - a1));
    const double dogleg = std::acos(std::clamp(cosine, -1.0, 1.0));
    const double ratio = dogleg < 1e-12 ? 1.0 : 2.0 / dogleg * std::tan(dogleg / 2.0);
    const double half = (stations[i].md - stations[i - 1].md) / 2.0;
    const auto& p = positions.back();
    positions.push_back({p[0] + half * (std::sin(i1) * std::cos(a1) + std::sin(i2) * std::cos(a2)) * ratio,
                         p[1] + half * (std::sin(i1) * std::sin(a1) + std::sin(i2) * std::sin(a2)) * ratio,
                         p[2] + half * (std::cos(i1) + std::cos(i2)) * ratio});
  }
  return positions;
}

TEST(WitsmlCli, WellPlacesAWitsmlTrajectoryByMinimumCurvatureWithin1mmOver5km) {
  const fs::path directory = Directory("build-and-turn");
  const std::vector<Station> stations = BuildAndTurn();
  std::string body;
  for (std::size_t i = 0; i < stations.size(); ++i) {
    body += fmt::format("<trajectoryStation uid=\"s{}\"><md uom=\"ft\" datum=\"KB\">{:.10g}</md><incl uom=\"dega\">"
                        "{:.10g}</incl><azi uom=\"dega\">{:.10g}</azi></trajectoryStation>\n",
                        i + 1, stations[i].md, stations[i].inclination, stations[i].azimuth);
  }
  std::ofstream(directory / "trajectory.xml")
      << "<trajectorys xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.1\">\n"
         "<trajectory uid=\"t\"><name>build and turn</name>\n"
      << body << "</trajectory></trajectorys>\n";
  std::ofstream(directory / "case.yaml") << "name: build and turn\nunits: field\n"
                                            "well: {witsml: trajectory.xml, hole: 8.5, output_step: 100}\n"
                                            "string: [{type: collar, od: 6.75, id: 2.8125, length: 30}]\n";
  const fs::path out = directory / "out";
  const RunResult result =
      RunShell(fmt::format("{} well {} -o {}", DRILLFLEX_EXE, (directory / "case.yaml").string(), out.string()));
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(ReadFile(out / "results.json"));
  const auto& rows = json["well"]["trajectory"];
  const auto reference = MinimumCurvature(stations);
  double largest = 0.0;  // m
  std::size_t compared = 0;
  for (const auto& row : rows) {
    const double md = row["md"].get<double>();
    const auto station = std::find_if(stations.begin(), stations.end(),
                                      [&](const Station& s) { return std::abs(s.md - md) < 1e-9; });
    if (station == stations.end()) continue;
    const auto& expected = reference[static_cast<std::size_t>(station - stations.begin())];
    const double dn = row["north"].get<double>() - expected[0];
    const double de = row["east"].get<double>() - expected[1];
    const double dv = row["tvd"].get<double>() - expected[2];
    largest = std::max(largest, std::sqrt(dn * dn + de * de + dv * dv) * kFt);
    ++compared;
  }
  EXPECT_EQ(compared, stations.size());
  EXPECT_GT(reference.back()[2], 2000.0);  // the well does go somewhere: TVD over 2000 ft
  std::cout << fmt::format("{} stations over {:.0f} m: largest position error {:.3g} m\n", compared,
                           stations.back().md * kFt, largest);
  EXPECT_LT(largest, 1e-3);
}

}  // namespace witsml_cli_test
