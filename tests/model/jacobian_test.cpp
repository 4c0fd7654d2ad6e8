// Every force element's and the elastic forces' analytic Jacobians against central differences
// of the model's own residual (solvers::FiniteDifferenceIterationMatrix).
#include <gtest/gtest.h>

#include "model/body_dynamics.hpp"
#include "model/static_problem.hpp"
#include "model_test_support.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {
namespace jacobian_test {

using testing::PerturbedPositions;
using testing::RodInput;

struct Scenario {
  const char* name;
  bool supports;
  bool loads;
  double gravity;
};

class JacobianTest : public ::testing::TestWithParam<Scenario> {};

TEST_P(JacobianTest, StiffnessMatchesCentralDifferences) {
  const Scenario scenario = GetParam();
  ModelInput input = RodInput(3, 4, 5);
  input.gravity = scenario.gravity;
  if (scenario.supports) {
    Support root;
    root.at = 0.0;
    root.fixed.fill(true);
    Support pin;
    pin.at = 5.08;
    pin.fixed = {false, true, true, false, false, false};
    input.supports = {root, pin};
  }
  if (scenario.loads) {
    Load tip;
    tip.at = 5.08;
    tip.force = Vec3(-2000.0, 500.0, 300.0);
    tip.moment = Vec3(50.0, -20.0, 70.0);
    Load line;
    line.distributed = true;
    line.from = 1.0;
    line.to = 4.2;
    line.force_per_length = Vec3(10.0, -300.0, 200.0);
    line.moment_per_length = Vec3(5.0, 1.0, -2.0);
    input.loads = {tip, line};
  }
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(input, cache);
  StaticModelProblem problem(built.system);
  problem.SetLoadFactor(0.7);
  std::mt19937 rng(42);
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = PerturbedPositions(built.system, rng, 0.05);
    const VecX zero = VecX::Zero(built.system.num_velocities());
    const SparseMat analytic = problem.IterationMatrix(0.0, q, zero, zero, 1.0, 0.0, 0.0);
    const SparseMat numeric = solvers::FiniteDifferenceIterationMatrix(problem, 0.0, q, zero, zero, 1.0, 0.0, 0.0, 1e-6);
    EXPECT_LT(solvers::RelativeMatrixError(MatX(analytic), MatX(numeric)), 1e-6) << scenario.name << " trial " << trial;
  }
}

TEST_P(JacobianTest, DampingMatchesCentralDifferences) {
  const Scenario scenario = GetParam();
  ModelInput input = RodInput(3, 4, 5);
  if (scenario.supports) {
    Support root;
    root.at = 0.0;
    root.fixed.fill(true);
    input.supports = {root};
  }
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(input, cache);
  StaticModelProblem problem(built.system);
  std::mt19937 rng(7);
  // Nearly unstrained, so that the finite differences in v are not swamped by round-off of a large
  // static residual (R ~ k·strain with k ~ 1e12 N/m).
  const VecX q = PerturbedPositions(built.system, rng, 1e-8);
  const VecX zero = VecX::Zero(built.system.num_velocities());
  // At rest the damping matrix is ∂R/∂v of the springs and modal damping (Q_v is quadratic in v).
  const SparseMat analytic = problem.IterationMatrix(0.0, q, zero, zero, 0.0, 1.0, 0.0);
  const SparseMat numeric = solvers::FiniteDifferenceIterationMatrix(problem, 0.0, q, zero, zero, 0.0, 1.0, 0.0, 1e-6);
  EXPECT_LT(solvers::RelativeMatrixError(MatX(analytic), MatX(numeric)), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Model, JacobianTest,
                         ::testing::Values(Scenario{"free", false, false, 0.0},
                                           Scenario{"supported", true, false, 0.0},
                                           Scenario{"loaded", true, true, 9.81},
                                           Scenario{"gravity only", false, false, 9.81}),
                         [](const auto& info) {
                           std::string name = info.param.name;
                           for (char& c : name) if (c == ' ') c = '_';
                           return name;
                         });

}  // namespace jacobian_test
}  // namespace drillflex::model

