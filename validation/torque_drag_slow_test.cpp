// V7 of validation.md, rotating off bottom over the full 10,000 ft at 60° (about 1000 bodies; the
// references and the check in v7_rotating.hpp, their derivation in torque_drag_test.cpp). Label
// `slow-validation`: ~40 s alone (479 Newton iterations: the coupling stages c = 31.6, 100 and
// 1000 each converge only on the mass shift's retry). Measured 2026-12-02: top torque 9,573.0 ft·lbf
// against 9,580 (−0.075 %), hook load 82,611 lbf (−0.005 %).
#include "v7_rotating.hpp"

namespace drillflex::validation {
namespace {

TEST(V7TorqueDragSlow, RotatingOffBottomTorqueWithinTwoPercent) {
  CheckRotatingOffBottom("v7-torque-drag/pipe-60-deg-rotating.yaml", 10000.0);
}

}  // namespace
}  // namespace drillflex::validation
