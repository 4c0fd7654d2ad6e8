// V3 of validation.md: a pipe compressed beyond its helical buckling load lies on the wall as a helix
// (validation/v3-helix/*.yaml: 40 mm × 30 mm steel, 40 m, 89 kN, in a 70 mm hole, vertical and
// weightless, and at 30° with its weight). Over the middle 24 m (a pitch or so from each end, where
// the bit's and the hook's holds disturb it), the contacts' direction around the hole turns at a
// constant rate whose pitch must be within 10 % of Lubinski's P = π √(8 EI / F) (Lubinski, Althouse
// & Logan 1962), and the wall contact force per length within 10 % of Mitchell's r F² / (4 EI).
#include <cmath>
#include <cstdio>

#include "validation_support.hpp"

namespace drillflex::validation {
namespace helix_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kYoungsModulus = 2.1e11, kOuter = 0.040, kInner = 0.030, kHole = 0.070, kCompression = 89e3;

struct HelixMeasure {
  double pitch = 0.0;             // m, from the least-squares slope of the unwrapped contact angle
  double force_per_length = 0.0;  // N/m, the contact forces over the span they cover
  int contacts = 0;
};

HelixMeasure MeasureHelix(const nlohmann::json& contacts, double from, double to) {
  std::vector<double> s, angle;
  double force = 0.0;
  for (const auto& contact : contacts) {
    const double at = contact["s"].get<double>();
    if (at < from || at > to) continue;
    const double raw = contact["high_side_angle"].get<double>();
    // Unwrapped: each step taken as the nearest turn (contacts are 5 cm apart, ~4.5° of a 4 m pitch).
    angle.push_back(angle.empty() ? raw : angle.back() + std::remainder(raw - std::fmod(angle.back(), 360.0), 360.0));
    s.push_back(at);
    force += contact["normal_force"].get<double>();
  }
  HelixMeasure measure;
  measure.contacts = static_cast<int>(s.size());
  if (s.size() < 3) return measure;
  double mean_s = 0.0, mean_angle = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    mean_s += s[i] / s.size();
    mean_angle += angle[i] / s.size();
  }
  double covariance = 0.0, variance = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    covariance += (s[i] - mean_s) * (angle[i] - mean_angle);
    variance += (s[i] - mean_s) * (s[i] - mean_s);
  }
  measure.pitch = 360.0 / std::abs(covariance / variance);
  measure.force_per_length = force / (s.back() - s.front());
  return measure;
}

class V3Helix : public ::testing::TestWithParam<const char*> {};

TEST_P(V3Helix, PitchAndContactForceWithinTenPercentOfLubinskiAndMitchell) {
  const auto results = RunCase("static", std::string("v3-helix/") + GetParam() + ".yaml");
  ASSERT_TRUE(results.contains("static"));
  const double bending = kYoungsModulus * kPi * (std::pow(kOuter, 4) - std::pow(kInner, 4)) / 64.0;
  const double clearance = 0.5 * (kHole - kOuter);
  const double pitch = kPi * std::sqrt(8.0 * bending / kCompression);
  const double force_per_length = clearance * kCompression * kCompression / (4.0 * bending);
  const HelixMeasure measured = MeasureHelix(results["static"]["contacts"], 8.0, 32.0);
  std::printf("V3 helix %s: %d contacts over 8–32 m; pitch %.4f m (Lubinski %.4f, %+.2f %%), contact force "
              "%.1f N/m (Mitchell %.1f, %+.2f %%)\n",
              GetParam(), measured.contacts, measured.pitch, pitch, 100.0 * RelativeError(measured.pitch, pitch),
              measured.force_per_length, force_per_length,
              100.0 * RelativeError(measured.force_per_length, force_per_length));
  EXPECT_GT(measured.contacts, 300);  // on the wall along most of the span (a contact node every 5 cm)
  EXPECT_LT(std::abs(RelativeError(measured.pitch, pitch)), 0.10);
  EXPECT_LT(std::abs(RelativeError(measured.force_per_length, force_per_length)), 0.10);
  EXPECT_EQ(results["static"]["method_used"].get<std::string>(), "energy-minimum");
}

INSTANTIATE_TEST_SUITE_P(Validation, V3Helix, ::testing::Values("vertical", "inclined"));

}  // namespace helix_test
}  // namespace drillflex::validation
