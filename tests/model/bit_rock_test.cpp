// The bit–rock interaction (model/bit_rock.hpp): Detournay's law against its unregularized
// formulas while drilling, lift-off and a bit that does not turn; the friction law's levels and
// continuity; the laws' derivatives and the element's stiffness and damping against central
// differences on every branch; the force's direction on the string; the builder's element.
#include "model/bit_rock.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <utility>
#include <random>

#include "core/error.hpp"
#include "model_test_support.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {
namespace bit_rock_test {

using testing::PerturbedPositions;
using testing::RodInput;

// An 8.5 in PDC bit in a medium-strength rock (Richard et al. 2007, table 1 orders of magnitude):
// ε = 60 MPa, ζ = 0.6, W_f = 20 kN, μ = 0.6, γ = 1.
BitRockParameters DetournayParameters() {
  BitRockParameters p;
  p.law = BitRockLaw::Detournay;
  p.radius = 0.10795;
  p.specific_energy = 60e6;
  p.cutting_ratio = 0.6;
  p.contact_force = 20e3;
  p.friction = 0.6;
  p.geometry = 1.0;
  p.contact_speed = 1e-5;
  p.stick_speed = 0.01;
  return p;
}

BitRockParameters FrictionParameters() {
  BitRockParameters p;
  p.law = BitRockLaw::Friction;
  p.static_torque = 12e3;
  p.kinetic_torque = 8e3;
  p.stick_speed = 0.01;
  p.stribeck_speed = 0.2;
  return p;
}

TEST(BitRockLawTest, DetournayMatchesItsFormulasWhileDrilling) {
  const BitRockParameters p = DetournayParameters();
  const double rop = 20.0 / 3600.0, omega = 120.0 * 2.0 * kPi / 60.0;  // 20 m/h at 120 rpm
  const double d = 2.0 * kPi * rop / omega;                              // 0.46 mm a revolution
  const double a = p.radius;
  const BitRockForces f = EvaluateBitRock(p, rop, omega);
  // Ω_ε/Ω = 8e-4: the regularized d is off by ½(Ω_ε/Ω)² = 3e-7.
  EXPECT_NEAR(f.wob, p.cutting_ratio * p.specific_energy * a * d + p.contact_force, 1e-6 * f.wob);
  EXPECT_NEAR(f.tob, 0.5 * p.specific_energy * a * a * d + 0.5 * p.friction * p.geometry * a * p.contact_force,
              1e-6 * f.tob);
  // The same torque against a backward spin.
  EXPECT_NEAR(EvaluateBitRock(p, rop, -omega).tob, -f.tob, 1e-9 * f.tob);
}

TEST(BitRockLawTest, DetournayLiftOffAndRest) {
  const BitRockParameters p = DetournayParameters();
  // Lifting off (V < 0): no force, whatever the spin.
  const BitRockForces off = EvaluateBitRock(p, -1e-3, 10.0);
  EXPECT_EQ(off.wob, 0.0);
  EXPECT_EQ(off.tob, 0.0);
  // At rest: nothing.
  const BitRockForces rest = EvaluateBitRock(p, 0.0, 0.0);
  EXPECT_EQ(rest.wob, 0.0);
  EXPECT_EQ(rest.tob, 0.0);
  // Pressing ahead without turning: a finite axial resistance 2π ζ ε a V/Ω_ε + W_f, no torque.
  const double v = 1e-4;
  const BitRockForces pressing = EvaluateBitRock(p, v, 0.0);
  EXPECT_TRUE(std::isfinite(pressing.wob));
  EXPECT_NEAR(pressing.wob, 2.0 * kPi * p.cutting_ratio * p.specific_energy * p.radius * v / p.stick_speed +
                                p.contact_force, 1e-9 * pressing.wob);
  EXPECT_EQ(pressing.tob, 0.0);
  // The flats' contact is half mobilized at half the contact speed.
  EXPECT_NEAR(EvaluateBitRock(p, 0.5 * p.contact_speed, 1e3).wob - 0.5 * p.contact_force, 0.0,
              1e-3 * p.contact_force);
}

TEST(BitRockLawTest, FrictionLevelsAndContinuity) {
  const BitRockParameters p = FrictionParameters();
  // Continuous at the stick speed, at the static level.
  EXPECT_NEAR(EvaluateBitRock(p, 0.0, p.stick_speed).tob, p.static_torque, 1e-9 * p.static_torque);
  EXPECT_NEAR(EvaluateBitRock(p, 0.0, p.stick_speed * (1.0 + 1e-9)).tob, p.static_torque, 1e-6 * p.static_torque);
  // Kinetic level well into the slip: T_d + (T_s − T_d) e^(−50).
  EXPECT_NEAR(EvaluateBitRock(p, 0.0, 10.0).tob, p.kinetic_torque, 1e-9 * p.kinetic_torque);
  EXPECT_NEAR(EvaluateBitRock(p, 0.0, -10.0).tob, -p.kinetic_torque, 1e-9 * p.kinetic_torque);
  // Viscous stick: half the static torque at half the stick speed; no axial force.
  const BitRockForces stick = EvaluateBitRock(p, 1e-3, 0.5 * p.stick_speed);
  EXPECT_NEAR(stick.tob, 0.5 * p.static_torque, 1e-9 * p.static_torque);
  EXPECT_EQ(stick.wob, 0.0);
  // One Stribeck speed into the slip: T_d + (T_s − T_d)/e.
  EXPECT_NEAR(EvaluateBitRock(p, 0.0, p.stick_speed + p.stribeck_speed).tob,
              p.kinetic_torque + (p.static_torque - p.kinetic_torque) / std::exp(1.0), 1e-9 * p.static_torque);
}

TEST(BitRockLawTest, BadParametersThrow) {
  BitRockParameters p = FrictionParameters();
  p.static_torque = p.kinetic_torque;
  EXPECT_THROW(EvaluateBitRock(p, 0.0, 1.0), LogicError);
  p = DetournayParameters();
  p.specific_energy = 0.0;
  EXPECT_THROW(EvaluateBitRock(p, 0.0, 1.0), LogicError);
  p = DetournayParameters();
  p.stick_speed = 0.0;
  EXPECT_THROW(EvaluateBitRock(p, 0.0, 1.0), LogicError);
}

// Central differences of the law at (V, Ω) against its derivatives, off the kinks.
void CheckLawDerivatives(const BitRockParameters& p, double v, double omega, const char* where) {
  const BitRockForces f = EvaluateBitRock(p, v, omega);
  const double hv = 1e-6 * std::max(std::abs(v), 1e-5);  // below every V_ε of the tests
  const double hw = 1e-6 * std::max(std::abs(omega), p.stick_speed);
  const BitRockForces vp = EvaluateBitRock(p, v + hv, omega), vm = EvaluateBitRock(p, v - hv, omega);
  const BitRockForces wp = EvaluateBitRock(p, v, omega + hw), wm = EvaluateBitRock(p, v, omega - hw);
  const auto close = [](double analytic, double numeric) {
    return std::abs(analytic - numeric) <= 1e-6 * std::max(1.0, std::abs(analytic)) + 1e-5 * std::abs(analytic);
  };
  EXPECT_TRUE(close(f.wob_by_penetration, (vp.wob - vm.wob) / (2 * hv))) << where << ": dWOB/dV " << f.wob_by_penetration;
  EXPECT_TRUE(close(f.wob_by_spin, (wp.wob - wm.wob) / (2 * hw))) << where << ": dWOB/dOmega " << f.wob_by_spin;
  EXPECT_TRUE(close(f.tob_by_penetration, (vp.tob - vm.tob) / (2 * hv))) << where << ": dTOB/dV " << f.tob_by_penetration;
  EXPECT_TRUE(close(f.tob_by_spin, (wp.tob - wm.tob) / (2 * hw))) << where << ": dTOB/dOmega " << f.tob_by_spin;
}

TEST(BitRockLawTest, DerivativesMatchCentralDifferencesOnEveryBranch) {
  const BitRockParameters d = DetournayParameters();
  CheckLawDerivatives(d, 5e-3, 12.0, "Detournay drilling");
  CheckLawDerivatives(d, 5e-3, -3.0, "Detournay backward spin");
  CheckLawDerivatives(d, 5e-3, 0.004, "Detournay sticking");
  CheckLawDerivatives(d, 0.4 * d.contact_speed, 2.0, "Detournay contact building up");
  CheckLawDerivatives(d, -1e-3, 2.0, "Detournay lifted off");
  const BitRockParameters f = FrictionParameters();
  CheckLawDerivatives(f, 0.0, 0.003, "friction stick");
  CheckLawDerivatives(f, 0.0, 0.3, "friction slip");
  CheckLawDerivatives(f, 0.0, -0.05, "friction backward slip");
}

// A one-body rod (the V1 rod, bit at node 0) with the element, at a state moved off the reference.
struct BitModel {
  BuiltModel built;
  const BitRockElement& element() const {
    return built.Get(*built.bit_rock);
  }
};

BitModel MakeBitModel(const BitRockParameters& parameters) {
  ModelInput input = RodInput(1, 4, 5);
  input.bit_rock = parameters;
  cms::ReductionCache cache;
  return BitModel{BuildSystemModel(input, cache)};
}

// The element's local force at (q, v).
VecX ElementForce(const BitModel& m, const VecX& q, const VecX& v) {
  const auto poses = m.built.system.Poses(q);
  ElementContribution c;
  m.element().Evaluate(m.built.system.StateOf(m.element(), poses, v, 0.0, 1.0), false, c);
  return c.force;
}

// The velocities that give the bit node a penetration rate V and a spin rate Ω (drilling sense)
// with a random lateral motion and modal rates on top, at the state q.
VecX BitVelocities(const BitModel& m, const VecX& q, double penetration, double spin, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const SystemModel& model = m.built.system;
  VecX v(model.num_velocities());
  for (int i = 0; i < v.size(); ++i) v[i] = (i < 6 ? 1e-3 : 1e-4) * u(rng);
  // Aim the node's velocity and rate with the rigid part: the string axis is the reference x.
  const auto poses = model.Poses(q);
  const ElementState state = model.StateOf(m.element(), poses, v, 0.0, 1.0);
  const double dv = -penetration - (-m.element().PenetrationRate(state));
  const double dw = -spin - (-m.element().SpinRate(state));
  const Mat3& A = poses[0].A;
  v.head<3>() += dv * Vec3::UnitX();
  v.segment<3>(3) += A.transpose() * (dw * Vec3::UnitX());  // ω is in the body frame
  return v;
}

void CheckElementJacobians(const BitRockParameters& parameters, double penetration, double spin, const char* where) {
  const BitModel m = MakeBitModel(parameters);
  const SystemModel& model = m.built.system;
  std::mt19937 rng(3);
  const VecX q = PerturbedPositions(model, rng, 0.02);
  const VecX v = BitVelocities(m, q, penetration, spin, rng);
  {
    const auto poses = model.Poses(q);
    const ElementState state = model.StateOf(m.element(), poses, v, 0.0, 1.0);
    ASSERT_NEAR(m.element().PenetrationRate(state), penetration, 1e-6 * std::abs(penetration) + 1e-12) << where;
    ASSERT_NEAR(m.element().SpinRate(state), spin, 1e-6 * std::abs(spin) + 1e-12) << where;
  }
  const auto poses = model.Poses(q);
  ElementContribution analytic;
  m.element().Evaluate(model.StateOf(m.element(), poses, v, 0.0, 1.0), true, analytic);
  const int n = m.element().local_size();
  ASSERT_EQ(n, model.num_velocities());
  MatX stiffness(n, n), damping(n, n);
  const double h = 1e-7;
  for (int j = 0; j < n; ++j) {
    VecX dq = VecX::Zero(n);
    dq[j] = h;
    stiffness.col(j) = (ElementForce(m, model.Increment(q, dq), v) - ElementForce(m, model.Increment(q, -dq), v)) / (2 * h);
    // Velocity steps small against the regularization speeds (the law's kinks).
    const double hv = 1e-4 * std::min(parameters.stick_speed, parameters.law == BitRockLaw::Detournay
                                                                  ? parameters.contact_speed : 1.0);
    VecX dv = VecX::Zero(n);
    dv[j] = hv;
    damping.col(j) = (ElementForce(m, q, v + dv) - ElementForce(m, q, v - dv)) / (2 * hv);
  }
  EXPECT_GT(analytic.damping.norm(), 0.0) << where;
  EXPECT_LT(solvers::RelativeMatrixError(analytic.stiffness, stiffness), 1e-5) << where;
  EXPECT_LT(solvers::RelativeMatrixError(analytic.damping, damping), 1e-6) << where;
}

TEST(BitRockElementTest, JacobiansMatchCentralDifferences) {
  CheckElementJacobians(DetournayParameters(), 5e-3, 12.0, "Detournay drilling");
  CheckElementJacobians(DetournayParameters(), 5e-3, 0.005, "Detournay sticking");
  CheckElementJacobians(DetournayParameters(), 0.3 * 1e-5, 8.0, "Detournay contact building up");
  CheckElementJacobians(FrictionParameters(), 0.0, 0.6, "friction slip");
  CheckElementJacobians(FrictionParameters(), 0.0, 0.004, "friction stick");
  CheckElementJacobians(FrictionParameters(), 0.0, -0.3, "friction backward slip");
}

TEST(BitRockElementTest, PushesTheBitUpHoleAndResistsItsSpin) {
  const BitRockParameters p = DetournayParameters();
  const BitModel m = MakeBitModel(p);
  const SystemModel& model = m.built.system;
  const VecX q = model.ReferencePositions();
  // Drilling: moving down-hole (−x here) and turning clockwise looking down-hole (about −x).
  const double rop = 5e-3, omega = 12.0;
  VecX v = VecX::Zero(model.num_velocities());
  v[0] = -rop;
  v[3] = -omega;
  const BitRockForces f = EvaluateBitRock(p, rop, omega);
  const VecX force = ElementForce(m, q, v);
  // The residual gets −Q: −WOB along x (the rock pushes up-hole, +x), +TOB about x (the rock's
  // moment TOB·x resists the spin about −x).
  EXPECT_NEAR(force[0], -f.wob, 1e-9 * f.wob);
  EXPECT_NEAR(force[3], -f.tob, 1e-9 * f.tob);
  EXPECT_NEAR(force.segment<2>(1).norm() + force.segment<2>(4).norm(), 0.0, 1e-9 * f.wob);
  // The power the rock takes out: Q·v = −(WOB V + TOB Ω) < 0.
  EXPECT_NEAR(-force.dot(v), -(f.wob * rop + f.tob * omega), 1e-9 * f.tob * omega);
}

TEST(BitRockElementTest, BuilderTakesTheRadiusFromTheBitOd) {
  BitRockParameters p = DetournayParameters();
  p.radius = 0.0;
  const BitModel m = MakeBitModel(p);
  EXPECT_DOUBLE_EQ(m.element().parameters().radius, 0.5 * 0.0762);
  EXPECT_EQ(m.element().bodies()[0], &m.built.system.bodies().front());
  ModelInput none = RodInput(1, 4, 5);
  cms::ReductionCache cache;
  EXPECT_EQ(BuildSystemModel(none, cache).bit_rock.has_value(), false);
}

// At rest the law puts nothing on the bit; what remains of the operation's bit loads shows in the
// residual's bit entries (−f_ext: −WOB along x, −TOB about x).
TEST(BitRockElementTest, ReplacesTheOperationsBitLoads) {
  const auto bit_entries = [](const std::optional<BitRockParameters>& law) {
    ModelInput input = RodInput(1, 4, 5);
    input.operation.weight_on_bit = 1000.0;
    input.operation.torque_on_bit = 300.0;
    input.bit_rock = law;
    cms::ReductionCache cache;
    const BuiltModel built = BuildSystemModel(input, cache);
    const VecX zero = VecX::Zero(built.system.num_velocities());
    const VecX r = built.system.Residual(0.0, built.system.ReferencePositions(), zero, zero, 1.0);
    return std::pair<double, double>(r[0], r[3]);
  };
  const auto [plain_wob, plain_tob] = bit_entries(std::nullopt);
  EXPECT_NEAR(plain_wob, -1000.0, 1e-9);
  EXPECT_NEAR(plain_tob, -300.0, 1e-9);
  const auto [friction_wob, friction_tob] = bit_entries(FrictionParameters());
  EXPECT_NEAR(friction_wob, -1000.0, 1e-9);  // the friction law leaves the WOB applied
  EXPECT_NEAR(friction_tob, 0.0, 1e-9);
  const auto [detournay_wob, detournay_tob] = bit_entries(DetournayParameters());
  EXPECT_NEAR(detournay_wob, 0.0, 1e-9);
  EXPECT_NEAR(detournay_tob, 0.0, 1e-9);
}

}  // namespace bit_rock_test
}  // namespace drillflex::model
