// SystemModel's assembly on OpenMP threads (model/system_model.cpp): the residual and the iteration
// matrix of a 48-body string at a moving, accelerating state are bit for bit the same on 1 and on 2
// threads (each body's and element's part is computed on its own, then summed in a fixed order).
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include <fmt/format.h>

#include "model_test_support.hpp"

namespace drillflex::model {
namespace system_model_test {

TEST(SystemModelThreads, ResidualAndIterationMatrixIdenticalOnOneAndTwoThreads) {
  ModelInput input = testing::RodInput(48, 4, 4);
  input.gravity = 9.81;
  Support root;
  root.fixed.fill(true);
  input.supports = {root};
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(input, cache);
  ASSERT_GE(built.system.bodies().size(), 32u);  // large enough to run in parallel
  std::mt19937 rng(13);
  const VecX q = testing::PerturbedPositions(built.system, rng, 1e-3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX v(built.system.num_velocities()), a(built.system.num_velocities());
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = 0.1 * u(rng), a[i] = 10.0 * u(rng);
  const int threads = omp_get_max_threads();
  auto evaluate = [&](int count, VecX& residual, SparseMat& matrix) {
    omp_set_num_threads(count);
    residual = built.system.Residual(0.3, q, v, a, 1.0);
    matrix = built.system.IterationMatrix(0.3, q, v, a, 1.0, 1.0, 2e3, 4e6);
  };
  VecX r1, r2;
  SparseMat m1, m2;
  evaluate(1, r1, m1);
  evaluate(2, r2, m2);
  omp_set_num_threads(threads);
  ASSERT_EQ(r1.size(), r2.size());
  EXPECT_TRUE((r1.array() == r2.array()).all());
  EXPECT_GT(r1.norm(), 0.0);
  ASSERT_EQ(m1.nonZeros(), m2.nonZeros());
  for (Eigen::Index k = 0; k < m1.nonZeros(); ++k) ASSERT_EQ(m1.valuePtr()[k], m2.valuePtr()[k]) << "entry " << k;
}

// Solver messages say where a residual row sits: the body, its span from the bit, the coordinate.
TEST(SystemModel, DescribeCoordinateNamesTheBodyAndTheCoordinate) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(2, 4, 3), cache);
  const Body& upper = built.system.bodies()[1];
  EXPECT_EQ(built.system.DescribeCoordinate(upper.v_offset + 4), "body 1 (2.54–5.08 m from the bit), frame rotation y");
  EXPECT_EQ(built.system.DescribeCoordinate(upper.v_offset + 6 + 2), "body 1 (2.54–5.08 m from the bit), mode 3");
  EXPECT_EQ(built.system.DescribeCoordinate(1), "body 0 (0.00–2.54 m from the bit), frame translation y");
  EXPECT_EQ(built.system.DescribeCoordinate(built.system.num_velocities()), fmt::format("coordinate {}", built.system.num_velocities()));
}

}  // namespace system_model_test
}  // namespace drillflex::model
