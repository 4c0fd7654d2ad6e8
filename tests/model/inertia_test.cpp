// The inertia terms' Jacobians (model/body_inertia_jacobian.hpp) against central differences of the
// inertial residual M(q) a + Q_v(q, v) and of the whole model's residual, at random moving states;
// the mass matrix's symmetry and definiteness; and the power balance of the gyroscopic terms.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cstdio>
#include <random>

#include "core/so3.hpp"
#include "model/body_dynamics.hpp"
#include "model/body_inertia_jacobian.hpp"
#include "model/static_problem.hpp"
#include "model_test_support.hpp"
#include "rigid_rotation.hpp"
#include "solvers/problem.hpp"
#include "core/dense_eigen.hpp"

namespace drillflex::model {
namespace inertia_test {

using testing::RodInput;

// Sizes of a random state: frame translation (m), modal coordinates (√kg·m), linear velocity (m/s),
// angular velocity (rad/s), modal rates, linear and angular accelerations, modal accelerations.
struct StateSizes {
  double eta = 0.05, rdot = 1.0, omega = 8.0, eta_rate = 0.5, acceleration = 20.0, angular = 30.0, eta_acc = 5.0;
};

// Random positions with arbitrary (large) body rotations, and random velocities and accelerations.
struct RandomState {
  VecX q, v, a;
};

RandomState MakeRandomState(const SystemModel& model, std::mt19937& rng, const StateSizes& sizes) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RandomState s;
  s.q = model.ReferencePositions();
  s.v = VecX::Zero(model.num_velocities());
  s.a = VecX::Zero(model.num_velocities());
  for (const Body& body : model.bodies()) {
    const int qo = body.q_offset, vo = body.v_offset, nf = body.flexible_count;
    const Quat rotation = so3::QuatFromRotationVector(3.0 * Vec3(u(rng), u(rng), u(rng)));
    s.q.segment<3>(qo) += Vec3(u(rng), u(rng), u(rng));
    s.q.segment<4>(qo + 3) << rotation.w(), rotation.x(), rotation.y(), rotation.z();
    for (int j = 0; j < nf; ++j) s.q[qo + 7 + j] = sizes.eta * u(rng);
    for (int j = 0; j < 3; ++j) {
      s.v[vo + j] = sizes.rdot * u(rng);
      s.v[vo + 3 + j] = sizes.omega * u(rng);
      s.a[vo + j] = sizes.acceleration * u(rng);
      s.a[vo + 3 + j] = sizes.angular * u(rng);
    }
    for (int j = 0; j < nf; ++j) {
      s.v[vo + 6 + j] = sizes.eta_rate * u(rng);
      s.a[vo + 6 + j] = sizes.eta_acc * u(rng);
    }
  }
  return s;
}

// The inertial residual Σ_b (M a + Q_v) of a model's bodies alone, with the analytic Jacobians.
class InertiaProblem : public solvers::Problem {
 public:
  explicit InertiaProblem(const SystemModel& model) : model_(model) {}
  Index num_positions() const override { return model_.num_positions(); }
  Index num_velocities() const override { return model_.num_velocities(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.Increment(q, dv); }
  VecX Residual(double, const VecX& q, const VecX& v, const VecX& a) const override {
    VecX residual = VecX::Zero(num_velocities());
    for (const Body& body : model_.bodies()) {
      const int n = body.velocity_count();
      residual.segment(body.v_offset, n) =
          BodyInertialForces(body, PoseOf(body, q), v.segment(body.v_offset, n), a.segment(body.v_offset, n));
    }
    return residual;
  }
  SparseMat IterationMatrix(double, const VecX& q, const VecX& v, const VecX& a, double cK, double cD,
                            double cM) const override {
    MatX matrix = MatX::Zero(num_velocities(), num_velocities());
    for (const Body& body : model_.bodies()) {
      const int n = body.velocity_count();
      MatX local = MatX::Zero(n, n);
      AddInertiaMatrices(body, PoseOf(body, q), v.segment(body.v_offset, n), a.segment(body.v_offset, n), cK, cD,
                         cM, local);
      matrix.block(body.v_offset, body.v_offset, n, n) = local;
    }
    return matrix.sparseView();
  }

 private:
  const SystemModel& model_;
};

// The part of the model's residual that the motion adds: R(q, v, a) − R(q, 0, 0), and its matrices
// through SystemModel::IterationMatrix: the moving one minus the stiffness at rest (R(q, 0, 0)
// depends on neither v nor a).
class MotionPartProblem : public solvers::Problem {
 public:
  explicit MotionPartProblem(const SystemModel& model) : model_(model) {}
  Index num_positions() const override { return model_.num_positions(); }
  Index num_velocities() const override { return model_.num_velocities(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.Increment(q, dv); }
  VecX Residual(double t, const VecX& q, const VecX& v, const VecX& a) const override {
    return model_.Residual(t, q, v, a, 1.0) - model_.Residual(t, q, Zero(), Zero(), 1.0);
  }
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, double cK, double cD,
                            double cM) const override {
    return model_.IterationMatrix(t, q, v, a, 1.0, cK, cD, cM) -
           model_.IterationMatrix(t, q, Zero(), Zero(), 1.0, cK, 0.0, 0.0);
  }

