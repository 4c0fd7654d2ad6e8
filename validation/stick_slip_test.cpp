// V8 of validation.md, the stick–slip pendulum: the top turned at a constant Ω through a torsional
// spring k (a 10 m rod), a flywheel of inertia J at the bit, a friction torque with static T_s and
// kinetic T_d levels against the bit's spin (v8-transient/stick-slip.yaml), through `drillflex
// transient`. The exact limit cycle (a one-degree-of-freedom pendulum; e.g. Leine et al., J. Vib.
// Acoust. 124, 2002, and validation.md V8): while stuck, the spring winds up at kΩ from 2T_d − T_s
// to T_s, so the stick lasts 2(T_s − T_d)/(kΩ); the slip is a free oscillation at ω_n = sqrt(k/J)
// about the kinetic level that starts and ends at zero bit speed, (2π − 2δ)/ω_n with
// δ = atan(u₀ω_n/Ω), u₀ = (T_s − T_d)/k, and peaks at Ω + sqrt(Ω² + (u₀ω_n)²). Period and peak bit
// speed within 2 %, over the cycles after the first stick (which starts from rest; every slip starts
// at T_s from zero bit speed, so the first slip is already the limit cycle's). 5–14 s in Release:
// 3 147 adaptive steps of a 143-coordinate model, dense LU.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "validation_support.hpp"

