// The drives (model/drive_elements.hpp): the ramp, the top drive's twist after thousands of turns,
// and every drive's analytic stiffness and damping against central differences of its own residual
// at a spun, bent and moving state.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "model/drive_elements.hpp"
#include "element_problem.hpp"
#include "model_test_support.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {
namespace drive_elements_test {

using testing::ElementProblem;
using testing::Errors;
using testing::JacobianErrors;
using testing::SpinningVelocities;
using testing::SpunPositions;

constexpr double kRpm = kPi / 30.0;  // rad/s per rpm

BuiltModel DrivenRod(cms::ReductionCache& cache, std::optional<TopDrive> drive, std::optional<BlockDrive> block) {
  ModelInput input = testing::RodInput(2, 4, 5);
  input.top_drive = drive;
  input.block = block;
  return BuildSystemModel(input, cache);
}

TEST(LinearRamp, ValueAndIntegralThroughTheRamp) {
  const LinearRamp ramp{10.0, 2.0};
  EXPECT_DOUBLE_EQ(ramp.Value(0.0), 0.0);
  EXPECT_DOUBLE_EQ(ramp.Value(1.0), 5.0);
  EXPECT_DOUBLE_EQ(ramp.Value(3.0), 10.0);
  EXPECT_DOUBLE_EQ(ramp.Integral(1.0), 2.5);         // ½ · 10 · 1² / 2
  EXPECT_DOUBLE_EQ(ramp.Integral(2.0), 10.0);        // continuous at the end of the ramp
  EXPECT_DOUBLE_EQ(ramp.Integral(5.0), 10.0 * 4.0);  // 10 (5 − 1)
  const LinearRamp step{3.0, 0.0};
  EXPECT_DOUBLE_EQ(step.Value(0.0), 3.0);
  EXPECT_DOUBLE_EQ(step.Integral(2.0), 6.0);
}

// After 2000 turns at 120 rpm the drive frame is still exact: a top exactly at the drive's angle
// carries no twist, and a top 1e-4 rad behind it carries that twist and the torque k·1e-4.
TEST(TopDriveElement, FollowsTheDriveAngleOverThousandsOfTurns) {
  cms::ReductionCache cache;
  const TopDrive drive{TopDriveMode::Speed, {120.0 * kRpm, 2.0}};
  const BuiltModel built = DrivenRod(cache, drive, std::nullopt);
  ASSERT_TRUE(built.top_drive.has_value());
  const auto& element = built.Get(*built.top_drive);
  const double t = 1000.0;
  const double angle = element.DriveAngle(t);
  EXPECT_NEAR(angle, 120.0 * kRpm * (t - 1.0), 1e-9 * angle);
  ASSERT_GT(angle / (2.0 * kPi), 1990.0);
  const ElementProblem problem(built.system, *built.top_drive);
  for (const double lag : {0.0, 1e-4}) {
    VecX dv = VecX::Zero(built.system.num_velocities());
    // Clockwise looking down-hole is about −x; the top behind the drive by `lag`.
    for (const Body& body : built.system.bodies()) dv[body.v_offset + 3] = -angle + lag;
    const VecX q = built.system.Increment(built.system.ReferencePositions(), dv);
    VecX v = VecX::Zero(built.system.num_velocities());
    for (const Body& body : built.system.bodies()) v[body.v_offset + 3] = -120.0 * kRpm;  // turning with it
    const ElementState state = problem.State(t, q, v);
    EXPECT_NEAR(element.Lag(state), lag, 1e-9);
    if (lag > 0.0) {
      const double stiffness = element.Torque(state) / lag;
      // The support stiffness it replaces: 10 · c · GJ/ℓ (c = 100, ℓ = 5.08/2/4 m, GJ of the V1 rod).
      const double polar = kPi * std::pow(0.0762, 4) / 32.0, shear = 2.1e11 / 2.6;
      const double expected = kSupportStiffnessFactor * 100.0 * shear * polar / (5.08 / 8.0);
      EXPECT_NEAR(stiffness, expected, 1e-6 * expected);
    } else {
      EXPECT_NEAR(element.Torque(state), 0.0, 1.0);  // N·m: k (~4e9 N·m/rad) times 2.5e-10 rad
    }
  }
}

TEST(TopDriveElement, SpeedDriveJacobiansMatchCentralDifferences) {
  cms::ReductionCache cache;
  const TopDrive drive{TopDriveMode::Speed, {120.0 * kRpm, 2.0}};
  const BuiltModel built = DrivenRod(cache, drive, std::nullopt);
  const auto& element = built.Get(*built.top_drive);
  const ElementProblem problem(built.system, *built.top_drive);
  std::mt19937 rng(17);
  // During the ramp and 72 turns later; the top bent and twisted off the drive by ~0.05 rad so that
  // every term (the frame's curvature, the torque's geometric part) is visible.
  for (const double t : {0.7, 37.3}) {
    const double angle = element.DriveAngle(t);
    const VecX q = SpunPositions(built.system, -angle, 0.05, rng);
    const VecX v = SpinningVelocities(built.system, -drive.setting.Value(t), 0.5, rng);
    const Errors errors = JacobianErrors(problem, t, q, v);
    std::printf("[ measure  ] speed drive at t = %.1f s (%.1f turns): stiffness %.2e, damping %.2e\n", t,
                angle / (2.0 * kPi), errors.stiffness, errors.damping);
    EXPECT_LT(errors.stiffness, 1e-6);
    EXPECT_LT(errors.damping, 1e-6);
  }
}

TEST(TopDriveElement, TorqueDriveAppliesItsTorqueWithAnExactTangent) {
  cms::ReductionCache cache;
  const TopDrive drive{TopDriveMode::Torque, {5000.0, 1.0}};
  const BuiltModel built = DrivenRod(cache, drive, std::nullopt);
  const auto& element = built.Get(*built.top_drive);
  const ElementProblem problem(built.system, *built.top_drive);
  std::mt19937 rng(5);
  const VecX q = SpunPositions(built.system, 300.0, 0.05, rng);
  const VecX v = SpinningVelocities(built.system, -10.0, 0.5, rng);
  EXPECT_DOUBLE_EQ(element.Torque(problem.State(0.5, q, v)), 2500.0);  // halfway up its ramp
  // At rest in the reference placement the generalized moment about x is the torque, clockwise
  // looking down-hole (about −x): the residual (−f_ext) is +T in the top body's ω_x row.
  const VecX rest = built.system.ReferencePositions();
  const VecX zero = VecX::Zero(built.system.num_velocities());
  const VecX residual = problem.Residual(2.0, rest, zero, zero);
  const Body& top = built.system.bodies().back();
  EXPECT_NEAR(residual[top.v_offset + 3], 5000.0, 1e-9);
  const Errors errors = JacobianErrors(problem, 0.5, q, v);
  std::printf("[ measure  ] torque drive: stiffness %.2e, damping %.2e\n", errors.stiffness, errors.damping);
  EXPECT_LT(errors.stiffness, 1e-6);
  EXPECT_EQ(errors.damping, 0.0);
}

TEST(BlockElement, VelocityAndHookLoadJacobiansMatchCentralDifferences) {
  cms::ReductionCache cache;
  // The hook load in tension and, ramped, in compression (a negative hook load).
  // And a velocity through a line of its own stiffness, started stretched (a preload).
  BlockDrive line{BlockMode::Velocity, {0.5, 1.0}};
  line.line_stiffness = 3e7;
  line.start_top_displacement = 1e-8;  // m: the hold carried ~15 kN
  for (const BlockDrive block : {BlockDrive{BlockMode::Velocity, {0.5, 1.0}}, BlockDrive{BlockMode::HookLoad, {2e5, 0.0}},
                                 BlockDrive{BlockMode::HookLoad, {-2e5, 0.3}}, line}) {
    const BuiltModel built = DrivenRod(cache, std::nullopt, block);
    ASSERT_TRUE(built.block.has_value());
    const ElementProblem problem(built.system, *built.block);
    std::mt19937 rng(23);
    // Within mm of the block (the ramp has pulled 2.5 mm at t = 0.1 s): the spring force k e
    // (k ~ 1e10 N/m) stays small enough for central differences in v to keep 1e-6 of the damping.
    const VecX q = SpunPositions(built.system, 40.0, 0.005, rng);
    const VecX v = SpinningVelocities(built.system, 12.0, 0.5, rng);
    const Errors errors = JacobianErrors(problem, 0.1, q, v);
    std::printf("[ measure  ] block (%s): stiffness %.2e, damping %.2e\n",
                block.mode == BlockMode::Velocity ? "velocity" : "hook load", errors.stiffness, errors.damping);
    EXPECT_LT(errors.stiffness, 1e-6);
    if (block.mode == BlockMode::Velocity) {
      // The force is linear in v, so the differences err only by round-off, ~ε|R|/h_v with the
      // spring's k e in R: measured 4.7e-7 to 1.5e-6 over random states (seeds 23–26).
      EXPECT_LT(errors.damping, 3e-6);
    } else {
      EXPECT_EQ(errors.damping, 0.0);
    }
  }
}

// A top exactly where the block has pulled it carries no force; 1 mm below it, k · 1 mm of tension.
TEST(BlockElement, HookLoadOfATopBehindTheBlock) {
  cms::ReductionCache cache;
  const BuiltModel built = DrivenRod(cache, std::nullopt, BlockDrive{BlockMode::Velocity, {0.5, 1.0}});
  const auto& element = built.Get(*built.block);
  const ElementProblem problem(built.system, *built.block);
  const double t = 3.0, travel = 0.5 * (t - 0.5);
  for (const double behind : {0.0, 1e-3}) {
    VecX dv = VecX::Zero(built.system.num_velocities());
    for (const Body& body : built.system.bodies()) dv[body.v_offset] = travel - behind;  // up-hole: +x
    const VecX q = built.system.Increment(built.system.ReferencePositions(), dv);
    VecX v = VecX::Zero(built.system.num_velocities());
    for (const Body& body : built.system.bodies()) v[body.v_offset] = 0.5;
    const double axial = 2.1e11 * kPi * 0.0762 * 0.0762 / 4.0 / (5.08 / 8.0);
    const double expected = kSupportStiffnessFactor * 100.0 * axial * behind;
    EXPECT_NEAR(element.HookLoad(problem.State(t, q, v)), expected, 1e-6 * std::max(expected, 1.0));
  }
}

// A line softer than the hold starts where the hold left the top: displaced u0 up-hole at t = 0
// it carries the hold's k_hold u0 (so nothing jumps when the block takes over), and a further
// travel δ changes that by the line's own k_line δ, not the hold's.
TEST(BlockElement, ASofterLineStartsWithTheHoldsForce) {
  cms::ReductionCache cache;
  const double start = 1e-8, line_stiffness = 3e7;  // m (the hold carried ~15 kN), N/m
  BlockDrive block{BlockMode::Velocity, {0.5, 1.0}};
  block.line_stiffness = line_stiffness;
  block.start_top_displacement = start;
  const BuiltModel built = DrivenRod(cache, std::nullopt, block);
  const auto& element = built.Get(*built.block);
  const ElementProblem problem(built.system, *built.block);
  const double axial = 2.1e11 * kPi * 0.0762 * 0.0762 / 4.0 / (5.08 / 8.0);
  const double hold = kSupportStiffnessFactor * 100.0 * axial;  // N/m, the hold the line replaces
  const auto hook_load = [&](double travel) {  // the rod moved up-hole by `travel`, at rest, t = 0
    VecX dv = VecX::Zero(built.system.num_velocities());
    for (const Body& body : built.system.bodies()) dv[body.v_offset] = travel;
    const VecX q = built.system.Increment(built.system.ReferencePositions(), dv);
    return element.HookLoad(problem.State(0.0, q, VecX::Zero(built.system.num_velocities())));
  };
  EXPECT_NEAR(hook_load(start), -hold * start, 1e-9 * hold * start);
  const double further = 1e-4;
  EXPECT_NEAR(hook_load(start + further) - hook_load(start), -line_stiffness * further, 1e-6 * line_stiffness * further);
}

}  // namespace drive_elements_test
}  // namespace drillflex::model