 private:
  VecX Zero() const { return VecX::Zero(num_velocities()); }
  const SystemModel& model_;
};

// Relative errors of K, D and M of `problem` against central differences at a state.
Eigen::Vector3d JacobianErrors(const solvers::Problem& problem, const RandomState& s) {
  Eigen::Vector3d errors;
  for (int part = 0; part < 3; ++part) {
    const double cK = part == 0, cD = part == 1, cM = part == 2;
    const MatX analytic(problem.IterationMatrix(0.0, s.q, s.v, s.a, cK, cD, cM));
    const MatX numeric(solvers::FiniteDifferenceIterationMatrix(problem, 0.0, s.q, s.v, s.a, cK, cD, cM, 1e-6));
    errors[part] = solvers::RelativeMatrixError(analytic, numeric);
  }
  return errors;
}

struct MassVariant {
  const char* name;
  fe::MassKind mass;
  double lateral_mass = 0.0;  // fluid-like lateral node mass, fraction of the structural node mass
};

class InertiaJacobianTest : public ::testing::TestWithParam<MassVariant> {};

ModelInput VariantInput(const MassVariant& variant, int bodies) {
  ModelInput input = RodInput(bodies, 5, 4);
  input.settings.mass = variant.mass;
  return input;
}

// The bodies of `model` alone (no force elements), with a lateral node mass added (the added mass
// of a fluid moves with the body sideways only: an anisotropic M_k = diag(m, m + m_l, m + m_l)).
SystemModel BodiesWithLateralMass(const SystemModel& model, double fraction) {
  std::vector<Body> bodies = model.bodies();
  for (Body& body : bodies) {
    auto reduced = std::make_shared<cms::ReducedBody>(*body.reduced);
    for (int k = 0; k < reduced->node_count(); ++k) reduced->node_lateral_mass[k] = fraction * reduced->node_mass[k];
    body.reduced = reduced;
    body.reference_mass = cms::NodalReferenceMassMatrix(*reduced) + body.mass_correction;
  }
  return SystemModel(std::move(bodies), {}, model.length());
}

// K_in, D_in and M of the bodies' inertial residual alone: the derivatives of exactly what
// BodyMassMatrix and BodyVelocityForces compute.
TEST_P(InertiaJacobianTest, InertialResidualMatchesCentralDifferences) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(VariantInput(GetParam(), 3), cache);
  const SystemModel model = BodiesWithLateralMass(built.system, GetParam().lateral_mass);
  const InertiaProblem problem(model);
  std::mt19937 rng(11);
  for (int trial = 0; trial < 4; ++trial) {
    const RandomState s = MakeRandomState(model, rng, StateSizes{});
    const Eigen::Vector3d errors = JacobianErrors(problem, s);
    std::printf("%s trial %d: relative errors K_in %.2e  D_in %.2e  M %.2e\n", GetParam().name, trial, errors[0],
                errors[1], errors[2]);
    EXPECT_LT(errors[0], 1e-6);
    EXPECT_LT(errors[1], 1e-6);
    EXPECT_LT(errors[2], 1e-6);
  }
}

// The Jacobians that can fail independently: a state with only acceleration (K_in from M(q) a
// alone) and one with only velocity (K_in and D_in from Q_v alone) must each be right.
TEST_P(InertiaJacobianTest, AccelerationAndVelocityPartsSeparately) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(VariantInput(GetParam(), 2), cache);
  const SystemModel model = BodiesWithLateralMass(built.system, GetParam().lateral_mass);
  const InertiaProblem problem(model);
  std::mt19937 rng(5);
  RandomState accelerating = MakeRandomState(model, rng, StateSizes{});
  accelerating.v.setZero();
  RandomState moving = MakeRandomState(model, rng, StateSizes{});
  moving.a.setZero();
  const Eigen::Vector3d acc = JacobianErrors(problem, accelerating);
  const Eigen::Vector3d vel = JacobianErrors(problem, moving);
  std::printf("%s: a only: K_in %.2e M %.2e;  v only: K_in %.2e D_in %.2e\n", GetParam().name, acc[0], acc[2],
              vel[0], vel[1]);
  EXPECT_LT(acc[0], 1e-6);
  EXPECT_LT(acc[2], 1e-6);
  EXPECT_LT(vel[0], 1e-6);
  EXPECT_LT(vel[1], 1e-6);
  // At rest with a = 0 the inertia adds nothing to K and D.
  const MatX at_rest(problem.IterationMatrix(0.0, accelerating.q, moving.a, moving.a, 1.0, 1.0, 0.0));
  EXPECT_EQ(at_rest.norm(), 0.0);
}

