// solvers::ColumnRuns against Eigen's sparse product: the same vector to the last bit, for a
// pattern of dense runs with gaps and empty columns, and a refused shape.
#include "solvers/column_runs.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/error.hpp"

namespace drillflex::solvers {
namespace column_runs_test {

TEST(ColumnRuns, MultipliesAsEigensSparseProductToTheLastBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  MatX dense = MatX::Zero(40, 30);
  for (int j = 0; j < 30; ++j) {
    if (j % 7 == 3) continue;  // an empty column
    for (int i = 0; i < 40; ++i) {
      if ((i / 5 + j) % 3 != 0) dense(i, j) = 1e6 * uniform(rng);  // runs of 5 rows with gaps
    }
  }
  const SparseMat a = dense.sparseView(0.0, 0.0);
  VecX x(30);
  for (int j = 0; j < 30; ++j) x[j] = uniform(rng);
  ColumnRuns runs;
  runs.Analyze(a);
  const VecX expected = a * x;
  EXPECT_EQ(runs.Multiply(a, x), expected);
  EXPECT_THROW(runs.Multiply(SparseMat(dense.topRows(39).sparseView()), x), LogicError);
}

}  // namespace column_runs_test
}  // namespace drillflex::solvers
