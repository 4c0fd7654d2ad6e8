// Every force element's and the elastic forces' analytic Jacobians against central differences
// of the model's own residual (solvers::FiniteDifferenceIterationMatrix).
#include <gtest/gtest.h>

#include "model/static_problem.hpp"
#include "model_test_support.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {
namespace {

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

}  // namespace
}  // namespace drillflex::model