namespace drillflex::validation {
namespace stick_slip_test {

constexpr double kPi = 3.14159265358979323846;
// The case's figures (SI).
constexpr double kRodDiameter = 0.04, kRodLength = 10.0, kE = 2.1e11, kNu = 0.3;
constexpr double kWheelDiameter = 1.0, kWheelLength = 0.5, kWheelDensity = 20000.0;
constexpr double kStatic = 3000.0, kKinetic = 2000.0, kOmega = 1.0, kStickSpeed = 1e-3;
constexpr double kRpm = 2.0 * kPi / 60.0;

struct Pendulum {
  double k, inertia, omega_n, u0, delta;
  double stick() const { return 2.0 * u0 / kOmega; }  // 2(T_s − T_d)/(kΩ)
  double slip() const { return (2.0 * kPi - 2.0 * delta) / omega_n; }
  double peak() const { return kOmega + std::sqrt(kOmega * kOmega + u0 * u0 * omega_n * omega_n); }
};

Pendulum Reference() {
  Pendulum p;
  const double shear = kE / (2.0 * (1.0 + kNu));
  p.k = shear * kPi * std::pow(kRodDiameter, 4) / 32.0 / kRodLength;                       // G J_p / L
  p.inertia = kWheelDensity * kPi * std::pow(kWheelDiameter, 4) / 32.0 * kWheelLength;     // ρ J_p L
  p.omega_n = std::sqrt(p.k / p.inertia);
  p.u0 = (kStatic - kKinetic) / p.k;
  p.delta = std::atan(p.u0 * p.omega_n / kOmega);
  return p;
}

// The times the bit speed crosses `level` upward (slip starts) and downward (stick starts),
// linearly interpolated between samples.
struct Crossings {
  std::vector<double> up, down;
};

Crossings CrossingsOf(const std::vector<double>& time, const std::vector<double>& speed, double level) {
  Crossings c;
  for (std::size_t i = 1; i < time.size(); ++i) {
    const double a = speed[i - 1] - level, b = speed[i] - level;
    const double at = time[i - 1] + (time[i] - time[i - 1]) * a / (a - b);
    if (a < 0.0 && b >= 0.0) c.up.push_back(at);
    if (a >= 0.0 && b < 0.0) c.down.push_back(at);
  }
  return c;
}

TEST(V8StickSlip, LimitCyclePeriodAndPeakBitSpeedWithin2Percent) {
  const auto results = RunCase("transient", "v8-transient/stick-slip.yaml");
  ASSERT_TRUE(results.contains("transient"));
  const CsvColumns csv =
      ReadCsv(std::string(DRILLFLEX_BINARY_DIR "/validation-results/v8-transient/stick-slip/transient.csv"));
  const auto& time = csv["time"];
  std::vector<double> bit, surface;
  for (const double rpm : csv["bit_rpm"]) bit.push_back(rpm * kRpm);
  for (const double rpm : csv["surface_rpm"]) surface.push_back(rpm * kRpm);
  const Pendulum ref = Reference();
  // The top turns at Ω once ramped up (0.2 s), whatever the bit does (within 2 %, measured 1.24 %: the top node rings
  // on the drive's stiff spring after the ramp and at each slip).
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] > 0.5) {
      ASSERT_NEAR(surface[i], kOmega, 2e-2 * kOmega) << "t = " << time[i];
    }
  }
  // Slip starts where the bit speed rises through a level well above the stuck creep (< Ω_ε) and
  // well below Ω; the bit crosses it (T_s − T_d)/J = 1.02 rad/s² into the slip and as far before
  // the stick, both ends the same: the stick measured between the crossings is 2 level J/(T_s − T_d)
  // too long, the slip as much too short.
  const double level = 0.01 * kOmega;
  const double offset = 2.0 * level * ref.inertia / (kStatic - kKinetic);
  const Crossings c = CrossingsOf(time, bit, level);
  ASSERT_GE(c.up.size(), 3u) << "fewer than three slips in " << time.back() << " s";
  // Cycles k = 0..: slip from up[k] to the next down, stick from that down to up[k + 1].
  std::vector<double> periods, sticks, slips, peaks;
  for (std::size_t k = 0; k + 1 < c.up.size(); ++k) {
    const auto down = std::upper_bound(c.down.begin(), c.down.end(), c.up[k]);
    ASSERT_TRUE(down != c.down.end() && *down < c.up[k + 1]) << "no stick between slips " << k << " and " << k + 1;
    periods.push_back(c.up[k + 1] - c.up[k]);
    slips.push_back(*down - c.up[k] + offset);
    sticks.push_back(c.up[k + 1] - *down - offset);
    double peak = 0.0, creep = 0.0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      if (time[i] >= c.up[k] && time[i] <= *down) peak = std::max(peak, bit[i]);
      // The middle of the stick: the bit creeps below the stick speed.
      if (time[i] > *down + 0.1 && time[i] < c.up[k + 1] - 0.1) creep = std::max(creep, std::abs(bit[i]));
    }
    peaks.push_back(peak);
    EXPECT_LT(creep, kStickSpeed) << "cycle " << k << ": the bit does not stick";
  }
  std::printf("V8 stick-slip: k %.2f N*m/rad, J %.2f kg*m2, omega_n %.5f rad/s\n", ref.k, ref.inertia, ref.omega_n);
  std::printf("V8 stick-slip: %-6s %10s %10s %10s %10s\n", "cycle", "stick s", "slip s", "period s", "peak rad/s");
  std::printf("V8 stick-slip: %-6s %10.4f %10.4f %10.4f %10.5f\n", "exact", ref.stick(), ref.slip(),
              ref.stick() + ref.slip(), ref.peak());
  for (std::size_t k = 0; k < periods.size(); ++k) {
    std::printf("V8 stick-slip: %-6zu %10.4f %10.4f %10.4f %10.5f\n", k + 1, sticks[k], slips[k], periods[k], peaks[k]);
    std::printf("V8 stick-slip: %-6s %+9.3f%% %+9.3f%% %+9.3f%% %+9.3f%%\n", "error", 100 * RelativeError(sticks[k], ref.stick()),
                100 * RelativeError(slips[k], ref.slip()), 100 * RelativeError(periods[k], ref.stick() + ref.slip()),
                100 * RelativeError(peaks[k], ref.peak()));
    EXPECT_LT(std::abs(RelativeError(periods[k], ref.stick() + ref.slip())), 0.02) << "cycle " << k + 1;
    EXPECT_LT(std::abs(RelativeError(peaks[k], ref.peak())), 0.02) << "cycle " << k + 1;
    // The split of the period: the slip within 2 %, the stick within 5 % (it is the most sensitive
    // part: the rod's torsional stiffness is 1.7 % low at 0.15 rad of elastic twist a body, which
    // lowers the spring's windup rate kΩ, measured 1996 against 2030 N·m/s, and the torque the
    // slip ends at; docs/validation.md).
    EXPECT_LT(std::abs(RelativeError(sticks[k], ref.stick())), 0.05) << "cycle " << k + 1;
    EXPECT_LT(std::abs(RelativeError(slips[k], ref.slip())), 0.02) << "cycle " << k + 1;
  }
}

}  // namespace stick_slip_test
}  // namespace drillflex::validation
