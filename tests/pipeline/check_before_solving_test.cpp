// A case an analysis cannot take is refused before anything is solved (issue 33, item 4): the
// static solve the modes and the vibration start from never runs (the observer hears no analysis
// finish), and the message names the case file and the key.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/case.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {
namespace {

constexpr const char* kCase = R"(name: checks
units: field
well:
  survey: [[0, 0, 0], [1000, 30, 0]]
  hole: [{diameter: 8.5}]
  bit_md: 900
fluid: {density: 10}
string:
  - {type: bit, od: 8.5, length: 1}
  - {type: collar, od: 6.75, id: 2.8125, length: 30, count: 3}
operation: {wob: 10, rpm: 60}
)";

// Runs the case and returns the InputError's message, or "" when it ran; counts the analyses that finished.
std::string Refusal(const std::string& analyses, const AnalysisRequest& request, int& finished) {
  const io::Case c = io::ParseCase(std::string(kCase) + analyses, "checks.yaml");
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
      Refusal("analyses:\n  vibration:\n    excitations:\n      - {type: motor, lateral: 100}\n",
              AnalysisRequest::Only(Analysis::Vibration), finished);
  EXPECT_NE(message.find("checks.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("analyses.vibration.excitations[0]"), std::string::npos) << message;
  EXPECT_EQ(finished, 0) << message;
}

// Without excitations the vibration takes its defaults (analyses::DefaultExcitations) and runs.
TEST(CheckBeforeSolving, AVibrationWithoutExcitationsRunsOnTheDefaults) {
  int finished = 0;
  const std::string message =
      Refusal("analyses:\n  vibration: {rpm: {from: 40, to: 80, step: 20}}\n", AnalysisRequest::Only(Analysis::Vibration),
              finished);
  EXPECT_EQ(message, "");
  EXPECT_EQ(finished, 2);  // the static it starts from, then the vibration
}

}  // namespace
}  // namespace drillflex::pipeline
