// Fatigue in doglegs (model/dogleg_fatigue.hpp) against a hand computation of RP 7G's formulas
// (Lubinski 1961; Python, in inches, psi and °/100 ft as RP 7G writes them).
#include "model/dogleg_fatigue.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "field_units.hpp"

namespace drillflex::model::test {
namespace dogleg_fatigue_test {

// 1 °/100 ft in 1/m.
constexpr double kDegPer100Ft = kPi / 180.0 / (100.0 * 0.3048);

// 5 in 19.50 lb/ft grade E (OD 5, ID 4.276 in: A 5.274596 in², I 14.269158 in⁴), E 30e6 psi, 100 000 lbf
// of tension, tool joints 30 ft apart (L = 180 in). By hand: σ_t = 18 958.80 psi,
// σ_b = 19 500 − (10/67) σ_t − (0.6/670²)(σ_t − 33 500)² = 16 387.709 psi, K L = √(T/(E I)) 180 = 2.751140,
// c = 432 000/π · σ_b/(E D) · tanh(KL)/(KL) = 5.416347 °/100 ft; the S-135 line 20 000 (1 − σ_t/145 000)
// = 17 384.993 psi.
TEST(DoglegFatigue, LubinskisPermissibleDoglegByHand) {
  const double area = kPi / 4.0 * (25.0 - 4.276 * 4.276) * kInch * kInch;
  const double inertia = kPi / 64.0 * (625.0 - std::pow(4.276, 4)) * std::pow(kInch, 4);
  const double modulus = 30e6 * kPsi;
  const double tension = 100000.0 * kPoundForce;
  const double grade_e = 75000.0 * kPsi;
  const double allowable = AllowableBendingStress(tension / area, grade_e);
  EXPECT_NEAR(allowable / kPsi, 16387.709, 0.01);
  EXPECT_NEAR(AllowableBendingStress(tension / area, 135000.0 * kPsi) / kPsi, 17384.993, 0.01);
  const double curvature = MaxPermissibleCurvature(allowable, modulus, 5.0 * kInch, tension, modulus * inertia, 180.0 * kInch);
  EXPECT_NEAR(curvature / kDegPer100Ft, 5.416347, 1e-5);
  // At that dogleg the body's bending stress is the allowable one.
  EXPECT_NEAR(DoglegBendingStress(curvature, modulus, 5.0 * kInch, tension, modulus * inertia, 180.0 * kInch) / kPsi,
              16387.709, 0.01);
}

// Without tension Lubinski's factor is 1: the pipe follows the hole, σ = E D κ/2.
TEST(DoglegFatigue, NoTensionNoMagnification) {
  EXPECT_DOUBLE_EQ(LubinskiFactor(0.0, 1e6, 4.5), 1.0);
  EXPECT_NEAR(DoglegBendingStress(1e-3, 2.1e11, 0.127, 0.0, 1e6, 4.5), 0.5 * 2.1e11 * 0.127 * 1e-3, 1e-6);
}

}  // namespace dogleg_fatigue_test
}  // namespace drillflex::model::test
