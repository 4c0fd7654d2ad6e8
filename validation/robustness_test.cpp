// Robustness of the static solve (issue 19): 200 randomized cases of each of two generators
// (validation/robustness_cases.hpp: build-and-turn wells with 1–3 stabilizers;
// validation/robustness_bha_cases.hpp: motors with bent housings, packed, pendulum and slick BHAs,
// vertical holes, drops and turns, rotating or not) run through `drillflex static`, two at a time
// on one thread each (validation/robustness_runner.hpp judges each run). At least 99.5 % of each
// generator's cases must converge (≥ 199 of 200); the rest must stop with a message; none may hang,
// crash, write a NaN or a partial result. CTest label `slow` (~10 min on 2 cores in a Release build
// with assertions); the CI sample is robustness_sample_test.cpp. Per case: the path that found the
// equilibrium, the times and the memory in <build>/validation-results/robustness*/summary.csv.
#include <cstdlib>

#include <gtest/gtest.h>

#include "robustness_cases_adapter.hpp"

namespace drillflex::validation {
namespace robustness_test {

constexpr int kCaseCount = kCasesPerGenerator;
// 99.5 % of 200: at most one case may stop (with its message).
constexpr int kRequiredConverged = 199;

// DRILLFLEX_ROBUSTNESS_STRIDE=k runs every k-th case only (a quick look; the rate is then not asserted).
int Stride() {
  const char* text = std::getenv("DRILLFLEX_ROBUSTNESS_STRIDE");
  return text ? std::max(1, std::atoi(text)) : 1;
}

void ExpectRobust(const RobustnessSummary& summary, int stride) {
  for (const auto& failure : summary.failures) ADD_FAILURE() << failure;
  if (stride == 1) {
    EXPECT_GE(summary.converged, kRequiredConverged) << summary.text;
  } else {
    std::cout << "(every " << stride << "th case only: the rate is not asserted)\n";
  }
}

TEST(Robustness, GeneratorSpansTheStatedRanges) {
  double min_clearance = 1e9, max_inclination = 0.0, max_dls = 0.0, min_wob = 1e9, max_wob = 0.0;
  int by_stabilizers[4] = {0, 0, 0, 0};
  for (int i = 0; i < kCaseCount; ++i) {
    const RobustnessCase c = MakeRobustnessCase(i);
    EXPECT_LE(c.max_dls_deg_per_100ft, 10.0 + 1e-9) << i;
    EXPECT_GE(c.clearance_in, 0.25) << i;
    EXPECT_GE(c.final_inclination_deg, 0.0) << i;
    EXPECT_LE(c.final_inclination_deg, 100.0) << i;
    EXPECT_GE(c.bha_length_ft, 60.0) << i;
    EXPECT_LE(c.bha_length_ft, 150.0) << i;
    ASSERT_EQ(static_cast<int>(c.stabilizer_at_ft.size()), c.stabilizers) << i;
    for (std::size_t k = 1; k < c.stabilizer_at_ft.size(); ++k) EXPECT_GE(c.stabilizer_at_ft[k] - c.stabilizer_at_ft[k - 1], 5.0) << i;
    EXPECT_LE(c.stabilizer_at_ft.back() + 5.0, c.bha_length_ft + 1e-9) << i;
    EXPECT_GT(c.hole_in - c.blade_under_gauge_in, c.collar_od_in) << i;
    // The string stays well below the first survey station (the surface).
    EXPECT_LT(c.string_length_ft, c.bit_md_ft - 300.0) << i;
    EXPECT_GE(c.bit_md_ft, c.kop_ft) << i;
    EXPECT_LE(c.bit_md_ft, c.survey.back().md_ft) << i;
    min_clearance = std::min(min_clearance, c.clearance_in);
    max_inclination = std::max(max_inclination, c.final_inclination_deg);
    max_dls = std::max(max_dls, c.max_dls_deg_per_100ft);
    min_wob = std::min(min_wob, c.wob_klbf);
    max_wob = std::max(max_wob, c.wob_klbf);
    ++by_stabilizers[c.stabilizers];
  }
  // The 200 cases reach the corners of the stated ranges.
  EXPECT_LT(min_clearance, 0.30);
  EXPECT_GT(max_inclination, 95.0);
  EXPECT_GT(max_dls, 9.5);
  EXPECT_LT(min_wob, 2.0);
  EXPECT_GT(max_wob, 48.0);
  for (int n = 1; n <= 3; ++n) EXPECT_GT(by_stabilizers[n], 40) << n << " stabilizers";
}

TEST(Robustness, FirstGeneratorConvergesOnAtLeast995Percent) {
  const int stride = Stride();
  const RobustnessSummary summary =
      RunGeneratedCases(FirstGeneratorCase, EveryNthCase(stride),
                        fs::path(DRILLFLEX_BINARY_DIR) / "validation-results" / "robustness", kFirstGeneratorHeader);
  ExpectRobust(summary, stride);
}

TEST(Robustness, SecondGeneratorSpansTheStatedRanges) {
  int by_shape[4] = {0, 0, 0, 0}, by_kind[4] = {0, 0, 0, 0}, rotating = 0;
  double min_hole = 1e9, max_hole = 0.0, min_bend = 1e9, max_bend = 0.0, max_wob = 0.0, min_mud = 1e9, max_mud = 0.0;
  for (int i = 0; i < kCaseCount; ++i) {
    const BhaCase c = MakeBhaCase(i);
    ++by_shape[static_cast<int>(c.shape)];
    ++by_kind[static_cast<int>(c.kind)];
    rotating += c.rpm > 0.0 ? 1 : 0;
    min_hole = std::min(min_hole, c.hole_in);
    max_hole = std::max(max_hole, c.hole_in);
    if (c.kind == BhaKind::kMotor) {
      min_bend = std::min(min_bend, c.bend_deg);
      max_bend = std::max(max_bend, c.bend_deg);
      EXPECT_GE(c.bend_deg, 0.5) << i;
      EXPECT_LE(c.bend_deg, 2.5) << i;
    }
    if (c.shape == WellShape::kVertical) {
      EXPECT_LE(c.inclination_deg, 2.0) << i;
    }
    max_wob = std::max(max_wob, c.wob_klbf);
    min_mud = std::min(min_mud, c.mud_ppg);
    max_mud = std::max(max_mud, c.mud_ppg);
    EXPECT_LT(c.string_length_ft, c.bit_md_ft - 300.0 + 1e-9) << i;
    EXPECT_LE(c.bit_md_ft, c.survey.back().md_ft) << i;
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT(by_shape[k], 30) << WellShapeName(static_cast<WellShape>(k));
    EXPECT_GT(by_kind[k], 30) << BhaKindName(static_cast<BhaKind>(k));
  }
  EXPECT_GT(rotating, 70);
  EXPECT_LT(rotating, 130);
  EXPECT_EQ(min_hole, 6.125);
  EXPECT_EQ(max_hole, 17.5);
  EXPECT_LT(min_bend, 0.7);
  EXPECT_GT(max_bend, 2.3);
  EXPECT_GT(max_wob, 43.0);
  EXPECT_LT(min_mud, 9.0);
  EXPECT_GT(max_mud, 15.5);
}

TEST(Robustness, SecondGeneratorConvergesOnAtLeast995Percent) {
  const int stride = Stride();
  const RobustnessSummary summary =
      RunGeneratedCases(SecondGeneratorCase, EveryNthCase(stride),
                        fs::path(DRILLFLEX_BINARY_DIR) / "validation-results" / "robustness-bha", kSecondGeneratorHeader);
  ExpectRobust(summary, stride);
}

}  // namespace robustness_test
}  // namespace drillflex::validation
