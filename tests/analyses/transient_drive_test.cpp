// The drives in a transient run (model/drives.hpp): the V1 rod (D = 3 in, L = 200 in, steel of
// ρ = 7800 kg/m³) held laterally at both ends and otherwise free, spun up, pulled and pushed by the
// drives at its top. Rigid-body references: the drive's torque J α and the block's force m a, with
// J = ρ (π D⁴/32) L = 0.1312 kg·m² and m = ρ (π D²/4) L = 180.9 kg. The corners of a ramp (a step
// in the acceleration) set the rod's first torsional or axial mode held at the top (158 Hz, 255 Hz)
// swinging by about J α or m a; with 5 % structural damping it has decayed to 1e-4 of that by the
// samples compared (0.3 s or more after a corner). The tolerance is 1e-6: the drive springs (4e9
// N·m/rad, 1.5e13 N/m) read the positions' Newton error (~1e-3 × tolerance × 1e-3 rad or m) as
// force, about 0.4 N·m and 1.5 kN at the default 1e-4.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analyses/transient_analysis.hpp"
#include "analyses/transient_start_places.hpp"
#include "analyses_test_support.hpp"
#include "cms/reduction_cache.hpp"

namespace drillflex::analyses {
namespace transient_drive_test {

using testing::kRodDiameter;
using testing::kRodLength;
using testing::SupportAt;

constexpr double kDensity = 7800.0;
constexpr double kRpm = kPi / 30.0;

double PolarInertia() { return kDensity * kPi * std::pow(kRodDiameter, 4) / 32.0 * kRodLength; }
double Mass() { return kDensity * testing::RodArea() * kRodLength; }

struct DrivenRun {
  TransientResult result;
  double top_travel = 0.0;  // m, the top node's displacement along the rod at the end (up-hole +)
  const TransientSample& At(double t) const {
    for (const TransientSample& s : result.samples) {
      if (std::abs(s.time - t) < 1e-9) return s;
    }
    throw std::runtime_error("no sample at that time");
  }
};

// `held_at_bit`: the bit end held axially too (a bar the block loads against a fixed end).
DrivenRun RunDriven(std::optional<model::TopDrive> drive, std::optional<model::BlockDrive> block, double duration,
                    bool held_at_bit = false) {
  model::ModelInput input = testing::RodInput(2, 2.1e11, kDensity, 4, 4);
  input.settings.structural_damping = 0.05;
  input.supports = {held_at_bit ? SupportAt(0.0, {model::kX, model::kY, model::kZ}) : SupportAt(0.0, {model::kY, model::kZ}),
                    SupportAt(kRodLength, {model::kY, model::kZ})};
  TransientSettings settings;
  settings.duration = duration;
  settings.output_interval = 0.05;
  settings.start = TransientStart::Reference;
  settings.tolerance = 1e-6;
  settings.top_drive = drive;
  settings.block = block;
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(TransientModelInput(input, settings, 0.0), cache);
  DrivenRun run{RunTransient(built, built.system.ReferencePositions(), settings)};
  const model::Body& top = built.system.bodies().back();
  const int node = top.node_count() - 1;
  const Vec3 moved = built.system.Poses(run.result.final_q).back().NodePosition(top, node) -
                     built.system.Poses(built.system.ReferencePositions()).back().NodePosition(top, node);
  run.top_travel = moved.x();  // the rod lies along x, up-hole +x
  return run;
}

// 60 rpm in 0.5 s: the torque J α during the ramp, none after it, bit and top at 60 rpm, clockwise.
TEST(TransientDrive, TopDriveSpinsTheRodUpToItsSpeed) {
  const double speed = 60.0 * kRpm, ramp = 0.5;
  const DrivenRun run = RunDriven(model::TopDrive{model::TopDriveMode::Speed, {speed, ramp}}, std::nullopt, 1.0);
  const double torque = PolarInertia() * speed / ramp;
  EXPECT_NEAR(run.At(0.4).surface_torque, torque, 0.03 * torque);
  EXPECT_NEAR(run.At(0.4).bit_speed, speed * 0.4 / ramp, 0.01 * speed);
  EXPECT_NEAR(run.At(1.0).surface_torque, 0.0, 0.03 * torque);
  EXPECT_NEAR(run.At(1.0).surface_speed, speed, 1e-3 * speed);
  EXPECT_NEAR(run.At(1.0).bit_speed, speed, 1e-3 * speed);
}

// A set torque of 1 N·m from t = 0 on the free rod: ω = T t / J.
TEST(TransientDrive, TorqueDriveAcceleratesTheRodAtTOverJ) {
  const DrivenRun run = RunDriven(model::TopDrive{model::TopDriveMode::Torque, {1.0, 0.0}}, std::nullopt, 0.5);
  const double expected = 1.0 * 0.5 / PolarInertia();
  EXPECT_NEAR(run.At(0.5).bit_speed, expected, 0.01 * expected);
  EXPECT_DOUBLE_EQ(run.At(0.5).surface_torque, 1.0);
}

// Pulling out at 0.2 m/s reached in 0.4 s: the hook load m a during the ramp, the rod moving with
// the block after it, its bit travelled ∫ v dt.
TEST(TransientDrive, BlockVelocityPullsTheRodOut) {
  const double velocity = 0.2, ramp = 0.4;
  const DrivenRun run = RunDriven(std::nullopt, model::BlockDrive{model::BlockMode::Velocity, {velocity, ramp}}, 0.8);
  const double force = Mass() * velocity / ramp;
  EXPECT_NEAR(run.At(0.3).hook_load, force, 0.03 * force);
  EXPECT_NEAR(run.At(0.8).hook_load, 0.0, 0.03 * force);
  // The bit body's frame origin moved up-hole (+x) by the block's travel 0.2 (0.8 − 0.2) m.
  const VecX& q = run.result.final_q;
  EXPECT_NEAR(q[0], velocity * (0.8 - 0.5 * ramp), 1e-3 * velocity);
  EXPECT_NEAR(run.result.final_v[0], velocity, 1e-3 * velocity);
}

// A hook load of 1000 N on the free rod: it accelerates up-hole at H/m.
TEST(TransientDrive, HookLoadAcceleratesTheRodAtHOverM) {
  const DrivenRun run = RunDriven(std::nullopt, model::BlockDrive{model::BlockMode::HookLoad, {1000.0, 0.0}}, 0.2);
  const double travel = 0.5 * 1000.0 / Mass() * 0.2 * 0.2;
  EXPECT_NEAR(run.result.final_q[0], travel, 0.01 * travel);
  EXPECT_DOUBLE_EQ(run.At(0.2).hook_load, 1000.0);
}

// A negative hook load is a compression: 20 kN (15 % of the pinned rod's Euler load π²EI/L² =
// 133 kN) ramped over 0.5 s onto the rod held axially at the bit and held to 1 s shortens it by
// F L/EA = 0.106 mm, quasi-statically: the ramp is 130 periods of the rod's first axial mode held
// at the bit (255 Hz), so the lag behind the static shortening, ~1/(ω T) = 1e-3 of it at the
// ramp's end, has decayed (5 % damping) by 1 s. Tolerance 1e-3 of F L/EA (measured +1.4e-4: the
// about the compliance the stiff body coupling and support springs add).
TEST(TransientDrive, CompressiveHookLoadShortensTheRodByFLOverEA) {
  const double force = 2e4, ramp = 0.5;
  const DrivenRun run =
      RunDriven(std::nullopt, model::BlockDrive{model::BlockMode::HookLoad, {-force, ramp}}, 1.0, true);
  EXPECT_DOUBLE_EQ(run.At(0.25).hook_load, -0.5 * force);
  EXPECT_DOUBLE_EQ(run.At(1.0).hook_load, -force);
  const double expected = -force * kRodLength / (2.1e11 * testing::RodArea());
  std::printf("[ measure  ] compressive hook load: top travel %.6e m against -F L/EA = %.6e m (%+.2e)\n",
              run.top_travel, expected, run.top_travel / expected - 1.0);
  EXPECT_NEAR(run.top_travel, expected, 1e-3 * std::abs(expected));
}

// The block pulling the rod (held axially at the bit) out through a line ten times softer than the
// rod, EA/L = 1.88e8 N/m: line and rod in series, the hook load is the travel ∫ v dt over
// 1/k_line + L/EA, and the top has moved by that force's F L/EA. 1 mm/s reached in 0.5 s and held
// to 1 s: 0.75 mm of travel, 12.8 kN; quasi-static as in the compression test above (the rod's
// first axial mode with the line at its top, ~260 Hz, against a 0.5 s ramp). Tolerance 1e-3.
TEST(TransientDrive, BlockThroughASoftLinePullsWithTheSeriesStiffness) {
  const double velocity = 1e-3, ramp = 0.5;
  const double rod_stiffness = 2.1e11 * testing::RodArea() / kRodLength, line_stiffness = 0.1 * rod_stiffness;
  model::BlockDrive block{model::BlockMode::Velocity, {velocity, ramp}};
  block.line_stiffness = line_stiffness;
  const DrivenRun run = RunDriven(std::nullopt, block, 1.0, true);
  const double travel = velocity * (1.0 - 0.5 * ramp);
  const double force = travel / (1.0 / line_stiffness + 1.0 / rod_stiffness);
  std::printf("[ measure  ] block through a soft line: hook load %.6e N against %.6e N (%+.2e), top travel %.6e m "
              "against F L/EA = %.6e m (%+.2e)\n",
              run.At(1.0).hook_load, force, run.At(1.0).hook_load / force - 1.0, run.top_travel, force / rod_stiffness,
              run.top_travel * rod_stiffness / force - 1.0);
  EXPECT_NEAR(run.At(1.0).hook_load, force, 1e-3 * force);
  EXPECT_NEAR(run.top_travel, force / rod_stiffness, 1e-3 * force / rod_stiffness);
}

// PlaceBlockAtStart reads the top's axial displacement in the start positions: the rod moved up-hole
// by 0.3 mm as a whole. Without a line stiffness of its own the block is left as it was.
TEST(TransientDrive, ABlockLineStartsAtTheTopsDisplacement) {
  cms::ReductionCache cache;
  model::ModelInput input = testing::RodInput(2, 2.1e11, kDensity, 4, 4);
  const model::BuiltModel start = model::BuildSystemModel(input, cache);
  VecX dv = VecX::Zero(start.system.num_velocities());
  for (const model::Body& body : start.system.bodies()) dv[body.v_offset] = 3e-4;
  const VecX q0 = start.system.Increment(start.system.ReferencePositions(), dv);
  model::BlockDrive block{model::BlockMode::Velocity, {0.1, 1.0}};
  input.block = block;
  EXPECT_EQ(PlaceBlockAtStart(input, start, q0).block->start_top_displacement, 0.0);
  input.block->line_stiffness = 1e6;
  EXPECT_NEAR(PlaceBlockAtStart(input, start, q0).block->start_top_displacement, 3e-4, 1e-12);
}

}  // namespace transient_drive_test
}  // namespace drillflex::analyses