namespace drillflex::model {
namespace jacobian_test {

// The elastic forces of one body at large modal amplitudes (where the foreshortening term of the
// axial strain matters) against central differences, and the force as the gradient of the energy.
TEST(ElasticForces, HessianAndGradientAtLargeDeflection) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(1, 10, 6), cache);
  const Body& body = built.system.bodies().front();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BodyPose pose = PoseOf(body, built.system.ReferencePositions());
  for (int i = 0; i < pose.eta.size(); ++i) pose.eta[i] = 0.5 * u(rng);  // ~cm-scale deflections
  const int n = body.velocity_count();
  const VecX zero = VecX::Zero(n);
  auto force = [&](const VecX& eta) {
    BodyPose p = pose;
    p.eta = eta;
    VecX r = VecX::Zero(n);
    AddElasticForces(body, p, zero, r);
    return VecX(r.tail(body.flexible_count));
  };
  MatX analytic = MatX::Zero(n, n);
  AddElasticMatrices(body, pose, 1.0, 0.0, analytic);
  const int nf = body.flexible_count;
  MatX numeric(nf, nf);
  VecX gradient(nf);
  const double h = 1e-6;
  for (int j = 0; j < nf; ++j) {
    VecX plus = pose.eta, minus = pose.eta;
    plus[j] += h;
    minus[j] -= h;
    numeric.col(j) = (force(plus) - force(minus)) / (2 * h);
    BodyPose pp = pose, pm = pose;
    pp.eta = plus;
    pm.eta = minus;
    gradient[j] = (BodyElasticEnergy(body, pp) - BodyElasticEnergy(body, pm)) / (2 * h);
  }
  EXPECT_LT((analytic.bottomRightCorner(nf, nf) - numeric).norm() / numeric.norm(), 1e-7);
  EXPECT_LT((gradient - force(pose.eta)).norm() / gradient.norm(), 1e-7);
}

// A body bent by a lateral modal deflection whose axial coordinates relax freely must carry no
// axial force: the foreshortening ½∫v′² is taken up by the end nodes coming together.
TEST(ElasticForces, BentBodyWithFreeAxialEndCarriesNoAxialForce) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(1, 10, 6), cache);
  const Body& body = built.system.bodies().front();
  BodyPose pose = PoseOf(body, built.system.ReferencePositions());
  const int nf = body.flexible_count;
  // Bend the body with every mode that has no axial end motion, then solve the axial force = 0
  // condition along the axial-force row (the elongation direction) by Newton on the scalar N.
  const VecX& row = body.axial_force_row;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < nf; ++i) pose.eta[i] = 0.3 * u(rng);
  pose.eta -= row * (row.dot(pose.eta) / row.squaredNorm());  // no elongation yet
  const double bent_only = BodyAxialForce(body, pose);
  EXPECT_GT(bent_only, 0.0);  // bending alone would stretch the axis: the foreshortening is counted
  for (int it = 0; it < 20; ++it) {
    const double n = BodyAxialForce(body, pose);
    // ∂N/∂α along the row direction at α: row·row + (EA/L) (Gη)·row.
    const VecX direction = row / row.norm();
    const double slope = row.dot(direction) + body.axial_rigidity / body.length() *
                                                 (body.reduced->modal_geometric_stiffness * pose.eta).dot(direction);
    pose.eta -= direction * (n / slope);
  }
  EXPECT_LT(std::abs(BodyAxialForce(body, pose)), 1e-9 * bent_only);
}

}  // namespace jacobian_test
}  // namespace drillflex::model

namespace drillflex::model {
namespace jacobian_test {

// The body's torque (body_dynamics.hpp BodyTorque) of a uniform twist θx′ = τ is GJ τ: the body
// twisted by TwistKeepingShape's elastic twist rate (its modes fitted to θx,k = τ (x_k − x_mid)).
TEST(ElasticForces, UniformTwistCarriesTorqueGJTimesTwistRate) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(1, 10, 6), cache);
  const Body& body = built.system.bodies().front();
  VecX q = built.system.ReferencePositions();
  const double twist_rate = 0.02;  // rad/m
  TwistKeepingShape(body, 0.0, q, twist_rate);
  const BodyPose pose = PoseOf(body, q);
  EXPECT_NEAR(BodyTorque(body, pose), body.torsional_rigidity * twist_rate,
              1e-6 * body.torsional_rigidity * twist_rate);
  EXPECT_NEAR(BodyAxialForce(body, pose), 0.0, 1e-6);  // N: a twist does not stretch it
}

}  // namespace jacobian_test
}  // namespace drillflex::model
