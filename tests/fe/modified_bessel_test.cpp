#include "fe/modified_bessel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace drillflex::fe {
namespace modified_bessel_test {

const Complex kEighthTurn = std::polar(1.0, kPi / 4.0);  // e^{iπ/4}: arg of sqrt(iω/ν) r

double RelativeError(Complex value, Complex expected) {
  return std::abs(value - expected) / std::abs(expected);
}

TEST(ModifiedBessel, RealArgumentsMatchAbramowitzStegunTable9_8) {
  // A&S Table 9.8: I₀(1) = 1.266065878, I₁(1) = 0.565159104, K₀(1) = 0.421024438,
  // K₁(1) = 0.601907230; e^{−10} I₀(10) = 0.1278333372, e^{10} K₀(10) = 0.3916319344,
  // e^{10} K₁(10) = 0.4107665706.
  const ScaledModifiedBessel at_one = ComputeScaledModifiedBessel(1.0);
  const double e = std::exp(1.0);
  EXPECT_NEAR(at_one.i0.real() * e, 1.266065878, 1e-9);
  EXPECT_NEAR(at_one.i1.real() * e, 0.565159104, 1e-9);
  EXPECT_NEAR(at_one.k0.real() / e, 0.421024438, 1e-9);
  EXPECT_NEAR(at_one.k1.real() / e, 0.601907230, 1e-9);
  EXPECT_NEAR(at_one.i0.imag(), 0.0, 1e-16);
  const ScaledModifiedBessel at_ten = ComputeScaledModifiedBessel(10.0);
  EXPECT_NEAR(at_ten.i0.real(), 0.1278333372, 1e-10);
  EXPECT_NEAR(at_ten.k0.real(), 0.3916319344, 1e-10);
  EXPECT_NEAR(at_ten.k1.real(), 0.4107665706, 1e-10);
}

TEST(ModifiedBessel, KelvinFunctionsMatchAbramowitzStegunTable9_12) {
  // ber x + i bei x = I₀(x e^{iπ/4}), ker x + i kei x = K₀(x e^{iπ/4}) (A&S 9.9.1, 9.9.2).
  // Values of A&S Table 9.12 (x = 1, 2), to the digits mpmath 1.3 confirms (x = 5, 10).
  struct Kelvin {
    double x, ber, bei, ker, kei;
  };
  const std::vector<Kelvin> table = {
      {1.0, 0.9843817812, 0.2495660400, 0.2867062087, -0.4949946365},
      {2.0, 0.7517341827, 0.9722916273, -0.0416645140, -0.2024000678},
      {5.0, -6.2300824787, 0.11603438155, -0.011511727199, 0.011187586510},
      {10.0, 138.84046594, 56.370458554, 1.2946633021e-4, -3.0752456909e-4},
  };
  for (const Kelvin& row : table) {
    const Complex z = row.x * kEighthTurn;
    const ScaledModifiedBessel values = ComputeScaledModifiedBessel(z);
    EXPECT_LT(RelativeError(values.i0 * std::exp(z), {row.ber, row.bei}), 2e-10) << row.x;
    EXPECT_LT(RelativeError(values.k0 * std::exp(-z), {row.ker, row.kei}), 2e-9) << row.x;
  }
}

TEST(ModifiedBessel, ScaledValuesAlongTheEighthTurnMatchMpmath) {
  // mpmath 1.3 (30 digits): e^{−z} I₀, e^{−z} I₁, e^{z} K₀, e^{z} K₁ at z = r e^{iπ/4}. The radii
  // straddle every branch: series (≤ 2), CF1 + Wronskian (Re z ≤ 40), asymptotic I (Re z > 40).
  struct Row {
    double r;
    Complex i0, i1, k0, k1;
  };
  const std::vector<Row> rows = {
      {1e-3, {0.99929289351325903, -0.00070635707581432665},
       {0.00035355316976819931, 0.00035305361156410424},
       {7.0292092386016832, -0.78098150696050814}, {708.10419664357316, -707.10881357496588}},
      {0.5, {0.67330710276270785, -0.20171598827237566},
       {0.15708319419776973, 0.078432742828390036}, {1.4746621608476117, -0.47522835025640943},
       {2.1550793312932954, -1.5156694647322907}},
      {1.9, {0.2711452744013832, -0.15087838216930773},
       {0.25461421268990313, -0.028581653458018467}, {0.81503681048541206, -0.30518668553020382},
       {0.91312432453920584, -0.4919531639945818}},
      {2.1, {0.25401586709362754, -0.13698445607911318},
       {0.24664136382840758, -0.039074759821676264}, {0.77751292193227793, -0.29338200589285499},
       {0.86185503543562661, -0.45633174096536419}},
      {7.0, {0.1402137271086077, -0.060402871420003742},
       {0.13641119494826856, -0.049891592637805356}, {0.43422781605958717, -0.17405015537003772},
       {0.4476864002951389, -0.20373899178768999}},
      {30.0, {0.067405978129794172, -0.028159058038807584},
       {0.066947689232569466, -0.027023330884941628}, {0.21103355176731037, -0.086702112842853291},
       {0.21250992842584587, -0.09018207577727362}},
      {39.0, {0.059096319839925303, -0.024638462429999754},
       {0.058786097830155606, -0.023874461464587734}, {0.18516470793395154, -0.076215271311203408},
       {0.18615827533227452, -0.078569754724043432}},
      {41.0, {0.05763331375538815, -0.024020754653369391},
       {0.057345359113687744, -0.023312304055029852}, {0.18060404522791649, -0.074360613224696286},
       {0.18152542398391857, -0.07654594908181334}},
      {100.0, {0.036876434240468683, -0.015313192198115787},
       {0.03680039276758987, -0.015128211174383769}, {0.11573084622523415, -0.047818327272330923},
       {0.11597153673591856, -0.048395120376433055}},
      {1000.0, {0.01165595560986368, -0.0048292628081226448},
       {0.011653542614594317, -0.0048234329456593916},
       {0.036614472770645624, -0.015162422465603551},
       {0.036622059106499628, -0.015180723787558681}},
  };
  for (const Row& row : rows) {
    const ScaledModifiedBessel values = ComputeScaledModifiedBessel(row.r * kEighthTurn);
    EXPECT_LT(RelativeError(values.i0, row.i0), 1e-14) << "I0 at |z| = " << row.r;
    EXPECT_LT(RelativeError(values.i1, row.i1), 1e-14) << "I1 at |z| = " << row.r;
    EXPECT_LT(RelativeError(values.k0, row.k0), 1e-14) << "K0 at |z| = " << row.r;
    EXPECT_LT(RelativeError(values.k1, row.k1), 1e-14) << "K1 at |z| = " << row.r;
  }
}

TEST(ModifiedBessel, WronskianHoldsFromTinyToHugeArguments) {
  // I₀(z) K₁(z) + I₁(z) K₀(z) = 1/z (A&S 9.6.15), the scale factors cancelling.
  for (const double angle : {0.0, kPi / 4.0, 1.2}) {
    for (double r = 1e-3; r <= 2e4; r *= 1.37) {
      const Complex z = std::polar(r, angle);
      const ScaledModifiedBessel v = ComputeScaledModifiedBessel(z);
      const Complex w = z * (v.i0 * v.k1 + v.i1 * v.k0);
      EXPECT_LT(std::abs(w - 1.0), 2e-14) << "|z| = " << r << ", arg z = " << angle;
    }
  }
}

TEST(ModifiedBessel, BranchesAgreeWhereTheyMeet) {
  auto expect_close = [](const ScaledModifiedBessel& a, const ScaledModifiedBessel& b,
                         bool compare_i, bool compare_k, double tolerance, double r) {
    if (compare_i) {
      EXPECT_LT(RelativeError(a.i0, b.i0), tolerance) << "I0 at " << r;
      EXPECT_LT(RelativeError(a.i1, b.i1), tolerance) << "I1 at " << r;
    }
    if (compare_k) {
      EXPECT_LT(RelativeError(a.k0, b.k0), tolerance) << "K0 at " << r;
      EXPECT_LT(RelativeError(a.k1, b.k1), tolerance) << "K1 at " << r;
    }
  };
  // Series against the continued fractions across |z| = 2 (the series is still good there).
  for (const double r : {2.0 * (1 - 1e-12), 2.0 * (1 + 1e-12), 2.5}) {
    const Complex z = r * kEighthTurn;
    expect_close(ComputeScaledModifiedBesselSeries(z), ComputeScaledModifiedBessel(z), true, true,
                 1e-14, r);
  }
  // CF1 + Wronskian against the asymptotic expansion across Re z = 40, and CF2 against the
  // asymptotic K (both exact to round-off there: the smallest asymptotic term is ~e^{−2|z|}).
  for (const double r : {40.0 * std::sqrt(2.0) * (1 - 1e-12), 40.0 * std::sqrt(2.0) * (1 + 1e-12),
                         300.0, 5000.0}) {
    const Complex z = r * kEighthTurn;
    expect_close(ComputeScaledModifiedBesselAsymptotic(z), ComputeScaledModifiedBessel(z), true, true,
                 1e-14, r);
  }
}

TEST(ModifiedBessel, RemaindersKeepTheirDigitsAtSmallArguments) {
  // mpmath 1.3: I₀ − 1, I₁ − z/2 and K₁ − 1/z at z = 1e-3 e^{iπ/4} and 1.5 e^{iπ/4}.
  const BesselRemainders tiny = ComputeSmallArgumentBesselRemainders(1e-3 * kEighthTurn);
  EXPECT_LT(RelativeError(tiny.i0_less_one, {-1.5624999999999993e-14, 2.4999999999999957e-7}),
            1e-14);
  EXPECT_LT(RelativeError(tiny.i1_less_linear, {-4.4194175665583091e-11, 4.4194171982735273e-11}),
            1e-14);
  EXPECT_LT(RelativeError(tiny.k1_less_pole, {-0.0029377048287031571, -0.002382345192730869}),
            1e-14);
  const BesselRemainders mid = ComputeSmallArgumentBesselRemainders(1.5 * kEighthTurn);
  EXPECT_LT(RelativeError(mid.i0_less_one, {-0.078927816453744236, 0.55756006230308669}), 1e-14);
  EXPECT_LT(RelativeError(mid.i1_less_linear, {-0.16246509688782071, 0.13453533206985843}),
            1e-14);
  EXPECT_LT(RelativeError(mid.k1_less_pole, {-0.47241320177604154, 0.054360235624774273}),
            1e-14);
  EXPECT_THROW(ComputeSmallArgumentBesselRemainders(3.0), LogicError);
}

TEST(ModifiedBessel, RejectsArgumentsOutsideTheRightHalfPlane) {
  EXPECT_THROW(ComputeScaledModifiedBessel(0.0), LogicError);
  EXPECT_THROW(ComputeScaledModifiedBessel({-1.0, 1.0}), LogicError);
  EXPECT_THROW(ComputeScaledModifiedBessel({0.0, 3.0}), LogicError);
  EXPECT_THROW(ComputeScaledModifiedBessel({std::nan(""), 1.0}), LogicError);
}

}  // namespace modified_bessel_test
}  // namespace drillflex::fe