// BodyInertialForces sums the nodes' inertial forces without forming M(q): it must equal
// M(q) a + Q_v(q, v) from BodyMassMatrix and BodyVelocityForces to round-off.
TEST_P(InertiaJacobianTest, NodeSumEqualsMassMatrixTimesAccelerationPlusVelocityForces) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(VariantInput(GetParam(), 3), cache);
  const SystemModel model = BodiesWithLateralMass(built.system, GetParam().lateral_mass);
  std::mt19937 rng(29);
  for (int trial = 0; trial < 3; ++trial) {
    const RandomState s = MakeRandomState(model, rng, StateSizes{});
    for (const Body& body : model.bodies()) {
      const int n = body.velocity_count();
      const BodyPose pose = PoseOf(body, s.q);
      const VecX v = s.v.segment(body.v_offset, n), a = s.a.segment(body.v_offset, n);
      const VecX expected = BodyMassMatrix(body, pose) * a + BodyVelocityForces(body, pose, v);
      EXPECT_LT((BodyInertialForces(body, pose, v, a) - expected).norm(), 1e-12 * expected.norm());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Model, InertiaJacobianTest,
                         ::testing::Values(MassVariant{"consistent", fe::MassKind::kConsistent, 0.0},
                                           MassVariant{"lumped", fe::MassKind::kLumped, 0.0},
                                           MassVariant{"consistent_lateral_mass", fe::MassKind::kConsistent, 0.6}),
                         [](const auto& info) { return std::string(info.param.name); });

// Through SystemModel::IterationMatrix and the model's full residual: one free body (no springs,
// so every term's position derivative is exact) with gravity and loads, moving and accelerating.
TEST(InertiaModel, FreeBodyFullResidualMatchesCentralDifferences) {
  ModelInput input = RodInput(1, 10, 6);
  input.gravity = 9.81;
  Load tip;
  tip.at = 5.08;
  tip.force = Vec3(-300.0, 200.0, 100.0);
  tip.moment = Vec3(10.0, -20.0, 5.0);
  input.loads = {tip};
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(input, cache);
  StaticModelProblem full(built.system);
  const MotionPartProblem motion(built.system);
  std::mt19937 rng(3);
  StateSizes sizes;
  sizes.eta = 1e-3;  // keep K_ff η (ω_j² up to ~1e9) from swamping the differences with round-off
  for (int trial = 0; trial < 3; ++trial) {
    const RandomState s = MakeRandomState(built.system, rng, sizes);
    const Eigen::Vector3d full_errors = JacobianErrors(full, s);
    const Eigen::Vector3d motion_errors = JacobianErrors(motion, s);
    std::printf("free body trial %d: full K %.2e D %.2e M %.2e; motion part K %.2e D %.2e\n", trial, full_errors[0],
                full_errors[1], full_errors[2], motion_errors[0], motion_errors[1]);
    EXPECT_LT(full_errors.maxCoeff(), 1e-6);
    EXPECT_LT(motion_errors[0], 1e-6);
    EXPECT_LT(motion_errors[1], 1e-6);
  }
}

// Several bodies joined by couplings. The springs leave the position derivative of their damping
// force C B(q) v out of the tangent (model/spring_elements.cpp), so K is exact only at v = 0: check
// K with accelerations only, and D and M with velocities too.
TEST(InertiaModel, CoupledStringMatchesCentralDifferences) {
  ModelInput input = RodInput(3, 4, 5);
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(input, cache);
  const MotionPartProblem motion(built.system);
  std::mt19937 rng(17);
  RandomState s = MakeRandomState(built.system, rng, StateSizes{});
  // A large rigid rotation of the unstrained string, slightly perturbed: the stiff springs
  // (k ~ 1e11) stay nearly unstrained, so their forces do not swamp the differences with round-off.
  const VecX turned = testing::RotateRigidly(built.system, built.system.ReferencePositions(),
                                             so3::ExpMap(Vec3(0.9, -2.1, 1.4)));
  VecX dv = 1e-7 * VecX::Random(built.system.num_velocities());
  s.q = built.system.Increment(turned, dv);
  RandomState accelerating = s;
  accelerating.v.setZero();
  const Eigen::Vector3d acc = JacobianErrors(motion, accelerating);
  const Eigen::Vector3d all = JacobianErrors(motion, s);
  std::printf("coupled string: a only K %.2e M %.2e; moving D %.2e M %.2e\n", acc[0], acc[2], all[1], all[2]);
  EXPECT_LT(acc[0], 1e-6);
  EXPECT_LT(acc[2], 1e-6);
  EXPECT_LT(all[1], 1e-6);
  EXPECT_LT(all[2], 1e-6);
}

// M(q) is symmetric positive definite at arbitrary orientations and deformations.
// The lumped node sum is a sum of squares, definite at any η. With a consistent FE mass the constant
// correction C (exact at η = 0) is not: M(q) loses definiteness at large modal displacements
// (measured on these 1.7 m V1 bodies: single modes of ~6–11 cm, random mixes of ~4–13 cm, i.e. a few
// per cent of the body length; the margin is the small polar inertia). It is checked here at
// displacements of up to ~2 cm.
TEST(InertiaModel, MassMatrixSymmetricPositiveDefinite) {
  for (const auto& [variant, eta] : {std::pair{MassVariant{"consistent", fe::MassKind::kConsistent}, 0.02},
                                     std::pair{MassVariant{"lumped", fe::MassKind::kLumped}, 0.5}}) {
    cms::ReductionCache cache;
    const BuiltModel built = BuildSystemModel(VariantInput(variant, 3), cache);
    std::mt19937 rng(23);
    StateSizes sizes;
    sizes.eta = eta;
    for (int trial = 0; trial < 5; ++trial) {
      const RandomState s = MakeRandomState(built.system, rng, sizes);
      const MatX mass(built.system.MassMatrix(s.q));
      EXPECT_LT((mass - mass.transpose()).norm(), 1e-13 * mass.norm());
      const Eigen::LLT<MatX> cholesky(mass);
      EXPECT_EQ(cholesky.info(), Eigen::Success);
      const VecX eigenvalues = SymmetricEigen(mass, false).values;
      const double smallest = eigenvalues.minCoeff();
      double displacement = 0.0;  // largest elastic node displacement |Φ_k η|, m
      for (const Body& body : built.system.bodies()) {
        const BodyPose pose = PoseOf(body, s.q);
        for (int k = 0; k < body.node_count(); ++k) {
          displacement = std::max(displacement, (body.reduced->node_translation_modes[k] * pose.eta).norm());
        }
      }
      std::printf("%s trial %d: eigenvalues of M in [%.3e, %.3e], node displacements up to %.3f m\n", variant.name,
                  trial, smallest, eigenvalues.maxCoeff(), displacement);
      EXPECT_GT(smallest, 0.0);
    }
  }
}

// Power balance of a free body: with T = ½ vᵀ M(q) v, the velocity-quadratic forces satisfy
// vᵀ Q_v = ½ vᵀ Ṁ v (Ṁ along q̇ = v) — the gyroscopic and Coriolis terms do no work (Kane's
// equations of a lumped, isotropic node mass). The consistency correction C has its quadratic terms
// neglected, which leaves exactly ½ vᵀṀv − vᵀQ_v = (Ẇv)ᵀ C W v = (−ω × Aᵀṙ)ᵀ (C w)_t,
// w = (Aᵀṙ, ω, η̇): zero for a lumped FE mass (C = 0), checked as stated for a consistent one.
TEST(InertiaModel, GyroscopicForcesDoNoWork) {
  for (fe::MassKind kind : {fe::MassKind::kLumped, fe::MassKind::kConsistent}) {
    ModelInput input = RodInput(1, 10, 6);
    input.settings.mass = kind;
    cms::ReductionCache cache;
    const BuiltModel built = BuildSystemModel(input, cache);
    const SystemModel& model = built.system;
    const Body& body = model.bodies()[0];
    std::mt19937 rng(29);
    for (int trial = 0; trial < 3; ++trial) {
      const RandomState s = MakeRandomState(model, rng, StateSizes{});
      const BodyPose pose = PoseOf(body, s.q);
      const double power = s.v.dot(BodyVelocityForces(body, pose, s.v));
      // ½ d/dt (vᵀ M(q(t)) v) at fixed v along q(t) = q ⊕ t v, central differences (error O(h²)).
      const double h = 1e-5;
      auto kinetic_twice = [&](double t) {
        return s.v.dot(BodyMassMatrix(body, PoseOf(body, model.Increment(s.q, t * s.v))) * s.v);
      };
      const double rate = 0.25 * (kinetic_twice(h) - kinetic_twice(-h)) / h;
      VecX w = s.v;
      w.head<3>() = pose.A.transpose() * s.v.head<3>();
      const Vec3 frame_rate = -s.v.segment<3>(3).cross(w.head<3>());  // d(Aᵀ)/dt ṙ
      const double neglected = frame_rate.dot(body.mass_correction.topRows<3>() * w);
      const double error = std::abs(rate - power - neglected) / std::abs(power);
      std::printf("%s trial %d: vᵀQ_v = %.6e W, ½vᵀṀv = %.6e W, neglected C part %.3e W, error %.2e\n",
                  kind == fe::MassKind::kLumped ? "lumped" : "consistent", trial, power, rate, neglected, error);
      EXPECT_GT(std::abs(power), 1.0);  // the check is not vacuous
      EXPECT_LT(error, 1e-7);
      if (kind == fe::MassKind::kLumped) {
        EXPECT_LT(std::abs(neglected), 1e-10 * std::abs(power));
      }
    }
  }
}

}  // namespace inertia_test
}  // namespace drillflex::model
