// Detournay's bit–rock law (model/bit_rock.hpp) in a transient run: a short, stiff collar pushed
// down with a dead axial force W and turned by a dead torque T at its top, on a bit of radius a,
// held laterally only. Rigid, it drills at a constant depth of cut d per revolution while it spins
// up, with (the law plus Newton's second law for the axial and the spin motion, V = dΩ/2π):
//   m d Ω̇/2π = W − (ζ ε a d + W_f),   J Ω̇ = T − (½ ε a² d + ½ μ γ a W_f).
// Below the torque the bit needs (T < TOB at that WOB) it does not turn: it sticks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analyses/transient_analysis.hpp"
#include "analyses_test_support.hpp"
#include "cms/reduction_cache.hpp"

namespace drillflex::analyses {
namespace bit_rock_transient_test {

using testing::PointLoad;
using testing::SupportAt;

constexpr double kDiameter = 0.3, kDensity = 7800.0, kWob = 20e3;

model::BitRockParameters Rock() {
  model::BitRockParameters p;
  p.law = model::BitRockLaw::Detournay;
  p.radius = 0.1;
  p.specific_energy = 50e6;
  p.cutting_ratio = 0.6;
  p.contact_force = 2e3;
  p.friction = 0.5;
  p.geometry = 1.0;
  p.contact_speed = 1e-5;
  p.stick_speed = 0.01;
  return p;
}

// The torque the bit needs at the WOB W when it does not accelerate: ½ a (W − W_f)/ζ + ½ μ γ a W_f.
double SteadyTorque(const model::BitRockParameters& p) {
  return 0.5 * p.radius * (kWob - p.contact_force) / p.cutting_ratio + 0.5 * p.friction * p.geometry * p.radius * p.contact_force;
}

struct DrillRun {
  TransientResult result;
  double penetration = 0.0, spin = 0.0;  // of the bit at the end, m/s and rad/s
};

DrillRun Drill(double torque, double duration) {
  model::ModelInput input = testing::RodInput(1, 2.1e11, kDensity, 4, 6);
  input.string.components[0].outer_diameter = kDiameter;
  // Damped torsion: at a fixed penetration rate the cutting torque falls with the spin (∝ 1/Ω), a
  // negative damping TOB/Ω that the rod's torsional modes would otherwise grow on.
  input.settings.structural_damping = 0.05;
  input.supports = {SupportAt(0.0, {model::kY, model::kZ}), SupportAt(testing::kRodLength, {model::kY, model::kZ})};
  // Down-hole is −x; clockwise looking down-hole is about −x.
  input.loads = {PointLoad(testing::kRodLength, Vec3(-kWob, 0.0, 0.0), Vec3(-torque, 0.0, 0.0))};
  input.bit_rock = Rock();
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  TransientSettings settings;
  settings.start = TransientStart::Reference;
  settings.duration = duration;
  settings.output_interval = duration / 10.0;
  settings.tolerance = 1e-5;
  DrillRun run;
  run.result = RunTransient(built, built.system.ReferencePositions(), settings);
  const auto& element = built.Get(*built.bit_rock);
  const auto poses = built.system.Poses(run.result.final_q);
  const model::ElementState state = built.system.StateOf(element, poses, run.result.final_v, duration, 1.0);
  run.penetration = element.PenetrationRate(state);
  run.spin = element.SpinRate(state);
  return run;
}

TEST(BitRockTransient, RigidCollarDrillsAtTheDepthOfCutItsWobGives) {
  const model::BitRockParameters p = Rock();
  const double torque = 1.5 * SteadyTorque(p);
  const DrillRun run = Drill(torque, 1.0);
  // The rigid collar's reference: mass and polar inertia of the solid rod; d and Ω̇ by fixed point.
  const double area = kPi * kDiameter * kDiameter / 4.0;
  const double mass = kDensity * area * testing::kRodLength;
  const double inertia = kDensity * kPi * std::pow(kDiameter, 4) / 32.0 * testing::kRodLength;
  const double a = p.radius, eps = p.specific_energy;
  double depth = (kWob - p.contact_force) / (p.cutting_ratio * eps * a), acceleration = 0.0;
  for (int i = 0; i < 50; ++i) {
    acceleration = (torque - 0.5 * eps * a * a * depth - 0.5 * p.friction * p.geometry * a * p.contact_force) / inertia;
    depth = (kWob - p.contact_force) / (p.cutting_ratio * eps * a + mass * acceleration / (2.0 * kPi));
  }
  // The depth of cut per revolution 2πV/Ω (6 mm): within 0.1 %.
  ASSERT_GT(run.spin, 1.0);
  EXPECT_NEAR(2.0 * kPi * run.penetration / run.spin, depth, 1e-3 * depth);
  // The spin-up rate from the bit speeds at 0.5 and 1 s: within 1 %.
  const auto& samples = run.result.samples;
  const double measured = (std::abs(samples[10].bit_speed) - std::abs(samples[5].bit_speed)) / 0.5;
  EXPECT_NEAR(measured, acceleration, 1e-2 * acceleration);
  std::printf("Detournay drilling: d %.6g mm (reference %.6g), spin-up %.6g rad/s2 (reference %.6g)\n",
              1e3 * 2.0 * kPi * run.penetration / run.spin, 1e3 * depth, measured, acceleration);
}

TEST(BitRockTransient, BelowTheTorqueItNeedsTheBitSticks) {
  const model::BitRockParameters p = Rock();
  const DrillRun run = Drill(0.8 * SteadyTorque(p), 0.5);
  // Stuck: the viscous stick law carries the torque at a creep of 0.8 Ω_ε (TOB = TOB_full Ω/Ω_ε), and
  // the WOB holds the regularized depth of cut, so the bit creeps ahead at d sqrt(Ω² + Ω_ε²)/2π.
  EXPECT_NEAR(run.spin, 0.8 * p.stick_speed, 1e-2 * p.stick_speed);
  const double depth = (kWob - p.contact_force) / (p.cutting_ratio * p.specific_energy * p.radius);
  const double creep = depth * std::hypot(run.spin, p.stick_speed) / (2.0 * kPi);
  EXPECT_NEAR(run.penetration, creep, 1e-2 * creep);
}

}  // namespace bit_rock_transient_test
}  // namespace drillflex::analyses
