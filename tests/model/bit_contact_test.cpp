// The bit's bottom contact (model/bit_bottom.hpp) and side cutting (model/bit_side_cutting.hpp):
// their forces against the formulas (k δ + c δ̇ pressing, nothing lifted off nor where the damper
// would pull; −2π k_s/Ω_r times the lateral velocity), the bottom's harmonic motion and ramp, their
// stiffness and damping against central differences of their residual, the bottom's penalty
// gradient against differences of δ, and what the builder does with them (default stiffness, the
// case's WOB left out, the bit's lateral hold freed).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "element_problem.hpp"
#include "model/bit_rock.hpp"
#include "model/builder.hpp"
#include "model_test_support.hpp"

namespace drillflex::model {
namespace bit_contact_test {

using testing::ElementProblem;
using testing::JacobianErrors;
using testing::PerturbedPositions;
using testing::RodInput;

constexpr double kStiffness = 4e8;  // N/m

BitRockParameters BottomOnly(double stiffness = kStiffness) {
  BitRockParameters p;
  p.law = BitRockLaw::None;
  p.stick_speed = kDefaultStickSpeed;
  p.bottom = BitBottomParameters{};
  p.bottom->stiffness = stiffness;
  p.bottom->damping_ratio = 0.1;
  return p;
}

BuiltModel Build(const ModelInput& input) {
  cms::ReductionCache cache;
  return BuildSystemModel(input, cache);
}

ModelInput RodWith(const BitRockParameters& p) {
  ModelInput input = RodInput(2, 4, 5);
  input.bit_rock = p;
  return input;
}

const BitBottomElement& Bottom(const BuiltModel& built) {
  return built.Get(*built.bit_bottom);
}

// The bottom element's local force at (q, v, t).
VecX LocalForce(const BuiltModel& built, const ForceElement& element, const VecX& q, const VecX& v, double t) {
  const auto poses = built.system.Poses(q);
  ElementContribution c;
  element.Evaluate(built.system.StateOf(element, poses, v, t, 1.0), false, c);
  return c.force;
}

// The rigid motion of the bit body: its first body's frame moved by `dx` along x (up-hole here).
VecX Moved(const SystemModel& model, double dx) {
  VecX dv = VecX::Zero(model.num_velocities());
  dv[0] = dx;
  return model.Increment(model.ReferencePositions(), dv);
}

TEST(BitBottomTest, PushesOnlyWhilePressedIn) {
  const BuiltModel built = Build(RodWith(BottomOnly()));
  const SystemModel& model = built.system;
  const BitBottomElement& bottom = Bottom(built);
  const double k = bottom.stiffness(), c = bottom.damping();
  // c = 2ζ sqrt(k m), m one FE element of the bit body: ρ A ℓ.
  const double element_mass = 7800.0 * kPi * 0.0762 * 0.0762 / 4.0 * (2.54 / 4.0);
  EXPECT_NEAR(c, 2.0 * 0.1 * std::sqrt(kStiffness * element_mass), 1e-9 * c);
  VecX v = VecX::Zero(model.num_velocities());
  // 0.1 mm into the bottom (the bit moved down-hole, −x), moving down at 1 mm/s: the rock pushes
  // up-hole (+x) with k δ + c δ̇; the residual gets −Q.
  const double delta = 1e-4, rate = 1e-3;
  v[0] = -rate;
  const VecX pressed = LocalForce(built, bottom, Moved(model, -delta), v, 0.0);
  EXPECT_NEAR(pressed[0], -(k * delta + c * rate), 1e-9 * k * delta);
  EXPECT_NEAR(pressed.segment<2>(1).norm(), 0.0, 1e-9 * k * delta);
  {
    const auto poses = model.Poses(Moved(model, -delta));
    EXPECT_NEAR(bottom.ContactForce(model.StateOf(bottom, poses, v, 0.0, 1.0)), k * delta + c * rate, 1e-9 * k * delta);
  }
  // Lifted off: nothing.
  EXPECT_EQ(LocalForce(built, bottom, Moved(model, 1e-5), v, 0.0).norm(), 0.0);
  // Still in, but leaving so fast that k δ + c δ̇ < 0: the damper does not pull.
  v[0] = 2.0 * k * delta / c;
  EXPECT_EQ(LocalForce(built, bottom, Moved(model, -delta), v, 0.0).norm(), 0.0);
}

TEST(BitBottomTest, HarmonicMotionWithItsRamp) {
  BitRockParameters p = BottomOnly();
  p.bottom->level = 2e-4;
  p.bottom->amplitude = 1e-3;
  p.bottom->frequency = 5.0;
  p.bottom->ramp_time = 0.4;
  const BuiltModel built = Build(RodWith(p));
  const BitBottomElement& bottom = Bottom(built);
  const double omega = 2.0 * kPi * 5.0;
  // After the ramp: level + a sin(ωt); half-way through it the envelope is a/2.
  EXPECT_NEAR(bottom.BottomPlace(0.55), 2e-4 + 1e-3 * std::sin(omega * 0.55), 1e-15);
  EXPECT_NEAR(bottom.BottomPlace(0.2), 2e-4 + 0.5e-3 * std::sin(omega * 0.2), 1e-15);
  EXPECT_EQ(bottom.BottomPlace(0.0), 2e-4);
  // The rate is the place's derivative (central differences, in and after the ramp).
  for (const double t : {0.1, 0.33, 0.61}) {
    const double h = 1e-7;
    EXPECT_NEAR(bottom.BottomRate(t), (bottom.BottomPlace(t + h) - bottom.BottomPlace(t - h)) / (2 * h), 1e-7 * omega * 1e-3)
        << t;
  }
}

TEST(BitBottomTest, JacobiansMatchCentralDifferences) {
  BitRockParameters p = BottomOnly();
  p.bottom->level = 0.02;  // pressed in at every perturbed state below (they move the bit by < 0.02 m)
  p.bottom->amplitude = 1e-3;
  p.bottom->frequency = 3.0;
  const BuiltModel built = Build(RodWith(p));
  const SystemModel& model = built.system;
  const ElementProblem problem(model, *built.bit_bottom);
  std::mt19937 rng(11);
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = PerturbedPositions(model, rng, 0.01);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    VecX v(model.num_velocities());
    for (int i = 0; i < v.size(); ++i) v[i] = 1e-3 * u(rng);
    const double t = 0.1 * trial;
    ASSERT_GT(Bottom(built).ContactForce(problem.State(t, q, v)), 0.0);
    const testing::Errors e = JacobianErrors(problem, t, q, v);
    EXPECT_LT(e.stiffness, 1e-6) << trial;
    EXPECT_LT(e.damping, 1e-6) << trial;
  }
}

TEST(BitBottomTest, PenaltyGradientIsThePenetrationsDerivative) {
  BitRockParameters p = BottomOnly();
  p.bottom->level = 1e-3;
  const BuiltModel built = Build(RodWith(p));
  const SystemModel& model = built.system;
  const BitBottomElement& bottom = Bottom(built);
  std::mt19937 rng(5);
  const VecX q = PerturbedPositions(model, rng, 0.01);
  const VecX rest = VecX::Zero(model.num_velocities());
  const auto delta_at = [&](const VecX& at) {
    const auto poses = model.Poses(at);
    return bottom.Penetration(model.StateOf(bottom, poses, rest, 0.0, 1.0));
  };
  const auto poses = model.Poses(q);
  double value = 0.0, stiffness = 0.0;
  VecX gradient;
  ASSERT_TRUE(bottom.Penalty(model.StateOf(bottom, poses, rest, 0.0, 1.0), value, stiffness, gradient));
  EXPECT_EQ(stiffness, kStiffness);
  EXPECT_DOUBLE_EQ(value, delta_at(q));
  const int n = bottom.local_size();
  for (int j = 0; j < n; ++j) {
    VecX dq = VecX::Zero(model.num_velocities());
    dq[j] = 1e-6;
    const double numeric = (delta_at(model.Increment(q, dq)) - delta_at(model.Increment(q, -dq))) / 2e-6;
    EXPECT_NEAR(gradient[j], numeric, 1e-7) << j;
  }
}

TEST(BitBottomTest, BuilderDefaultsAndTheCasesWob) {
  ModelInput input = RodWith(BottomOnly(0.0));
  input.operation.weight_on_bit = 1000.0;
  input.operation.torque_on_bit = 300.0;
  const BuiltModel built = Build(input);
  const Body& bit = built.system.bodies().front();
  // As stiff as the supports: 10 × c·EA/ℓ of the bit body.
  EXPECT_DOUBLE_EQ(Bottom(built).stiffness(), kSupportStiffnessFactor * input.settings.coupling_factor *
                                                  bit.axial_rigidity / bit.element_length);
  EXPECT_EQ(built.bit_rock.has_value(), false);  // no torque law
  // At the reference (touching, δ = 0) the contact pushes nothing; the case's WOB is not applied,
  // its TOB is (no law replaces it).
  const VecX zero = VecX::Zero(built.system.num_velocities());
  const VecX r = built.system.Residual(0.0, built.system.ReferencePositions(), zero, zero, 1.0);
  EXPECT_NEAR(r[0], 0.0, 1e-9);
  EXPECT_NEAR(r[3], -300.0, 1e-9);
  // None of it without a bottom.
  EXPECT_EQ(Build(RodInput(2, 4, 5)).bit_bottom.has_value(), false);
}

TEST(BitBottomTest, RefusedWithDetournaysLawAndBadParameters) {
  BitRockParameters p = BottomOnly();
  p.law = BitRockLaw::Detournay;
  p.radius = 0.1;
  p.specific_energy = 5e7;
  p.cutting_ratio = 0.6;
  p.contact_speed = 1e-5;
  EXPECT_THROW(CheckBitRockParameters(p), LogicError);
  p = BottomOnly();
  p.bottom->amplitude = 1e-3;  // no frequency
  EXPECT_THROW(CheckBitRockParameters(p), LogicError);
}

BitRockParameters SideCutting(double resistance) {
  BitRockParameters p;
  p.law = BitRockLaw::None;
  p.stick_speed = 0.05;
  p.side_cutting = resistance;
  return p;
}

TEST(BitSideCuttingTest, ForceAgainstTheLateralVelocity) {
  const double ks = 3e7;
  const BuiltModel built = Build(RodWith(SideCutting(ks)));
  const SystemModel& model = built.system;
  const ForceElement& side = built.Get(*built.bit_side);
  const VecX q = model.ReferencePositions();
  VecX v = VecX::Zero(model.num_velocities());
  const double spin = 12.0;
  v[0] = -3e-3;  // drilling ahead: no lateral force from it
  v[1] = 1e-3;
  v[2] = -2e-3;
  v[3] = -spin;  // clockwise looking down-hole (about −x)
  const VecX force = LocalForce(built, side, q, v, 0.0);
  const double coefficient = 2.0 * kPi * ks / std::sqrt(spin * spin + 0.05 * 0.05);
  // The rock's force −c V_n; the residual gets −Q = +c V_n.
  EXPECT_NEAR(force[0], 0.0, 1e-9 * coefficient * 1e-3);
  EXPECT_NEAR(force[1], coefficient * 1e-3, 1e-9 * coefficient * 1e-3);
  EXPECT_NEAR(force[2], -coefficient * 2e-3, 1e-9 * coefficient * 1e-3);
}

TEST(BitSideCuttingTest, JacobiansMatchCentralDifferences) {
  const BuiltModel built = Build(RodWith(SideCutting(3e7)));
  const SystemModel& model = built.system;
  const ElementProblem problem(model, *built.bit_side);
  std::mt19937 rng(7);
  for (const double spin : {-8.0, 0.02, 0.3}) {
    const VecX q = testing::SpunPositions(model, 0.4, 0.01, rng);
    const VecX v = testing::SpinningVelocities(model, -spin, 1e-3, rng);
    const testing::Errors e = JacobianErrors(problem, 0.0, q, v);
    EXPECT_LT(e.stiffness, 1e-6) << spin;
    EXPECT_LT(e.damping, 1e-6) << spin;
  }
}

// Side cutting takes over the supports' lateral hold of the bit: a bit moved sideways is held by
// nothing but the (velocity) law.
TEST(BitSideCuttingTest, FreesTheBitsLateralHold) {
  const auto lateral_reaction = [](const std::optional<BitRockParameters>& p) {
    ModelInput input = RodInput(2, 4, 5);
    Support bit;
    bit.at = 0.0;
    bit.fixed[kY] = bit.fixed[kZ] = true;
    Support top;
    top.at = 5.08;
    top.fixed.fill(true);
    input.supports = {bit, top};
    input.bit_rock = p;
    const BuiltModel built = Build(input);
    VecX dv = VecX::Zero(built.system.num_velocities());
    dv[1] = 1e-3;  // the first body moved sideways (y)
    const VecX q = built.system.Increment(built.system.ReferencePositions(), dv);
    const VecX zero = VecX::Zero(built.system.num_velocities());
    const VecX at_rest = built.system.Residual(0.0, built.system.ReferencePositions(), zero, zero, 1.0);
    const VecX moved = built.system.Residual(0.0, q, zero, zero, 1.0);
    // The support's part of the first body's y residual: the coupling to the next body is the same
    // in both models.
    return moved[1] - at_rest[1];
  };
  const double held = lateral_reaction(std::nullopt);
  const double cutting = lateral_reaction(SideCutting(3e7));
  EXPECT_GT(held - cutting, 1e3);  // the support's spring, 10 × c·12EI/ℓ³ × 1 mm, is gone
  EXPECT_GT(cutting, 0.0);         // the coupling to the body above still pulls back
}

}  // namespace bit_contact_test
}  // namespace drillflex::model
