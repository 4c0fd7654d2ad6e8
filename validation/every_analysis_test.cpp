// Every analysis on every generated BHA (issue 33, item 1): the 200 cases of each of the two
// robustness generators (validation/robustness_cases.hpp, robustness_bha_cases.hpp), each with the
// static, 10 modes, the vibration on its default excitations, the buckling and a 1 s transient
// (validation/every_analysis.hpp), through `drillflex run --keep-finished`, two at a time. The static,
// modes, vibration and transient must finish with results on at least 99.5 % of each generator's
// cases (199 of 200: they finish on all 200); the buckling on at least what it does today (187 and 191
// of 200; the issue asks 199: docs/validation.md, "Every analysis on every BHA"), and where it does not,
// results.json names it with a one-line reason. No run may crash, hang or write a NaN. CTest label
// `slow` (about 40 min on 2 cores); the CI sample is in robustness_sample_test.cpp.
// Per case: the times and each analysis's outcome in
// <build>/validation-results/every-analysis/{first,second}/summary.csv.
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "every_analysis.hpp"
#include "robustness_cases_adapter.hpp"

namespace drillflex::validation {
namespace {

constexpr int kRequiredFinished = 199;  // 99.5 % of 200
// The buckling's finished cases today (2026-12-07): the others lie buckled at the case's loads already
// (18: a compression beyond Dawson–Paslay's load, mostly in a vertical section above the kick-off) or
// find no equilibrium or no lateral mode on the way up (4).
constexpr int kBucklingFinishedFirst = 187;
constexpr int kBucklingFinishedSecond = 191;

// DRILLFLEX_ROBUSTNESS_STRIDE=k runs every k-th case only (a quick look; the rates are then not asserted).
int Stride() {
  const char* text = std::getenv("DRILLFLEX_ROBUSTNESS_STRIDE");
  return text ? std::max(1, std::atoi(text)) : 1;
}

void ExpectEveryAnalysisFinishes(const std::vector<GeneratedCase>& cases, const char* name, int buckling_floor) {
  const EveryAnalysisSummary summary =
      RunEveryAnalysisCases(cases, fs::path(DRILLFLEX_BINARY_DIR) / "validation-results" / "every-analysis" / name);
  for (const std::string& problem : summary.problems) ADD_FAILURE() << problem;
  for (const std::string& failure : summary.failures) std::cout << "  " << failure << "\n";
  if (Stride() != 1) {
    std::cout << "(every " << Stride() << "th case only: the rates are not asserted)\n";
    return;
  }
  for (const char* analysis : kEveryAnalysis) {
    const int required = std::string(analysis) == "buckling" ? buckling_floor : kRequiredFinished;
    EXPECT_GE(summary.finished.at(analysis), required) << analysis << ": " << summary.text;
  }
}

TEST(EveryAnalysis, FirstGeneratorFinishesEveryAnalysis) {
  std::vector<GeneratedCase> cases;
  for (const int index : EveryNthCase(Stride())) cases.push_back(WithEveryAnalysis(FirstGeneratorCase(index), 0.0));
  ExpectEveryAnalysisFinishes(cases, "first", kBucklingFinishedFirst);
}

TEST(EveryAnalysis, SecondGeneratorFinishesEveryAnalysis) {
  std::vector<GeneratedCase> cases;
  for (const int index : EveryNthCase(Stride())) {
    cases.push_back(WithEveryAnalysis(SecondGeneratorCase(index), MakeBhaCase(index).rpm));
  }
  ExpectEveryAnalysisFinishes(cases, "second", kBucklingFinishedSecond);
}

}  // namespace
}  // namespace drillflex::validation
