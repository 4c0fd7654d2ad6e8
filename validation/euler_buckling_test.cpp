// V2 of validation.md: Euler buckling and frequencies under axial load, through the command line.
// The V1 rod with E = 207 GPa, ρ = 7850 kg/m³, modelled as 4 bodies × 10 elements × 12 flexible
// coordinates. References from beam-column theory (formulas below).
#include <cmath>

#include "validation_support.hpp"

namespace drillflex::validation {
namespace euler_buckling_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLength = 5.08, kDiameter = 0.0762, kE = 207e9, kRho = 7850.0;
const double kEI = kE * kPi * std::pow(kDiameter, 4) / 64.0;

// P_cr = π² EI / (K L)².
double EulerLoad(double effective_length_factor) {
  return kPi * kPi * kEI / std::pow(effective_length_factor * kLength, 2);
}

struct EulerCase {
  const char* file;
  double effective_length_factor;
};

class V2EulerLoad : public ::testing::TestWithParam<EulerCase> {};

TEST_P(V2EulerLoad, WithinOnePercentByBothMethods) {
  const EulerCase c = GetParam();
  const auto results = RunCase("buckling", std::string("v2-euler-buckling/") + c.file);
  ASSERT_TRUE(results.contains("buckling"));
  const double reference = EulerLoad(c.effective_length_factor);
  const auto& buckling = results["buckling"];
  EXPECT_LT(std::abs(RelativeError(buckling["critical_load"].get<double>(), reference)), 0.01)
      << "eigenproblem: " << buckling["critical_load"] << " N against " << reference << " N";
  ASSERT_TRUE(buckling["frequency_method"]["converged"].get<bool>());
  EXPECT_LT(std::abs(RelativeError(buckling["frequency_method"]["critical_load"].get<double>(), reference)), 0.01)
      << "frequency against load: " << buckling["frequency_method"]["critical_load"] << " N against " << reference;
  // The case's load is 1 kN: the multiplier is the critical load in kN (the compression read back
  // from the internal forces is 1 kN to about 1e-6).
  EXPECT_NEAR(buckling["load_factor"].get<double>() * 1000.0, buckling["critical_load"].get<double>(), 1e-5 * reference);
}

INSTANTIATE_TEST_SUITE_P(Validation, V2EulerLoad,
                         ::testing::Values(EulerCase{"euler-pinned-pinned.yaml", 1.0},
                                           EulerCase{"euler-clamped-free.yaml", 2.0},
                                           EulerCase{"euler-clamped-clamped.yaml", 0.5},
                                           EulerCase{"euler-clamped-pinned.yaml", 0.6992}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           name = name.substr(6, name.size() - 11);
                           for (char& ch : name) if (ch == '-') ch = '_';
                           return name;
                         });

double LowestFrequency(const std::string& file) {
  const auto results = RunCase("modes", "v2-euler-buckling/" + file);
  if (!results.contains("modes") || results["modes"].empty()) return std::nan("");
  return results["modes"][0]["frequency_hz"].get<double>();
}

// Pinned-pinned: f₀ = (π/2L²) sqrt(EI/ρA) and f(P) = f₀ sqrt(1 − P/P_cr) exactly.
TEST(V2PinnedPinned, FrequencyUnderAxialLoadWithinHalfPercent) {
  const double f0 = kPi / (2.0 * kLength * kLength) * std::sqrt(kEI / (kRho * kPi * kDiameter * kDiameter / 4.0));
  EXPECT_NEAR(f0, 5.9544, 5e-4);  // validation.md's value
  EXPECT_LT(std::abs(RelativeError(LowestFrequency("pinned-pinned-unloaded.yaml"), f0)), 0.005);
  EXPECT_LT(std::abs(RelativeError(LowestFrequency("pinned-pinned-half-critical.yaml"), f0 * std::sqrt(0.5))), 0.005);
  EXPECT_LT(std::abs(RelativeError(LowestFrequency("pinned-pinned-tension.yaml"), f0 * std::sqrt(2.0))), 0.005);
}

// Cantilever under a dead tip load: f/f₀ from the exact beam-column eigenvalue equation
// (validation.md V2, computed), f₀ = 1.8751041² /(2π L²) sqrt(EI/ρA).
TEST(V2Cantilever, DeadLoadTableWithinOnePercent) {
  const double f0 = 1.8751041 * 1.8751041 / (2.0 * kPi * kLength * kLength) *
                    std::sqrt(kEI / (kRho * kPi * kDiameter * kDiameter / 4.0));
  const struct { const char* file; double ratio; } table[] = {
      {"cantilever-dead-load-0.25.yaml", 0.874143},
      {"cantilever-dead-load-0.5.yaml", 0.720862},
      {"cantilever-dead-load-0.75.yaml", 0.515158},
      {"cantilever-dead-load-tension.yaml", 1.36938}};
  for (const auto& row : table) {
    EXPECT_LT(std::abs(RelativeError(LowestFrequency(row.file), row.ratio * f0)), 0.01) << row.file;
  }
}

// Greenhill: a standing column clamped at its base buckles under its own weight w at
// w L³/EI = 7.8373. The case's axial load is 100 N/m, so the multiplier × 100 N/m is w_cr.
TEST(V2Greenhill, SelfWeightColumnWithinTwoPercent) {
  const auto results = RunCase("buckling", "v2-euler-buckling/greenhill.yaml");
  ASSERT_TRUE(results.contains("buckling"));
  const double w_cr = 7.8373 * kEI / std::pow(kLength, 3);
  EXPECT_LT(std::abs(RelativeError(results["buckling"]["load_factor"].get<double>() * 100.0, w_cr)), 0.02);
  ASSERT_TRUE(results["buckling"]["frequency_method"]["converged"].get<bool>());
  EXPECT_LT(std::abs(RelativeError(results["buckling"]["frequency_method"]["load_factor"].get<double>() * 100.0, w_cr)),
            0.02);
}

}  // namespace euler_buckling_test
}  // namespace drillflex::validation
