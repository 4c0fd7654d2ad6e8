// V9 of validation.md: the directional tendency (analyses/tendency_analysis.hpp).
//
// 1. Three-point geometry: a bent motor whose bit, pad and stabilizer are at full gauge, weightless,
//    with S -> oo: the steady curvature is the circle through the three points, 2 θ (L − b)/(L (L − a))
//    (v9-tendency/three-point.yaml), within 0.2 %, toward the toolface. Measured at toolfaces 0, 90 and
//    180: −0.03 %, 88.8° (the high side turns by ΔA cos I along a hole that turns: about 1.2° over the
//    BHA here), 180°.
// 2. MADSim's turn-loading static (v9-tendency/madsim-turn.yaml, the top guided as MADSim's): the bit's,
//    the near-bit pad's and the stabilizer's contact forces, the largest bending moment and the top's
//    within 15 % of MADSim's (measured +12.4 %, +13.0 %, −11.6 %, +12.6 %, +11.2 %; the top free carried
//    11 403 ft·lbf there, −55 %).
// 3. MADSim's sliding motor yield (v9-tendency/madsim-motor.yaml) against WOB and steerability: the yield
//    rises with WOB from 5 to 35 klbf and moves by less than 0.5°/100 ft from a steerability of 5 % to
//    25 %, as MADSim's does (13.53 → 15.16, and 14.87 → 14.69 at 30 klbf). The level is not MADSim's:
//    23.1°/100 ft against 14.87 at 30 klbf. An independent planar beam-column of MADSim's own element
//    table (v9-tendency/madsim_yield_reference.py) gives 22.5 there, and the yield at 30 klbf is asserted
//    within 1.5°/100 ft of it (docs/validation.md says what was checked and what is open).
// 4. Point-the-bit (v9-tendency/point-the-bit.yaml): the bit, a full-gauge stabilizer at the fulcrum and
//    one 14.75 ft up, weightless, S -> oo: the steady curvature at full steer is the circle through the
//    three points, 2 θ / L with the offset θ at the lower contact, within 0.2 % and 1.5° of the toolface,
//    at toolfaces 0, 90 and 180; rotating at 60 rpm the same (the housing holds the toolface); at 50 %
//    steer half of it (the time-averaged deviation of a linear, force-free fit), within 0.5 %.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "validation_support.hpp"

