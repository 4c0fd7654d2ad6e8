// NodalLoadElement's residual, summed without the node loop (products with the rotation's entries
// set up once, nodal_loads.hpp), against the node loop its matrices are evaluated with: the same
// generalized force for a turned, bent body under forces and moments at every node.
#include "model/nodal_loads.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "cms/reduction_cache.hpp"
#include "model/builder.hpp"
#include "model_test_support.hpp"

namespace drillflex::model {
namespace {

TEST(NodalLoadElement, ResidualWithoutTheNodeLoopIsTheNodeSum) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(2, 10, 6), cache);
  const SystemModel& model = built.system;
  const Body& body = model.bodies()[1];
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> forces, moments;
  for (int k = 0; k < body.node_count(); ++k) {
    forces.emplace_back(1e3 * u(rng), 1e3 * u(rng), 1e3 * u(rng));
    moments.emplace_back(1e2 * u(rng), 1e2 * u(rng), 1e2 * u(rng));
  }
  const NodalLoadElement loads(&body, forces, moments);
  // Turned by ~1 rad about a random axis and bent (modal coordinates 1e-3 of the body's 1 m scale).
  const VecX q = testing::PerturbedPositions(model, rng, 1.0);
  const auto poses = model.Poses(q);
  ASSERT_GT(poses[1].eta.norm(), 1e-5);
  const ElementState state = model.StateOf(loads, poses, VecX::Zero(model.num_velocities()), 0.0, 0.7);
  ElementContribution summed, looped;
  loads.Evaluate(state, false, summed);
  loads.Evaluate(state, true, looped);
  ASSERT_EQ(summed.force.size(), looped.force.size());
  // Round-off of sums of ~1e3 N terms: 1e-12 of the largest.
  const double scale = looped.force.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 1e2);
  EXPECT_LT((summed.force - looped.force).cwiseAbs().maxCoeff(), 1e-12 * scale)
      << "summed " << summed.force.transpose() << "\nlooped " << looped.force.transpose();
}

}  // namespace
}  // namespace drillflex::model
