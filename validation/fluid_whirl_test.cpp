// V8 fluid in the transient (validation.md), the whirl cases in mud: V8's backward whirl and the
// eccentric collar (the paper's test 3.5) in a 12 ppg, 20 cP mud (v8-fluid/backward-whirl-mud.yaml,
// eccentric-collar-mud.yaml; the annulus's C_m and C_v at the rolling whirl's 3.137 Hz).
//  * Rolling without slip is kinematics: the contact point is at rest, so the whirl rate is
//    −Ω R_c/(R_h − R_c) = −188.24 rpm whatever the mass that whirls (Jansen 1991, "Whirl and chaotic
//    motion of stabilized drill collars"; Vandiver, Nicholson & Shyu 1990). The fluid changes the
//    forces: its added mass whirls with the collar, and its damping takes power that the friction at
//    the contact has to supply (the whirl rolls from ~5 s instead of ~3 s in air).
//    Asserted: the rate over the last 1.5 s within 2 % of −188.24 rpm (V8's tolerance), on the wall,
//    turning at the drive's 100 rpm.
//  * The contact force at the mid-span node of a span that lies on the wall is the centripetal force
//    of the mass whirling with the node, (m_s + m_i + C_m ρ π a²) L_k e ω_w² (L_k = 2.5 ft, the node's
//    share; e the offset), within 10 %: an estimate, not an exact reference (the bow's elastic push
//    and the neighbouring nodes' share are left out of it: in air the steel alone gives 803 lbf
//    against the 824 measured, +2.6 %; in mud +7.3 % measured, the difference not explained: not buoyancy,
//    the gravity-free eccentric collar reads the same).
//    Without the fluid's mass (56 % over the steel's) the force would be 35 % below the estimate.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fe/annulus_fluid.hpp"
#include "validation_support.hpp"
#include "whirl_support.hpp"

namespace drillflex::validation {
namespace fluid_whirl_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInch = 0.0254, kLbf = 4.4482216152605, kPpg = 119.826427;
constexpr double kSpeedRpm = 100.0;
constexpr double kCollarRadius = 4.0, kHoleRadius = 6.125, kBore = 2.8125;  // in
constexpr double kSteel = 7850.0, kMud = 12.0 * kPpg, kViscosity = 0.020;    // kg/m³, Pa·s
constexpr double kFluidFrequency = 3.137;                                     // Hz, the cases' fluid_frequency
constexpr double kNodeLength = 2.5 * 12.0 * kInch;                             // m: 15 ft bodies of 6 elements

// The lateral mass per length whirling with the collar, kg/m: steel, bore fluid, annulus added mass.
double WhirlingMassPerLength() {
  const double a = kCollarRadius * kInch, b = kHoleRadius * kInch, bore = 0.5 * kBore * kInch;
  const fe::AnnulusFluidCoefficients c =
      fe::ComputeAnnulusFluidCoefficients(a, b, 2.0 * kPi * kFluidFrequency, kViscosity / kMud);
  return kSteel * kPi * (a * a - bore * bore) + kMud * kPi * bore * bore + c.added_mass * kMud * kPi * a * a;
}

void CheckRollingWhirlInMud(const std::string& name) {
  const auto results = RunCase("transient", "v8-fluid/" + name + ".yaml");
  ASSERT_TRUE(results.contains("transient"));
  const CsvColumns csv = ReadCsv(ResultsDirectory("v8-fluid/" + name + ".yaml") + "/transient.csv");
  const auto& time = csv["time"];
  const double from = time.back() - 1.5;
  const std::vector<double> angle = Unwrapped(csv["probe1_whirl_angle"]);
  const double whirl_rpm = Slope(time, angle, from) / 6.0;  // deg/s → rpm
  const double rolling = -kSpeedRpm * kCollarRadius / (kHoleRadius - kCollarRadius);
  const auto& force = csv["probe1_contact_force"];
  const auto& bit_rpm = csv["bit_rpm"];
  const auto& y = csv["probe1_lateral_y"];
  const auto& z = csv["probe1_lateral_z"];
  double least_force = 1e300, force_sum = 0.0, offset_sum = 0.0, slowest = 1e300, fastest = -1e300;
  int window = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < from) continue;
    least_force = std::min(least_force, force[i]);
    force_sum += force[i];
    offset_sum += std::hypot(y[i], z[i]);
    slowest = std::min(slowest, bit_rpm[i]);
    fastest = std::max(fastest, bit_rpm[i]);
    ++window;
  }
  const double mean_force = force_sum / window * kLbf;     // N
  const double offset = offset_sum / window * kInch;       // m
  const double whirl = std::abs(whirl_rpm) * 2.0 * kPi / 60.0;  // rad/s
  const double centripetal = WhirlingMassPerLength() * kNodeLength * offset * whirl * whirl;
  std::printf("V8 fluid, %s: whirl %.2f rpm against rolling %.2f rpm (%+.2f %%); mid-span contact force %.0f lbf "
              "(least %.0f) against the centripetal force of %.1f kg/m whirling, %.0f lbf (%+.2f %%); bit %.1f to "
              "%.1f rpm\n",
              name.c_str(), whirl_rpm, rolling, 100.0 * RelativeError(whirl_rpm, rolling), mean_force / kLbf,
              least_force, WhirlingMassPerLength(), centripetal / kLbf, 100.0 * RelativeError(mean_force, centripetal),
              slowest, fastest);
  EXPECT_LT(std::abs(RelativeError(whirl_rpm, rolling)), 0.02);
  EXPECT_GT(least_force, 0.0);
  EXPECT_LT(std::abs(RelativeError(mean_force, centripetal)), 0.10);
  EXPECT_NEAR(slowest, kSpeedRpm, 0.05 * kSpeedRpm);
  EXPECT_NEAR(fastest, kSpeedRpm, 0.05 * kSpeedRpm);
}

TEST(V8FluidWhirl, BackwardWhirlInMudRollsAtTheKinematicRate) { CheckRollingWhirlInMud("backward-whirl-mud"); }

TEST(V8FluidWhirl, EccentricCollarInMudRollsAtTheKinematicRate) { CheckRollingWhirlInMud("eccentric-collar-mud"); }

}  // namespace fluid_whirl_test
}  // namespace drillflex::validation
