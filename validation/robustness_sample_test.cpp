// CI's look at the robustness of the static solve (issue 19): every tenth case of each of the two
// generators of validation/robustness_test.cpp (20 + 20 cases, two at a time on one thread each:
// about two minutes on 2 cores). Every sampled case must converge, with a finite results.json
// (validation/robustness_runner.hpp judges each run); the full runs (label `slow`) assert 99.5 % of
// 200. Then `drillflex buckling`, which finds its equilibria by the static analysis' own path, runs
// on sampled cases of both generators that carry WOB.
#include <gtest/gtest.h>

#include "robustness_cases_adapter.hpp"

namespace drillflex::validation {
namespace {

constexpr int kSampleStep = 10;

fs::path SampleDirectory(const char* name) {
  return fs::path(DRILLFLEX_BINARY_DIR) / "validation-results" / "robustness-sample" / name;
}

TEST(RobustnessSample, EveryTenthCaseOfTheFirstGeneratorConverges) {
  const RobustnessSummary summary = RunGeneratedCases(FirstGeneratorCase, EveryNthCase(kSampleStep),
                                                      SampleDirectory("first"), kFirstGeneratorHeader);
  for (const auto& failure : summary.failures) ADD_FAILURE() << failure;
  EXPECT_EQ(summary.converged, summary.cases) << summary.text;
}

TEST(RobustnessSample, EveryTenthCaseOfTheSecondGeneratorConverges) {
  const RobustnessSummary summary = RunGeneratedCases(SecondGeneratorCase, EveryNthCase(kSampleStep),
                                                      SampleDirectory("second"), kSecondGeneratorHeader);
  for (const auto& failure : summary.failures) ADD_FAILURE() << failure;
  EXPECT_EQ(summary.converged, summary.cases) << summary.text;
}

// `drillflex buckling` exits 0 with a finite load multiplier above 1 (the case's own equilibrium is
// stable) on sampled cases with WOB.
void ExpectBucklingRuns(const GeneratedCase& c, const fs::path& directory) {
  fs::create_directories(directory);
  const RobustnessOutcome outcome = RunGeneratedCase(c, directory, "buckling");
  ASSERT_EQ(outcome.status, 0) << c.stem << ": " << outcome.message;
  const nlohmann::json results =
      nlohmann::json::parse(ReadText(directory / (c.stem + "-buckling") / "results.json"), nullptr, false);
  ASSERT_FALSE(results.is_discarded()) << c.stem;
  const double multiplier = results["buckling"].value("load_factor", -1.0);
  std::cout << fmt::format("{}: buckling load multiplier {:.4f} ({:.2f} s)\n", c.stem, multiplier, outcome.seconds);
  EXPECT_TRUE(std::isfinite(multiplier)) << c.stem;
  // The equilibrium at the case's loads is a stable one (the static solve checks it): no multiplier below 1.
  EXPECT_GE(multiplier, 1.0) << c.stem;
}

TEST(RobustnessSample, BucklingRunsOnSampledCasesWithWob) {
  for (const int index : {0, 30, 40}) ExpectBucklingRuns(FirstGeneratorCase(index), SampleDirectory("buckling"));
  for (const int index : {10, 60}) ExpectBucklingRuns(SecondGeneratorCase(index), SampleDirectory("buckling"));
}

}  // namespace
}  // namespace drillflex::validation
