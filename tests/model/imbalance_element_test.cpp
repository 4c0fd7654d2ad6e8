// The imbalance (model/imbalance_element.hpp): on a body spinning at Ω about its axis the force is
// m e Ω² along the offset, turning with the body; its analytic stiffness and damping match central
// differences of its own residual at a spun, bent and moving state.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "element_problem.hpp"
#include "model/imbalance_element.hpp"
#include "model_test_support.hpp"

namespace drillflex::model {
namespace imbalance_element_test {

constexpr double kImbalance = 0.05;  // kg·m

// The V1 rod with an imbalance at mid-length (a node of the lower body's top: s = 2.54 m).
BuiltModel RodWithImbalance(cms::ReductionCache& cache) {
  ModelInput input = testing::RodInput(2, 4, 5);
  input.imbalances.push_back({2.54, kImbalance});
  return BuildSystemModel(input, cache);
}

int ImbalanceIndex(const SystemModel& model) {
  for (std::size_t i = 0; i < model.elements().size(); ++i) {
    if (dynamic_cast<const ImbalanceElement*>(model.elements()[i].get()) != nullptr) return static_cast<int>(i);
  }
  return -1;
}

// Every body turned rigidly by `angle` about the string axis and spinning at `rate` about it:
// the centrifugal force m e Ω² points along the offset's direction, turned by the same angle.
TEST(ImbalanceElement, CentrifugalForceMeOmegaSquaredAlongTheTurnedOffset) {
  cms::ReductionCache cache;
  const BuiltModel built = RodWithImbalance(cache);
  const SystemModel& model = built.system;
  const int index = ImbalanceIndex(model);
  ASSERT_GE(index, 0);
  const auto& element = static_cast<const ImbalanceElement&>(*model.elements()[index]);
  const testing::ElementProblem problem(model, index);
  for (const double angle : {0.0, 0.7, 2.0 * kPi * 123.4}) {
    for (const double rate : {10.0, -31.4}) {
      VecX dv = VecX::Zero(model.num_velocities()), v = VecX::Zero(model.num_velocities());
      for (const Body& body : model.bodies()) {
        dv[body.v_offset + 3] = angle;
        v[body.v_offset + 3] = rate;
      }
      const VecX q = model.Increment(model.ReferencePositions(), dv);
      const Vec3 force = element.Force(problem.State(0.0, q, v));
      // The offset e_z turned about x by the angle: (0, −sin, cos) in the (global = string) frame.
      const Vec3 expected = kImbalance * rate * rate * Vec3(0.0, -std::sin(angle), std::cos(angle));
      EXPECT_LT((force - expected).norm(), 1e-12 * expected.norm()) << "angle " << angle << ", rate " << rate;
      // The residual takes −F at the node: on the body's translation rows, summed over both bodies.
      const VecX residual = problem.Residual(0.0, q, v, v);
      Vec3 translation = Vec3::Zero();
      for (const Body& body : model.bodies()) translation += residual.segment<3>(body.v_offset);
      EXPECT_LT((translation + expected).norm(), 1e-12 * expected.norm());
    }
  }
  // At rest nothing.
  const VecX rest = model.ReferencePositions();
  EXPECT_EQ(element.Force(problem.State(0.0, rest, VecX::Zero(model.num_velocities()))).norm(), 0.0);
}

TEST(ImbalanceElement, JacobiansMatchCentralDifferences) {
  cms::ReductionCache cache;
  const BuiltModel built = RodWithImbalance(cache);
  const int index = ImbalanceIndex(built.system);
  const testing::ElementProblem problem(built.system, index);
  std::mt19937 rng(31);
  // Spun 40 rad, bent and displaced by 0.05, moving at 0.5 about a 12 rad/s spin: every term
  // (ω_k's lateral parts, the offset's turn, the modal rows) is visible.
  const VecX q = testing::SpunPositions(built.system, 40.0, 0.05, rng);
  const VecX v = testing::SpinningVelocities(built.system, 12.0, 0.5, rng);
  const testing::Errors errors = testing::JacobianErrors(problem, 0.0, q, v);
  std::printf("[ measure  ] imbalance: stiffness %.2e, damping %.2e\n", errors.stiffness, errors.damping);
  EXPECT_LT(errors.stiffness, 1e-6);
  EXPECT_LT(errors.damping, 1e-6);
}

}  // namespace imbalance_element_test
}  // namespace drillflex::model