namespace drillflex::validation {
namespace tendency_test {

constexpr double kDegreesPerRadian = 57.29577951308232;

// The case `relative` with `from` replaced by `to`, written beside its results; its path.
std::string Variant(const std::string& relative, const std::string& from, const std::string& to,
                    const std::string& name) {
  std::ifstream in(CasePath(relative));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const std::filesystem::path path = std::filesystem::path(ResultsDirectory(relative) + "-" + name + ".yaml");
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path.string();
}

nlohmann::json RunFile(const std::string& command, const std::string& path) {
  const std::string output = path + ".results";
  std::filesystem::remove_all(output);
  const std::string line = fmt::format("{} {} {} --no-report -o {} > {}.log 2>&1", DRILLFLEX_EXE, command, path, output, output);
  if (std::system(line.c_str()) != 0) {
    ADD_FAILURE() << line << " failed";
    return nlohmann::json::object();
  }
  std::ifstream file(output + "/results.json");
  return nlohmann::json::parse(file);
}

// The case `relative` (S -> oo, its `toolface: 0` put at 0, 90 and 180): the steady dogleg is the circle
// through its three full-gauge contacts, `three_point` deg/100 ft, within 0.2 %, toward the toolface
// within 1.5°, and the three-point yield is reported beside. The build rates at the three toolfaces.
std::vector<double> ExpectTheCircleAtEachToolface(const std::string& relative, double three_point) {
  std::vector<double> builds;
  for (const double toolface : {0.0, 90.0, 180.0}) {
    const std::string path =
        Variant(relative, "toolface: 0", fmt::format("toolface: {:g}", toolface), fmt::format("tf{:g}", toolface));
    const auto results = RunFile("tendency", path);
    EXPECT_TRUE(results.contains("tendency")) << path;
    if (!results.contains("tendency")) return {};
    const auto& t = results["tendency"];
    const double build = t["build_rate"], right = t["right_curvature"], dogleg = t["dogleg_severity"];
    const double direction = std::atan2(right, build) * kDegreesPerRadian;
    std::printf("V9 %s, toolface %g: build %+.4f, right %+.4f, dogleg %.4f deg/100 ft (three-point %.4f, %+.3f %%), "
                "toward %.2f deg\n",
                relative.c_str(), toolface, build, right, dogleg, three_point,
                100.0 * RelativeError(dogleg, three_point), direction);
    EXPECT_LT(std::abs(RelativeError(dogleg, three_point)), 2e-3);
    EXPECT_NEAR(t["three_point"]["dogleg_severity"].get<double>(), three_point, 1e-9 * three_point);  // reported beside
    EXPECT_LT(std::abs(std::remainder(direction - toolface, 360.0)), 1.5);
    builds.push_back(build);
  }
  return builds;
}

TEST(V9Tendency, ThreePointMotorIsTheCircleThroughItsContacts) {
  const double bend = 1.0, a = 2.75, b = 4.75, L = 14.75;  // deg, ft
  const double three_point = 2.0 * bend * (L - b) / (L * (L - a)) * 100.0;  // deg/100 ft
  ExpectTheCircleAtEachToolface("v9-tendency/three-point.yaml", three_point);
}

// The same motor rotating (60 rpm): its bend sweeps every toolface and the deviation averaged over
// them vanishes in the hole of no curvature (by the geometry's symmetry): the BHA drills straight.
TEST(V9Tendency, ThreePointMotorRotatingDrillsStraight) {
  const auto results = RunFile("tendency", Variant("v9-tendency/three-point.yaml", "rpm: 0", "rpm: 60", "rotating"));
  ASSERT_TRUE(results.contains("tendency"));
  const auto& t = results["tendency"];
  std::printf("V9 three-point rotating: dogleg %.3g deg/100 ft over %d toolfaces\n", t["dogleg_severity"].get<double>(),
              t["toolfaces"].get<int>());
  EXPECT_EQ(t["toolfaces"].get<int>(), 4);
  EXPECT_LT(t["dogleg_severity"].get<double>(), 0.01);
}

// The point-the-bit system's geometric yield at full steer: the circle through the bit, the fulcrum's
// stabilizer and the one above, 2 θ / L (the three-point formula with the bend at the lower contact).
constexpr double kPointOffset = 0.8, kPointStabilizer = 14.75;  // deg, ft
constexpr double kPointThreePoint = 2.0 * kPointOffset / kPointStabilizer * 100.0;  // deg/100 ft

TEST(V9Tendency, PointTheBitIsTheCircleThroughItsContacts) {
  const std::vector<double> builds = ExpectTheCircleAtEachToolface("v9-tendency/point-the-bit.yaml", kPointThreePoint);
  ASSERT_EQ(builds.size(), 3u);
  EXPECT_NEAR(builds[2], -builds[0], 1e-3 * builds[0]);  // the low side drops as the high side builds
}

// Rotating, the housing holds the offset at its toolface (a rotating bent motor's bend averages out:
// ThreePointMotorRotatingDrillsStraight); at 50 % steer the rate is half, the natural tendency nothing.
TEST(V9Tendency, PointTheBitRotatingHoldsItsToolfaceAndHalfSteerHalvesIt) {
  const auto rotating = RunFile("tendency", Variant("v9-tendency/point-the-bit.yaml", "rpm: 0", "rpm: 60", "rotating"));
  ASSERT_TRUE(rotating.contains("tendency"));
  const double spun = rotating["tendency"]["build_rate"];
  const auto half = RunFile("tendency", Variant("v9-tendency/point-the-bit.yaml", "steer: 1", "steer: 0.5", "half"));
  ASSERT_TRUE(half.contains("tendency"));
  const auto& steering = half["tendency"]["steering"];
  const double at_half = half["tendency"]["build_rate"], natural = steering["natural"]["build_rate"],
               full = steering["full"]["build_rate"], per_steer = steering["yield_per_steer"]["build_rate"];
  std::printf("V9 point-the-bit rotating at 60 rpm: %.4f deg/100 ft (three-point %.4f); 50 %% steer %.4f (natural "
              "%.4f, full %.4f, per unit of steer %.4f)\n",
              spun, kPointThreePoint, at_half, natural, full, per_steer);
  EXPECT_LT(std::abs(RelativeError(spun, kPointThreePoint)), 2e-3);
  EXPECT_NEAR(natural, 0.0, 1e-3 * kPointThreePoint);
  EXPECT_LT(std::abs(RelativeError(full, kPointThreePoint)), 2e-3);
  EXPECT_NEAR(per_steer, full - natural, 1e-9 * kPointThreePoint);
  EXPECT_EQ(steering["type"].get<std::string>(), "point");
  EXPECT_NEAR(steering["offset"].get<double>(), kPointOffset, 1e-12);
  EXPECT_LT(std::abs(RelativeError(at_half, 0.5 * full)), 5e-3);
}

TEST(V9Tendency, MadsimTurnLoadingStaticWithinFifteenPercent) {
  const auto results = RunCase("static", "v9-tendency/madsim-turn.yaml");
  ASSERT_TRUE(results.contains("static"));
  const auto& st = results["static"];
  double pad = 0.0, stabilizer = 0.0, peak_moment = 0.0, peak_at = 0.0, top_moment = 0.0, top_at = 0.0;
  for (const auto& contact : st["contacts"]) {
    const double s = contact["s"];
    if (std::abs(s - 2.75) < 0.6) pad += contact["normal_force"].get<double>();
    if (std::abs(s - 36.75) < 0.6) stabilizer += contact["normal_force"].get<double>();
  }
  for (const auto& node : st["nodes"]) {
    if (node["s"].get<double>() >= top_at) {
      top_at = node["s"];
      top_moment = node["bending_moment"];
    }
    if (node["bending_moment"].get<double>() > peak_moment) {
      peak_moment = node["bending_moment"];
      peak_at = node["s"];
    }
  }
  const double bit = st["bit"]["side_force"];
  std::printf("V9 MADSim turn: bit %.0f lbf (%+.1f %%), pad %.0f lbf (%+.1f %%), stabilizer %.0f lbf (%+.1f %%), "
              "largest bending moment %.0f ft*lbf at %.2f ft (%+.1f %%), at the top (%.2f ft) %.0f ft*lbf (%+.1f %%)\n",
              bit, 100.0 * RelativeError(bit, 14800.0), pad, 100.0 * RelativeError(pad, 17342.0), stabilizer,
              100.0 * RelativeError(stabilizer, 2187.0), peak_moment, peak_at, 100.0 * RelativeError(peak_moment, 40574.0),
              top_at, top_moment, 100.0 * RelativeError(top_moment, 25570.0));
  EXPECT_LT(std::abs(RelativeError(bit, 14800.0)), 0.15);
  EXPECT_LT(std::abs(RelativeError(pad, 17342.0)), 0.15);
  EXPECT_LT(std::abs(RelativeError(stabilizer, 2187.0)), 0.15);
  EXPECT_LT(std::abs(RelativeError(peak_moment, 40574.0)), 0.15);
  EXPECT_NEAR(peak_at, 2.75, 0.3);  // at the near-bit pad, as MADSim's
  EXPECT_NEAR(top_at, 105.25, 0.01);
  EXPECT_LT(std::abs(RelativeError(top_moment, 25570.0)), 0.15);  // the guided top's moment
}

double Yield(const std::string& replace, const std::string& with, const std::string& name) {
  const auto results = RunFile("tendency", Variant("v9-tendency/madsim-motor.yaml", replace, with, name));
  return results.contains("tendency") ? results["tendency"]["build_rate"].get<double>() : std::nan("");
}

TEST(V9Tendency, MadsimMotorYieldRisesWithWobAndHardlyMovesWithSteerability) {
  const double at_5 = Yield("wob: 30,", "wob: 5,", "wob5");
  const double at_35 = Yield("wob: 30,", "wob: 35,", "wob35");
  const double s5 = Yield("steerability: 0.05", "steerability: 0.05", "s5");
  const double s25 = Yield("steerability: 0.05", "steerability: 0.25", "s25");
  std::printf("V9 MADSim motor yield: WOB 5 klbf %.2f deg/100 ft (MADSim 13.53), 35 klbf %.2f (15.16); at 30 klbf "
              "S 5 %% %.2f (14.87), 25 %% %.2f (14.69)\n",
              at_5, at_35, s5, s25);
  // The level is that of an independent planar beam-column of the same BHA (v9-tendency/
  // madsim_yield_reference.py: MADSim's element table, its wall and pads, the top guided, the same
  // criterion): 22.50 deg/100 ft at 30 klbf and S 0.05; MADSim's 14.87 is 7.6 below it.
  EXPECT_NEAR(s5, 22.50, 1.5);
  EXPECT_GT(at_35, at_5 + 0.5);
  EXPECT_LT(std::abs(s25 - s5), 0.5);
}

}  // namespace tendency_test
}  // namespace drillflex::validation
