// V2 of validation.md, torque and weight inside the string (issue 21 items 2 and 3), through the
// command line:
//  * Greenhill's rod clamped at both ends under a torque (and under torque and compression together):
//    references from the clamped–clamped solution of EI u'''' + P u'' + i T u''' = 0, u = v + i w
//    (Greenhill 1883; Ziegler, Principles of Structural Stability, 1968, §2.8), computed here;
//  * strings in a vertical hole under their own weight: Greenhill's standing column (w L³/EI =
//    7.8373), Lubinski's string pinned at the bit with its top free sideways (the first zero of Ai′,
//    p = 1.018793: A&S 10.4.95 / Table 10.13) and with its top pinned (the hinged–hinged column of
//    Lubinski 1950, solved here by shooting).
#include <cmath>
#include <complex>
#include <functional>
#include <string>

#include "validation_support.hpp"

namespace drillflex::validation {
namespace torque_buckling_test {

constexpr double kPi = 3.14159265358979323846;

// The V1/V2 rod: 3 in solid, 200 in, E = 207 GPa.
constexpr double kRodLength = 5.08, kRodDiameter = 0.0762, kRodE = 207e9;
const double kRodEI = kRodE * kPi * std::pow(kRodDiameter, 4) / 64.0;

// The bisection root of f on [a, b] (f(a), f(b) of opposite signs).
double Bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  for (int i = 0; i < 100; ++i) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm > 0.0) == (fa > 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// The first root above `from` of f, scanning by `step`.
double FirstRoot(const std::function<double(double)>& f, double from, double step, double to) {
  double previous = f(from);
  for (double x = from + step; x <= to; x += step) {
    const double value = f(x);
    if ((value > 0.0) != (previous > 0.0)) return Bisect(f, x - step, x);
    previous = value;
  }
  return std::nan("");
}

// The clamped–clamped rod under compression P and torque T: u = A + Bx + C e^{i m1 x} + D e^{i m2 x},
// EI m² + T m − P = 0; u = u′ = 0 at both ends. The determinant times e^{−i(m1+m2)L/2} is imaginary;
// its imaginary part changes sign at the critical loads.
double ClampedDeterminant(double compression, double torque, double ei, double length) {
  using Complex = std::complex<double>;
  const Complex i(0.0, 1.0);
  const double root = std::sqrt(torque * torque + 4.0 * ei * compression);
  const double m1 = (-torque + root) / (2.0 * ei), m2 = (-torque - root) / (2.0 * ei);
  const Complex e1 = std::exp(i * m1 * length), e2 = std::exp(i * m2 * length);
  Complex a[4][4] = {{1.0, 0.0, 1.0, 1.0},
                     {0.0, 1.0, i * m1, i * m2},
                     {1.0, length, e1, e2},
                     {0.0, 1.0, i * m1 * e1, i * m2 * e2}};
  Complex det = 1.0;
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 4; ++r) if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    if (pivot != c) {
      for (int k = 0; k < 4; ++k) std::swap(a[c][k], a[pivot][k]);
      det = -det;
    }
    det *= a[c][c];
    for (int r = c + 1; r < 4; ++r) {
      const Complex f = a[r][c] / a[c][c];
      for (int k = c; k < 4; ++k) a[r][k] -= f * a[c][k];
    }
  }
  return (det * std::exp(-i * (m1 + m2) * length / 2.0)).imag();
}

// Prints the figure beside its reference and asserts it within 1 %.
void ExpectWithinOnePercent(const std::string& what, double computed, double reference) {
  std::printf("[ measure  ] %s: %.6g against %.6g (%+.3f %%)\n", what.c_str(), computed, reference,
              100.0 * RelativeError(computed, reference));
  EXPECT_LT(std::abs(RelativeError(computed, reference)), 0.01) << what;
}

TEST(V2GreenhillTorque, ClampedRodPureTorqueWithinOnePercent) {
  // tan x = x: x1 = 4.493409457909064 (A&S Table 4.19); T_cr = 2 x1 EI/L.
  const double x1 = Bisect([](double x) { return std::tan(x) - x; }, 4.4, 4.6);
  EXPECT_NEAR(x1, 4.493409457909064, 1e-12);
  const double reference = 2.0 * x1 * kRodEI / kRodLength;
  const auto results = RunCase("buckling", "v2-torque-buckling/clamped-torque.yaml");
  ASSERT_TRUE(results.contains("buckling"));
  const double critical = results["buckling"]["load_factor"].get<double>() * 50e3;
  ExpectWithinOnePercent("Greenhill clamped, T_cr (N·m)", critical, reference);
}

