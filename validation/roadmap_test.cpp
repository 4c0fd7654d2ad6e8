// V7 of validation.md as a torque-and-drag roadmap (validation/v7-roadmap/pipe-60-deg.yaml, issue 23):
// `drillflex roadmap` on the V7 drill pipe in a straight hole inclined I = 60° from the surface,
// μ = 0.25, bit depths D = 2,500, 5,000, 7,500 and 10,000 ft. Johancsik et al. (1984), a straight
// section with nothing at the bit, at each depth (w_b = 16.523 lbf/ft):
//   pick-up   w_b D (cos I + μ sin I)   (118,388 lbf at 10,000 ft)
//   slack-off w_b D (cos I − μ sin I)   (46,841 lbf)
//   rotating  w_b D cos I               (82,615 lbf)
//   off-bottom torque μ w_b D sin I r_joint / sqrt(1 + μ²)  (9,580 ft·lbf: the rotating pipe climbs the
//     wall, V7; Johancsik's N = w_b sin I gives 9,875, 3.1 % above)
//   on-bottom torque: the same plus the torque on bit (5,000 ft·lbf; WOB 0).
// Each within 3 % (issue 23); measured within 0.6 % (printed).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "v7_pipe.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {
namespace roadmap_test {

constexpr double kJointRadiusFt = 6.625 / 24.0;
constexpr double kTorqueOnBit = 5000.0;  // ft·lbf, the case's

nlohmann::json RunRoadmapCase(const std::string& relative_case) {
  const std::string output = ResultsDirectory(relative_case);
  std::filesystem::remove_all(output);
  std::filesystem::create_directories(std::filesystem::path(output).parent_path());
  const std::string line =
      fmt::format("{} roadmap {} -o {} --jobs 2 > {}.log 2>&1", DRILLFLEX_EXE, CasePath(relative_case), output, output);
  const int status = std::system(line.c_str());
  EXPECT_EQ(status, 0) << line;
  if (status != 0) return nlohmann::json::object();
  std::ifstream file(output + "/roadmap.json");
  return nlohmann::json::parse(file);
}

TEST(V7Roadmap, HookLoadsAndTorquesAtEveryDepthWithinThreePercentOfJohancsik) {
  const nlohmann::json roadmap = RunRoadmapCase("v7-roadmap/pipe-60-deg.yaml");
  ASSERT_TRUE(roadmap.contains("roadmap"));
  const nlohmann::json& points = roadmap["roadmap"]["points"];
  ASSERT_EQ(points.size(), 4u);
  const double w = V7CaseBuoyedWeight(), sin_i = std::sin(kV7Inclination), cos_i = std::cos(kV7Inclination);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const nlohmann::json& point = points[k];
    ASSERT_EQ(point["message"].get<std::string>(), "");
    const double depth = point["bit_md"].get<double>();
    EXPECT_NEAR(depth, 2500.0 * static_cast<double>(k + 1), 1e-9);
    const double weight = w * depth;
    const double torque = kV7Friction * weight * sin_i * kJointRadiusFt / std::sqrt(1.0 + kV7Friction * kV7Friction);
    const struct {
      const char* name;
      double reference;
    } checks[] = {{"pick_up", weight * (cos_i + kV7Friction * sin_i)},
                  {"slack_off", weight * (cos_i - kV7Friction * sin_i)},
                  {"rotating", weight * cos_i},
                  {"off_bottom_torque", torque},
                  {"on_bottom_torque", torque + kTorqueOnBit}};
    for (const auto& check : checks) {
      const double value = point[check.name].get<double>();
      EXPECT_LT(std::abs(RelativeError(value, check.reference)), 0.03)
          << check.name << " at " << depth << " ft: " << value << " against " << check.reference;
      std::printf("V7 roadmap, %5.0f ft: %-17s %10.1f (Johancsik %10.1f, %+.3f %%)\n", depth, check.name, value,
                  check.reference, 100.0 * RelativeError(value, check.reference));
    }
  }
}

}  // namespace roadmap_test
}  // namespace drillflex::validation
