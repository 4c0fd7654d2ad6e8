// A run that keeps what finished (RunOptions::keep_finished, issue 33 item 5): an analysis whose
// solver fails is named in CaseResults::failures with its reason, the analyses before and beside it
// keep their results, and results.json names the failure; without it the failure ends the run.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/case.hpp"
#include "pipeline/case_files.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {
namespace keep_finished_test {

// tests/cases/keep-finished.yaml: its buckling fails after its static and modes.
io::Case KeepFinishedCase() { return io::ReadCase(DRILLFLEX_SOURCE_DIR "/tests/cases/keep-finished.yaml"); }

TEST(KeepFinished, TheBucklingThatFailsIsNamedAndTheStaticAndModesStand) {
  const io::Case c = KeepFinishedCase();
  RunOptions options;
  options.keep_finished = true;
  const CaseResults results = RunCase(c, CaseAnalyses(c), options);
  ASSERT_TRUE(results.static_result.has_value());
  EXPECT_TRUE(results.static_result->converged);
  ASSERT_TRUE(results.modes.has_value());
  EXPECT_EQ(results.modes->modes.size(), 3u);
  EXPECT_FALSE(results.buckling.has_value());
  ASSERT_EQ(results.failures.size(), 1u);
  EXPECT_EQ(results.failures[0].analysis, Analysis::Buckling);
  // The solver's reason, without its "buckling: " (the failure names the analysis).
  EXPECT_EQ(results.failures[0].message.rfind("the string's lowest lateral frequency does not fall", 0), 0u)
      << results.failures[0].message;
  const io::ResultFiles files = ComposeResultFiles(c, results, {});
  const auto& json = files.json();
  ASSERT_TRUE(json.contains("failures"));
  ASSERT_EQ(json["failures"].size(), 1u);
  EXPECT_EQ(json["failures"][0]["analysis"], "buckling");
  EXPECT_TRUE(json.contains("static"));
  EXPECT_TRUE(json.contains("modes"));
  EXPECT_FALSE(json.contains("buckling"));
}

TEST(KeepFinished, WithoutItTheFailureEndsTheRun) {
  const io::Case c = KeepFinishedCase();
  EXPECT_THROW(RunCase(c, CaseAnalyses(c), {}), SolverError);
}

// A static that fails (ten steps of dynamic relaxation for a string that must settle on the wall of a
// build) takes the modes that start from it along (named, not run); the buckling, which solves its
// own equilibria, is tried on its own.
TEST(KeepFinished, AFailedStaticNamesTheModesItLeavesUnrun) {
  const io::Case c = io::WithValues(KeepFinishedCase(), {{"analyses.static", "{method: relaxation, max_iterations: 1}"}});
  RunOptions options;
  options.keep_finished = true;
  const CaseResults results = RunCase(c, CaseAnalyses(c), options);
  EXPECT_FALSE(results.static_result.has_value());
  EXPECT_FALSE(results.modes.has_value());
  ASSERT_GE(results.failures.size(), 2u);
  EXPECT_EQ(results.failures[0].analysis, Analysis::Static);
  EXPECT_EQ(results.failures[1].analysis, Analysis::Modes);
  EXPECT_EQ(results.failures[1].message, "not run: it starts from the static equilibrium, which failed");
}

}  // namespace keep_finished_test
}  // namespace drillflex::pipeline