TEST(V2GreenhillTorque, ClampedRodTorqueAndCompressionWithinOnePercent) {
  const double compression = 65.5e3, torque = 98.15e3;  // the case's loads, scaled together by μ
  // The pure-torque and pure-compression ends of the curve from the same determinant.
  const double euler = 4.0 * kPi * kPi * kRodEI / (kRodLength * kRodLength);
  EXPECT_NEAR(FirstRoot([&](double p) { return ClampedDeterminant(p, 1e-6 * euler, kRodEI, kRodLength); },
                        0.5 * euler, 1e-3 * euler, 1.5 * euler) / euler, 1.0, 1e-4);
  const double multiplier = FirstRoot(
      [&](double mu) { return ClampedDeterminant(mu * compression, mu * torque, kRodEI, kRodLength); }, 0.05, 0.01, 10.0);
  ASSERT_TRUE(std::isfinite(multiplier));
  const auto results = RunCase("buckling", "v2-torque-buckling/clamped-combined.yaml");
  ASSERT_TRUE(results.contains("buckling"));
  const double computed = results["buckling"]["load_factor"].get<double>();
  ExpectWithinOnePercent(fmt::format("Greenhill combined, multiplier (onset at P = {:.3f} P_E, T = {:.3f} EI/L)",
                                     multiplier * compression / euler, multiplier * torque * kRodLength / kRodEI),
                         computed, multiplier);
}

// The collars of the vertical-hole cases: 6-3/4 in × 2-13/16 in steel (E = 210 GPa, 7850 kg/m³), no
// fluid, g = 9.81 m/s².
struct Collar {
  double w = 0.0, ei = 0.0;
  double m() const { return std::cbrt(ei / w); }  // Lubinski's unit length, m
};
Collar VerticalHoleCollar() {
  const double od = 6.75 * 0.0254, id = 2.8125 * 0.0254;
  Collar c;
  c.w = 7850.0 * 9.81 * kPi / 4.0 * (od * od - id * id);
  c.ei = 210e9 * kPi / 64.0 * (std::pow(od, 4) - std::pow(id, 4));
  return c;
}

TEST(V2VerticalHole, StandingColumnUnderItsWeightWithinOnePercent) {
  const Collar c = VerticalHoleCollar();
  const double length = 30.0;
  const double reference = 7.8373 * c.ei / (c.w * std::pow(length, 3));
  const auto results = RunCase("buckling", "v2-vertical-hole/standing-column.yaml");
  ASSERT_TRUE(results.contains("buckling"));
  EXPECT_EQ(results["buckling"]["scaled"], "all");
  const double computed = results["buckling"]["load_factor"].get<double>();
  ExpectWithinOnePercent("standing column, multiplier", computed, reference);
}

TEST(V2VerticalHole, LubinskiStringWithItsTopFreeWithinOnePercent) {
  const Collar c = VerticalHoleCollar();
  const double reference = 1.018792972 * c.w * c.m();  // |a′1|, the first zero of Ai′
  const auto results = RunCase("buckling", "v2-vertical-hole/lubinski-free-top.yaml");
  ASSERT_TRUE(results.contains("buckling"));
  EXPECT_EQ(results["buckling"]["scaled"], "wob");
  const double computed = results["buckling"]["critical_wob"].get<double>();
  ExpectWithinOnePercent("Lubinski, top free, critical WOB (N)", computed, reference);
}

// Lubinski's hinged–hinged column in units of m: the slope u = y′ obeys u″ − (x − p) u = c (the
// shear c), y(0) = 0, u′(0) = 0 (pinned: no moment), y(L) = 0, u′(L) = 0. Shooting with the two
// solutions (u(0), c) = (1, 0) and (0, 1), RK4: the determinant of their end conditions vanishes
// at the critical p.
double LubinskiPinnedDeterminant(double p, double length) {
  auto shoot = [&](double u0, double c, double& slope_end, double& integral) {
    const int steps = 20000;
    const double h = length / steps;
    double x = 0.0, u = u0, v = 0.0, y = 0.0;
    auto f = [&](double xx, double uu, double vv, double out[3]) {
      out[0] = vv;
      out[1] = (xx - p) * uu + c;
      out[2] = uu;
    };
    for (int s = 0; s < steps; ++s) {
      double k1[3], k2[3], k3[3], k4[3];
      f(x, u, v, k1);
      f(x + h / 2, u + h / 2 * k1[0], v + h / 2 * k1[1], k2);
      f(x + h / 2, u + h / 2 * k2[0], v + h / 2 * k2[1], k3);
      f(x + h, u + h * k3[0], v + h * k3[1], k4);
      y += h / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]);
      u += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
      v += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
      x += h;
    }
    slope_end = v;
    integral = y;
  };
  double v1 = 0, y1 = 0, v2 = 0, y2 = 0;
  shoot(1.0, 0.0, v1, y1);
  shoot(0.0, 1.0, v2, y2);
  return v1 * y2 - v2 * y1;
}

TEST(V2VerticalHole, LubinskiStringPinnedAtBothEndsWithinOnePercent) {
  const Collar c = VerticalHoleCollar();
  const double length = 240.0 / c.m();
  const double p = FirstRoot([&](double x) { return LubinskiPinnedDeterminant(x, length); }, 1.2, 0.05, 3.0);
  ASSERT_TRUE(std::isfinite(p));
  const double reference = p * c.w * c.m();
  const auto results = RunCase("buckling", "v2-vertical-hole/lubinski-pinned-top.yaml");
  ASSERT_TRUE(results.contains("buckling"));
  const double computed = results["buckling"]["critical_wob"].get<double>();
  ExpectWithinOnePercent(fmt::format("Lubinski, both ends pinned {:.2f} m units apart (p = {:.5f}), critical WOB (N)",
                                     length, p),
                         computed, reference);
}

}  // namespace torque_buckling_test
}  // namespace drillflex::validation
