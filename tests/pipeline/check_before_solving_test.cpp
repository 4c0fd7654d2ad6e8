// A case an analysis cannot take is refused before anything is solved (issue 33, item 4): the
// static solve the modes and the vibration start from never runs (the observer hears no analysis
// finish), and the message names the case file and the key.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/case.hpp"
#include "pipeline/case_run.hpp"
#include "../sweep_case.hpp"

namespace drillflex::pipeline {
namespace check_before_solving_test {

// The sweep tests' case (collars and pipe in a straight 30° hole) at 60 rpm with `vibration` as its
// vibration settings, run: the InputError's message, or "" when it ran; counts the analyses that finished.
std::string Refusal(const std::string& vibration, const AnalysisRequest& request, int& finished) {
  const io::Case c = io::WithValues(io::ParseCase(test_cases::kSweepCase, "checks.yaml"),
                                    {{"operation.rpm", "60"}, {"analyses.vibration", vibration}});
  RunOptions options;
  options.observer.finished = [&finished](Analysis, const CaseResults&) { ++finished; };
  try {
    RunCase(c, request, options);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(CheckBeforeSolving, AMotorExcitationWithoutAMotorIsRefusedBeforeTheStatic) {
  int finished = 0;
  const std::string message =
      Refusal("{excitations: [{type: motor, lateral: 100}]}", AnalysisRequest::Only(Analysis::Vibration), finished);
  EXPECT_NE(message.find("checks.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("analyses.vibration.excitations[0]"), std::string::npos) << message;
  EXPECT_EQ(finished, 0) << message;
}

// Without excitations the vibration takes its defaults (analyses::DefaultExcitations) and runs.
TEST(CheckBeforeSolving, AVibrationWithoutExcitationsRunsOnTheDefaults) {
  int finished = 0;
  const std::string message =
      Refusal("{rpm: {from: 40, to: 80, step: 20}}", AnalysisRequest::Only(Analysis::Vibration), finished);
  EXPECT_EQ(message, "");
  EXPECT_EQ(finished, 2);  // the static it starts from, then the vibration
}

}  // namespace check_before_solving_test
}  // namespace drillflex::pipeline
