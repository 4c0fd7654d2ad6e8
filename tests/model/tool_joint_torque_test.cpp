// API RP 7G's tool-joint torsional strength and make-up torque (model/tool_joint_torque.hpp) against a
// hand computation of the formula (Python, in inches, psi and ft·lbf as the standard writes it:
// T = Y A/12 (P/(2π) + R_t f/cos 30° + R_s f)) and against a published rating.
#include "model/tool_joint_torque.hpp"

#include <gtest/gtest.h>

#include "field_units.hpp"

namespace drillflex::model::test {
namespace {

// NC50 (C 5.0417 in, L_pc 4.5 in, Q_c 5.3125 in, V-0.038R: H 0.216005 in, S_rs 0.038 in, 4 TPI, 2 in/ft) on
// a 6-5/8 in × 3-1/4 in tool joint, 120 ksi, f 0.08. By hand (Python):
//   B = 2 (0.108003 − 0.038) + 0.125 · 2/12 = 0.160839 in, A_p = π/4 ((5.0417 − B)² − 3.25²) = 10.414624 in²,
//   A_b = π/4 (6.625² − (5.3125 − 0.0625)²) = 12.824079 in² (the pin is the weaker),
//   R_t = (5.0417 + 5.0417 − 3.875 · 2/12)/4 = 2.359392 in, R_s = (6.625 + 5.3125)/4 = 2.984375 in,
//   T_y = 120 000 · 10.414624/12 · (0.25/(2π) + R_t 0.08/cos 30° + R_s 0.08) = 51 707.565 ft·lbf,
//   make-up 0.6 T_y = 31 024.539 ft·lbf.
TEST(ToolJointTorque, Nc50AgainstTheFormulaByHand) {
  const auto nc50 = FindRotaryConnection("NC50");
  ASSERT_TRUE(nc50);
  const ConnectionStrength strength = ConnectionTorsionalStrength(*nc50, 6.625 * kInch, 3.25 * kInch);
  EXPECT_NEAR(strength.pin_area / (kInch * kInch), 10.414624, 1e-6);
  EXPECT_NEAR(strength.box_area / (kInch * kInch), 12.824079, 1e-6);
  EXPECT_TRUE(strength.pin_weaker);
  EXPECT_NEAR(strength.torsional_yield / kFootPound, 51707.565, 0.01);
  EXPECT_NEAR(strength.makeup_torque / kFootPound, 31024.539, 0.01);
}

// A published rating of the same joint: Workstrings International's data sheet for 5 in 19.50 lb/ft
// S-135 pipe with 6.625 × 3.250 in NC50 joints (120 ksi; scribd.com/document/552214615) gives a torsional
// strength of 51 200 ft·lbf and a largest recommended make-up torque of 30 700 ft·lbf, both rounded to
// 100 ft·lbf. The formula gives 1.0 % and 1.1 % more: within 1.5 %.
TEST(ToolJointTorque, Nc50AgainstAPublishedRating) {
  const ConnectionStrength strength =
      ConnectionTorsionalStrength(*FindRotaryConnection("NC50"), 6.625 * kInch, 3.25 * kInch);
  EXPECT_NEAR(strength.torsional_yield / kFootPound, 51200.0, 0.015 * 51200.0);
  EXPECT_NEAR(strength.makeup_torque / kFootPound, 30700.0, 0.015 * 30700.0);
}

// A thin box (5.6 in OD, 2 in pin bore) is the weaker: A_b = π/4 (5.6² − 5.25²) = 2.982550 in² by hand,
// R_s = (5.6 + 5.3125)/4: T_y = 14 196.638 ft·lbf.
TEST(ToolJointTorque, AThinBoxIsTheWeaker) {
  const ConnectionStrength strength =
      ConnectionTorsionalStrength(*FindRotaryConnection("NC50"), 5.6 * kInch, 2.0 * kInch);
  EXPECT_FALSE(strength.pin_weaker);
  EXPECT_NEAR(strength.box_area / (kInch * kInch), 2.982550, 1e-6);
  EXPECT_NEAR(strength.torsional_yield / kFootPound, 14196.638, 0.01);
}

TEST(ToolJointTorque, NamesAreFoundLoosely) {
  EXPECT_TRUE(FindRotaryConnection("nc 50"));
  EXPECT_TRUE(FindRotaryConnection("NC-38"));
  EXPECT_FALSE(FindRotaryConnection("NC51"));
}

}  // namespace
}  // namespace drillflex::model::test
