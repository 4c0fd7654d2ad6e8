// API RP 7G's tool-joint torsional strength and make-up torque (model/tool_joint_torque.hpp) against a
// hand computation of the formula (Python, in inches, psi and ft·lbf as the standard writes it:
// T = Y A/12 (P/(2π) + R_t f/cos 30° + R_s f)) and against a published rating.
#include "model/tool_joint_torque.hpp"

#include <gtest/gtest.h>

#include <utility>

#include "field_units.hpp"

namespace drillflex::model::test {
namespace tool_joint_torque_test {

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

// NC31 (2-7/8 IF: C 3.183 in, L_pc 3.5 in, Q_c 3-29/64 in) on a 4-1/8 × 2-1/8 in tool joint, 120 ksi, f 0.08.
// By hand (Python, the formula as above): B = 0.160838 in, A_p = π/4 ((3.183 − B)² − 2.125²) = 3.626840 in²,
// A_b = π/4 (4.125² − (3.453125 − 0.0625)²) = 4.334838 in² (the pin the weaker), R_t = (2 · 3.183 − 2.875/6)/4
// = 1.471708 in, R_s = (4.125 + 3.453125)/4 = 1.894531 in: T_y = 11 870.714 ft·lbf, make-up 7 122.428 ft·lbf.
TEST(ToolJointTorque, Nc31AgainstTheFormulaByHand) {
  const auto nc31 = FindRotaryConnection("NC31");
  ASSERT_TRUE(nc31);
  const ConnectionStrength strength = ConnectionTorsionalStrength(*nc31, 4.125 * kInch, 2.125 * kInch);
  EXPECT_NEAR(strength.pin_area / (kInch * kInch), 3.626840, 1e-6);
  EXPECT_NEAR(strength.box_area / (kInch * kInch), 4.334838, 1e-6);
  EXPECT_TRUE(strength.pin_weaker);
  EXPECT_NEAR(strength.torsional_yield / kFootPound, 11870.714, 0.01);
  EXPECT_NEAR(strength.makeup_torque / kFootPound, 7122.428, 0.01);
}

// The thread data against API Spec 7-2 (2017), Annex B, Table B.1 (the preferred connections in SI units,
// as a published copy of the table gives them: 123doc.top, "Api spec 7 2 2017"): C, L_pc and Q_c in mm,
// which the table rounds to 0.0001 (C) and 0.01 mm.
TEST(ToolJointTorque, ThreadDataAsApiSpec72TableB1) {
  struct Row {
    const char* name;
    double pitch_diameter, pin_length, counterbore;  // mm
  };
  for (const Row& row : {Row{"NC26", 67.7672, 76.21, 74.63}, Row{"NC31", 80.8482, 88.91, 87.71},
                         Row{"NC38", 96.7232, 101.61, 103.58}, Row{"NC40", 103.4288, 114.31, 110.34},
                         Row{"NC46", 117.5004, 114.31, 124.61}, Row{"NC50", 128.0592, 114.31, 134.95}}) {
    const auto connection = FindRotaryConnection(row.name);
    ASSERT_TRUE(connection) << row.name;
    EXPECT_NEAR(connection->pitch_diameter * 1e3, row.pitch_diameter, 1e-4) << row.name;
    EXPECT_NEAR(connection->pin_length * 1e3, row.pin_length, 0.02) << row.name;
    EXPECT_NEAR(connection->counterbore * 1e3, row.counterbore, 0.02) << row.name;
  }
}

// The internal-flush connections are the numbered ones of the same thread (API Spec 7-2's
// interchangeability; docs/case-format.md), and 4 FH is NC40; the other REG and FH connections are not known.
TEST(ToolJointTorque, CommonNamesAreTheNumberedConnections) {
  for (const auto& [alias, numbered] : {std::pair{"2-3/8 IF", "NC26"}, std::pair{"2 7/8 if", "NC31"},
                                        std::pair{"3-1/2 IF", "NC38"}, std::pair{"4 IF", "NC46"},
                                        std::pair{"4-1/2IF", "NC50"}, std::pair{"4 FH", "NC40"}}) {
    const auto found = FindRotaryConnection(alias);
    ASSERT_TRUE(found) << alias;
    EXPECT_STREQ(found->name, numbered) << alias;
  }
  EXPECT_FALSE(FindRotaryConnection("6-5/8 REG"));
  EXPECT_FALSE(FindRotaryConnection("4-1/2 FH"));
  EXPECT_FALSE(FindRotaryConnection("5-1/2 IF"));
}

}  // namespace tool_joint_torque_test
}  // namespace drillflex::model::test
