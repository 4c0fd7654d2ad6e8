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
namespace nodal_loads_test {

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

}  // namespace nodal_loads_test
}  // namespace drillflex::model

namespace drillflex::model {
namespace nodal_loads_test {

// The axial force's gradient inside a body (nodal_loads.hpp): with random forces at every node (so
// the axial components vary along the body) on a turned, bent body, the element's force and its
// stiffness against central differences along increments (q ⊕ Δ, the rotation in the body frame),
// and the force against the gradient of its potential energy.
TEST(NodalLoadElement, AxialGradientForceAndStiffnessMatchCentralDifferences) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(2, 10, 6), cache);
  const SystemModel& model = built.system;
  const Body& body = model.bodies()[1];
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> forces, moments(body.node_count(), Vec3::Zero());
  for (int k = 0; k < body.node_count(); ++k) forces.emplace_back(1e5 * u(rng), 1e3 * u(rng), 1e3 * u(rng));
  const NodalLoadElement loads(&body, forces, moments);
  const VecX q = testing::PerturbedPositions(model, rng, 0.5);
  const VecX zero = VecX::Zero(model.num_velocities());
  constexpr double kLoadFactor = 0.7;
  auto evaluate = [&](const VecX& at, bool matrices) {
    const auto poses = model.Poses(at);
    ElementContribution out;
    loads.Evaluate(model.StateOf(loads, poses, zero, 0.0, kLoadFactor), matrices, out);
    return out;
  };
  auto energy = [&](const VecX& at) {
    const auto poses = model.Poses(at);
    return loads.PotentialEnergy(model.StateOf(loads, poses, zero, 0.0, kLoadFactor));
  };
  const ElementContribution here = evaluate(q, true);
  const int n = body.velocity_count();
  MatX numeric(n, n);
  VecX gradient(n);
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    VecX step = VecX::Zero(model.num_velocities());
    step[body.v_offset + j] = h;
    const VecX plus = model.Increment(q, step), minus = model.Increment(q, -step);
    numeric.col(j) = (evaluate(plus, false).force - evaluate(minus, false).force) / (2.0 * h);
    gradient[j] = (energy(plus) - energy(minus)) / (2.0 * h);
  }
  EXPECT_LT((here.stiffness - numeric).norm() / numeric.norm(), 1e-6);
  // The potential reports the forces' part exactly; the moments are zero here.
  EXPECT_LT((here.force - gradient).norm() / here.force.norm(), 1e-6);
}

// The gradient's energy is the work of the interior axial loads through the bending's shortening
// (nodal_loads.hpp): a bent body with one axial load a at node k stores −a δ_k,
// δ_k = −½∫₀^{x_k}(v′² + w′²) + (x_k/L) ½∫₀^L(v′² + w′²), the integrals summed element by element
// (each element's U_eᵀ K_G,e U_e, whose sum tests/cms checks against the FE K_G), node by node.
TEST(NodalLoadElement, AxialGradientEnergyIsTheWorkThroughTheShortening) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(1, 10, 6), cache);
  const SystemModel& model = built.system;
  const Body& body = model.bodies()[0];
  const cms::ReducedBody& reduced = *body.reduced;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX q = model.ReferencePositions();
  BodyPose pose = PoseOf(body, q);
  for (int i = 0; i < pose.eta.size(); ++i) pose.eta[i] = 1e-2 * u(rng);
  const int elements = body.node_count() - 1;
  for (int k = 1; k < elements; ++k) {
    const double axial = 1000.0;  // N along the body axis (+x, the reference frame is the identity)
    std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
    forces[k] = Vec3(axial, 0.0, 0.0);
    const NodalLoadElement loads(&body, forces, moments);
    // ∫ over elements below node k and over all of v′² + w′² from the FE element matrices.
    double below = 0.0, total = 0.0;
    for (int e = 0; e < elements; ++e) {
      const double part = pose.eta.dot(reduced.element_modal_geometric_stiffness[e] * pose.eta);
      total += part;
      if (e < k) below += part;
    }
    const double x = reduced.node_positions[k].x() / body.length();
    const double expected = -axial * (-0.5 * below + x * 0.5 * total);
    const std::vector<BodyPose> poses = {pose};
    ElementState state;
    state.poses = {&poses[0]};
    state.velocity = VecX::Zero(body.velocity_count());
    state.parameters.load_factor = 1.0;
    // PotentialEnergy = −F·(r_k − r_k,ref) of the linear modes plus the gradient's energy.
    const Vec3 rest = body.reference_position + reduced.node_positions[k];
    const double linear = -forces[k].dot(pose.NodePosition(body, k) - rest);
    EXPECT_NEAR(loads.PotentialEnergy(state) - linear, expected, 1e-9 * std::abs(axial) * total + 1e-15) << "node " << k;
  }
}

}  // namespace nodal_loads_test
}  // namespace drillflex::model
