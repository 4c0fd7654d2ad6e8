// The case of the sweep's tests (tests/pipeline/sweep_test.cpp, tests/app/sweep_cli_test.cpp):
// collars and pipe on the low side of a straight hole at 30°, the bit on bottom; a static run of a few
// hundredths of a second.
#pragma once

namespace drillflex::test_cases {

inline constexpr const char* kSweepCase = R"(name: sweep test
units: SI
well:
  survey: [[0, 30, 0], [400, 30, 0]]
  hole: [{diameter: 0.2159}]
  bit_md: 300
fluid: {density: 1200}
string:
  - {type: bit, od: 0.2159, length: 0.3}
  - {type: collar, od: 0.1715, id: 0.0714, length: 9, count: 3}
  - {type: pipe, od: 0.127, id: 0.1086, length: 9, count: 3}
model: {body_length: 9, elements_per_body: 4, modes_per_body: 4}
operation: {wob: 40 kN}
analyses:
  static: {}
)";

}  // namespace drillflex::test_cases
