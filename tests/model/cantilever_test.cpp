// The V1 cantilever of validation.md through the model layer: static deflections and natural
// frequencies against Euler–Bernoulli theory, with the paper's model (4 bodies × 10 elements,
// 12 fixed-interface... 6 + H flexible coordinates).
#include <gtest/gtest.h>

#include <cmath>

#include "model/static_problem.hpp"
#include "model_test_support.hpp"
#include "solvers/eigen.hpp"
#include "solvers/newton.hpp"

namespace drillflex::model {
namespace cantilever_test {

constexpr double kLength = 5.08, kDiameter = 0.0762, kE = 2.1e11, kRho = 7800.0;
const double kI = kPi * std::pow(kDiameter, 4) / 64.0;
const double kA = kPi * kDiameter * kDiameter / 4.0;

ModelInput Cantilever(double coupling_factor) {
  ModelInput input = testing::RodInput(4, 10, 6, coupling_factor);
  input.settings.rotary_inertia = false;  // the Euler–Bernoulli reference has none
  Support root;
  root.at = 0.0;
  root.fixed.fill(true);
  input.supports = {root};
  return input;
}

double TipDeflection(const ModelInput& input) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(input, cache);
  StaticModelProblem problem(built.system);
  solvers::NewtonOptions options;
  options.increment_tolerance = 1e-10;
  options.line_search.enabled = false;
  const auto result = solvers::SolveStatic(problem, built.system.ReferencePositions(), options);
  const auto poses = built.system.Poses(result.q);
  const Body& last = built.system.bodies().back();
  return poses.back().NodePosition(last, last.node_count() - 1).y();
}

TEST(Cantilever, TipForceDeflection) {
  for (double factor : {100.0, 1000.0}) {
    ModelInput input = Cantilever(factor);
    Load tip;
    tip.at = kLength;
    tip.force = Vec3(0.0, 100.0, 0.0);  // linear range: tip rotation 4e-3 rad
    input.loads = {tip};
    const double exact = 100.0 * std::pow(kLength, 3) / (3.0 * kE * kI);
    const double error = TipDeflection(input) / exact - 1.0;
    std::printf("coupling factor %g: tip-force deflection error %.4f %%\n", factor, 100 * error);
    if (factor >= 1000.0) {
      EXPECT_LT(std::abs(error), 5e-4);
    }
  }
}

TEST(Cantilever, Frequencies) {
  // Euler–Bernoulli cantilever: f_n = (β_n L)² / (2π L²) sqrt(EI / ρA).
  const double beta[4] = {1.8751041, 4.6940911, 7.8547574, 10.995541};
  VecX softer;  // the frequencies with the softer couplings
  for (double factor : {100.0, 1000.0}) {
    ModelInput input = Cantilever(factor);
    input.settings.modes_per_body = 6;
    cms::ReductionCache cache;
    const BuiltModel built = BuildSystemModel(input, cache);
    const VecX q = built.system.ReferencePositions();
    const VecX zero = VecX::Zero(built.system.num_velocities());
    const SparseMat stiffness = built.system.IterationMatrix(0.0, q, zero, zero, 1.0, 1.0, 0.0, 0.0);
    const SparseMat mass = built.system.MassMatrix(q);
    const VecX hz = solvers::FrequenciesHz(solvers::SolveModes(stiffness, mass, 8).eigenvalues);
    ASSERT_EQ(built.system.num_velocities(), 72);
    for (int n = 0; n < 4; ++n) {
      const double exact = beta[n] * beta[n] / (2 * kPi * kLength * kLength) * std::sqrt(kE * kI / (kRho * kA));
      std::printf("coupling factor %g, mode %d: exact %.5f Hz, error %.4f %%\n", factor, n + 1, exact,
                  100 * (hz[2 * n] / exact - 1));
      // A round rod bends alike in y and z: both members of each pair.
      EXPECT_NEAR(hz[2 * n + 1], hz[2 * n], 1e-6 * hz[2 * n]);
      if (factor >= 1000.0) {
        EXPECT_LT(std::abs(hz[2 * n] / exact - 1.0), 5e-4) << "mode " << n + 1;
        // The couplings' compliance only lowers frequencies: stiffer couplings raise them.
        EXPECT_GT(hz[2 * n], softer[2 * n]) << "mode " << n + 1;
      }
    }
    softer = hz;
  }
}

}  // namespace cantilever_test
}  // namespace drillflex::model
