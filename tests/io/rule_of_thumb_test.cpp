// The field rule of thumb for the critical RPM (io/analysis_results.hpp ComputeRuleOfThumbCriticalSpeed):
// 33,055 sqrt(OD² + ID²)/L² rpm (in, ft) over the span it picks.
#include <gtest/gtest.h>

#include <cmath>

#include "io/analysis_results.hpp"

namespace drillflex::io {
namespace rule_of_thumb_test {

constexpr double kInch = 0.0254, kFoot = 0.3048, kRpm = kPi / 30.0;

model::Component Pipe(double length_ft, bool joints) {
  model::Component pipe;
  pipe.type = model::ComponentType::Pipe;
  pipe.outer_diameter = 5.0 * kInch;
  pipe.inner_diameter = 4.276 * kInch;
  pipe.length = length_ft * kFoot;
  pipe.count = 30;
  if (joints) pipe.joint_diameter = 6.625 * kInch;
  return pipe;
}

double Rule(double span_ft) { return 33055.0 * std::sqrt(25.0 + 4.276 * 4.276) / (span_ft * span_ft); }

TEST(RuleOfThumb, SpanIsBetweenSupportsElseOneJointElseTheString) {
  Case c;
  c.input.string.components = {Pipe(30.0, true)};
  // Pipe with tool joints, no supports: one joint spacing (30 ft, one joint per 30 ft item).
  RuleOfThumbSpeed rule = ComputeRuleOfThumbCriticalSpeed(c);
  EXPECT_NEAR(rule.span, 30.0 * kFoot, 1e-12);
  EXPECT_NEAR(rule.rotary_speed / kRpm, Rule(30.0), 1e-9 * Rule(30.0));  // 241.63 rpm
  // Two lateral supports 600 ft apart win.
  model::Support low, high;
  low.at = 0.0;
  high.at = 600.0 * kFoot;
  low.fixed[model::kY] = high.fixed[model::kZ] = true;
  c.input.supports = {low, high};
  rule = ComputeRuleOfThumbCriticalSpeed(c);
  EXPECT_NEAR(rule.span, 600.0 * kFoot, 1e-9);
  EXPECT_NEAR(rule.rotary_speed / kRpm, Rule(600.0), 1e-9 * Rule(600.0));
  // No joints and no supports: the whole string (30 × 30 ft).
  c.input.supports.clear();
  c.input.string.components = {Pipe(30.0, false)};
  EXPECT_NEAR(ComputeRuleOfThumbCriticalSpeed(c).span, 900.0 * kFoot, 1e-9);
}

}  // namespace rule_of_thumb_test
}  // namespace drillflex::io
