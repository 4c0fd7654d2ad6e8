// V8's headline figures do not depend on the friction regularization (validation.md "V8 friction
// regularization"): the wall friction's v_ε (model.contact.friction_velocity; default Ω_ε R_c with
// Ω_ε = 0.01 rad/s, model/builder.hpp kFrictionRegularizationRate: 1.016 mm/s for the 8 in collar)
// at ×0.3 and ×3 of its default, on V8's backward whirl and the eccentric collar (the rolling whirl
// rate −Ω R_c/(R_h − R_c) = −188.24 rpm within V8's 2 %). The stick–slip pendulum has no wall
// contact: its friction is the bit–rock law's, regularized by its own stick speed (1e-3 rad/s in the
// case), which is varied the same way there (the limit cycle's period and peak bit speed within V8's
// 2 % of the exact ones, validation/stick_slip_test.cpp). The variants are the V8 case files with the
// one key added, written to the build tree.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "validation_support.hpp"
#include "whirl_support.hpp"

namespace drillflex::validation {
namespace friction_velocity_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFactors[] = {0.3, 3.0};

// The case file `relative` with `from` replaced by `to`, written to the build tree as `name`.yaml; its
// absolute path (RunCase takes it as it is, and its results go next to it).
std::string Variant(const std::string& relative, const std::string& from, const std::string& to,
                    const std::string& name) {
  std::ifstream in(CasePath(relative));
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::size_t at = yaml.find(from);
  if (at == std::string::npos) throw std::runtime_error(relative + ": no '" + from + "'");
  yaml.replace(at, from.size(), to);
  const std::filesystem::path path = std::filesystem::path(DRILLFLEX_BINARY_DIR "/validation-variants") / (name + ".yaml");
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << yaml;
  return path.string();
}

// The whirl rate over the last 1.5 s of a run's mid-span probe, rpm.
double WhirlRpm(const std::string& results_directory) {
  const CsvColumns csv = ReadCsv(results_directory + "/transient.csv");
  const auto& time = csv["time"];
  return Slope(time, Unwrapped(csv["probe1_whirl_angle"]), time.back() - 1.5) / 6.0;
}

void CheckWhirlAcrossFrictionVelocity(const std::string& relative, const std::string& label) {
  constexpr double kRolling = -100.0 * 4.0 / (6.125 - 4.0);          // rpm
  constexpr double kDefault = 0.01 * 4.0 * 0.0254;                    // m/s, Ω_ε R_c of the 8 in collar
  RunCase("transient", relative, "friction-velocity");
  const double at_default = WhirlRpm(ResultsDirectory(relative) + "-friction-velocity");
  std::printf("V8 friction regularization, %s: v_eps %.4f mm/s (default): whirl %.2f rpm (%+.2f %%)\n", label.c_str(),
              1e3 * kDefault, at_default, 100.0 * RelativeError(at_default, kRolling));
  EXPECT_LT(std::abs(RelativeError(at_default, kRolling)), 0.02);
  for (const double factor : kFactors) {
    const std::string name = label + "-" + std::to_string(static_cast<int>(10 * factor));
    const std::string path = Variant(relative, "contact: {friction: 0.3}",
                                     "contact: {friction: 0.3, friction_velocity: " +
                                         std::to_string(factor * kDefault) + " m/s}",
                                     name);
    RunCase("transient", path);
    const double whirl = WhirlRpm(ResultsDirectory(path));
    std::printf("V8 friction regularization, %s: v_eps %.4f mm/s (x%.1f): whirl %.2f rpm (%+.2f %%; %+.3f %% from the "
                "default's)\n",
                label.c_str(), 1e3 * factor * kDefault, factor, whirl, 100.0 * RelativeError(whirl, kRolling),
                100.0 * RelativeError(whirl, at_default));
    EXPECT_LT(std::abs(RelativeError(whirl, kRolling)), 0.02) << "x" << factor;
  }
}

TEST(V8FrictionRegularization, BackwardWhirlRateWithin2PercentAtAThirdAndThreeTimesTheDefault) {
  CheckWhirlAcrossFrictionVelocity("v8-transient/backward-whirl.yaml", "backward-whirl");
}

TEST(V8FrictionRegularization, EccentricCollarWhirlRateWithin2PercentAtAThirdAndThreeTimesTheDefault) {
  CheckWhirlAcrossFrictionVelocity("v8-transient/eccentric-collar.yaml", "eccentric-collar");
}

// The stick–slip limit cycle (stick_slip_test.cpp's exact pendulum) at ×0.3 and ×3 of the case's
// stick speed: the mean period and the largest peak bit speed over the cycles after the first slip.
TEST(V8FrictionRegularization, StickSlipPeriodAndPeakWithin2PercentAtAThirdAndThreeTimesTheStickSpeed) {
  // The exact limit cycle of v8-transient/stick-slip.yaml (see stick_slip_test.cpp).
  const double shear = 2.1e11 / 2.6, k = shear * kPi * std::pow(0.04, 4) / 32.0 / 10.0;
  const double inertia = 20000.0 * kPi / 32.0 * 0.5, omega_n = std::sqrt(k / inertia), u0 = 1000.0 / k;
  const double delta = std::atan(u0 * omega_n / 1.0);
  const double period = 2.0 * u0 / 1.0 + (2.0 * kPi - 2.0 * delta) / omega_n;
  const double peak = 1.0 + std::sqrt(1.0 + u0 * u0 * omega_n * omega_n);
  for (const double factor : kFactors) {
    const std::string path = Variant("v8-transient/stick-slip.yaml", "stick_speed: 1e-3 rad/s",
                                     "stick_speed: " + std::to_string(factor * 1e-3) + " rad/s",
                                     "stick-slip-" + std::to_string(static_cast<int>(10 * factor)));
    RunCase("transient", path);
    const CsvColumns csv = ReadCsv(ResultsDirectory(path) + "/transient.csv");
    const auto& time = csv["time"];
    std::vector<double> bit;
    for (const double rpm : csv["bit_rpm"]) bit.push_back(rpm * kPi / 30.0);
    // Slip starts: upward crossings of 1 % of Ω (as stick_slip_test.cpp); the peaks between them.
    std::vector<double> starts;
    for (std::size_t i = 1; i < time.size(); ++i) {
      if (bit[i - 1] < 0.01 && bit[i] >= 0.01) {
        starts.push_back(time[i - 1] + (time[i] - time[i - 1]) * (0.01 - bit[i - 1]) / (bit[i] - bit[i - 1]));
      }
    }
    ASSERT_GE(starts.size(), 3u) << "x" << factor;
    const double mean_period = (starts.back() - starts.front()) / static_cast<double>(starts.size() - 1);
    double largest = 0.0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      if (time[i] >= starts.front()) largest = std::max(largest, bit[i]);
    }
    std::printf("V8 friction regularization, stick-slip at stick speed x%.1f: period %.4f s against %.4f s (%+.2f %%), "
                "peak %.4f rad/s against %.4f (%+.2f %%)\n",
                factor, mean_period, period, 100.0 * RelativeError(mean_period, period), largest, peak,
                100.0 * RelativeError(largest, peak));
    EXPECT_LT(std::abs(RelativeError(mean_period, period)), 0.02) << "x" << factor;
    EXPECT_LT(std::abs(RelativeError(largest, peak)), 0.02) << "x" << factor;
  }
}

}  // namespace friction_velocity_test
}  // namespace drillflex::validation
