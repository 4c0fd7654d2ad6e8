// A mud motor's bent housing (model::BentHousingRotation, analyses::RunStaticInWell): the bodies
// meet at the bend, the coupling there holds the bend angle toward the toolface, and the bit's
// side force follows the toolface the way a directional driller expects: toward the high side it
// builds, toward the low side it drops, to the right it walks right, and right and left mirror
// each other (the weight acts in the high-low plane only).
#include <cmath>
#include <cstdio>
#include <optional>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "analyses/static_analysis.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {
namespace bent_motor_test {

constexpr double kIn = 0.0254, kFt = 0.3048;
constexpr double kBend = 1.5 * kDegree;
constexpr double kBendToBit = 6.0 * kFt;

model::Component Part(model::ComponentType type, const char* name, double od_in, double id_in, double length_ft) {
  model::Component part;
  part.type = type;
  part.name = name;
  part.outer_diameter = od_in * kIn;
  part.inner_diameter = id_in * kIn;
  part.length = length_ft * kFt;
  return part;
}

// A bit, a 25 ft motor bent 6 ft above the bit, 90 ft of collars, in a straight 8-1/2 in hole at 30°.
model::ModelInput BentMotorInput(std::optional<double> toolface) {
  model::ModelInput input;
  model::Component motor = Part(model::ComponentType::Motor, "motor", 6.75, 2.0, 25.0);
  if (toolface) {
    motor.bend_angle = kBend;
    motor.bend_to_bit = kBendToBit;
    motor.toolface = *toolface;
  }
  input.string.components = {Part(model::ComponentType::Bit, "bit", 8.5, 2.0, 1.0), motor,
                             Part(model::ComponentType::Collar, "collars", 6.5, 2.8125, 90.0)};
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.gravity = 9.81;
  input.well = model::MakeWellbore(
      well::Trajectory(std::vector<well::SurveyStation>{{0.0, 30.0 * kDegree, 0.0}, {2000.0, 30.0 * kDegree, 0.0}}),
      std::vector<well::HoleSection>{well::HoleSection{{}, 8.5 * kIn, {}}});
  input.bit_md = 1500.0;
  input.operation.weight_on_bit = 20000.0 * 4.4482216152605;
  return input;
}

BitReport SolveBit(std::optional<double> toolface) {
  const model::ModelInput input = BentMotorInput(toolface);
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const StaticResult result = RunStaticInWell(input, built, StaticSettings{});
  EXPECT_TRUE(result.converged);
  EXPECT_TRUE(result.bit.has_value());
  const BitReport bit = result.bit.value_or(BitReport{});
  std::printf("[ measure  ] toolface %s: build %.1f N, walk %.1f N, tilt %.4f deg (%d iterations)\n",
              toolface ? fmt::format("{:g} deg", *toolface / kDegree).c_str() : "none", bit.build_force, bit.walk_force,
              bit.tilt / kDegree, result.iterations);
  return bit;
}

TEST(BentMotor, TheCouplingAtTheBendHoldsTheBendTowardTheToolface) {
  for (const double toolface_deg : {0.0, 90.0, 137.0, 180.0}) {
    const model::ModelInput input = BentMotorInput(toolface_deg * kDegree);
    const Mat3 bend = model::BentHousingRotation(input.string, kBendToBit);
    // The upper body's axis seen from the lower body: e_x turned by the bend toward d.
    const Vec3 toward(0.0, std::sin(toolface_deg * kDegree), std::cos(toolface_deg * kDegree));
    EXPECT_NEAR((bend * Vec3::UnitX() - (std::cos(kBend) * Vec3::UnitX() + std::sin(kBend) * toward)).norm(), 0.0,
                1e-15);
    EXPECT_NEAR(Eigen::AngleAxisd(bend).angle(), kBend, 1e-15);
    EXPECT_TRUE(model::BentHousingRotation(input.string, kBendToBit + 0.01).isIdentity(0.0));
  }
  // The bodies meet at the bend.
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(BentMotorInput(0.0), cache);
  bool joint_at_bend = false;
  for (const model::Body& body : built.system.bodies()) joint_at_bend |= std::abs(body.s_start - kBendToBit) < 1e-9;
  EXPECT_TRUE(joint_at_bend);
}

TEST(BentMotor, TheBitFollowsTheToolface) {
  const BitReport straight = SolveBit(std::nullopt);
  const BitReport high = SolveBit(0.0);
  const BitReport low = SolveBit(180.0 * kDegree);
  const BitReport right = SolveBit(90.0 * kDegree);
  const BitReport left = SolveBit(270.0 * kDegree);
  const double scale = std::abs(straight.side_force);
  ASSERT_GT(scale, 100.0);
  // Toolface high side: more build than the straight motor; low side: more drop.
  EXPECT_GT(high.build_force - straight.build_force, 0.1 * scale);
  EXPECT_LT(low.build_force - straight.build_force, -0.1 * scale);
  EXPECT_GT(high.tilt, straight.tilt);
  EXPECT_LT(low.tilt, straight.tilt);
  // Right walks right, left walks left, mirror images to 1 % of the side force (the round-off of the
  // stiff couplings and supports is tens of N; measured 0 N on the walk, 63 N on the build).
  EXPECT_GT(right.walk_force, 0.1 * scale);
  EXPECT_LT(left.walk_force, -0.1 * scale);
  EXPECT_NEAR(right.walk_force, -left.walk_force, 0.01 * right.side_force);
  EXPECT_NEAR(right.build_force, left.build_force, 0.01 * right.side_force);
}

}  // namespace bent_motor_test
}  // namespace drillflex::analyses
