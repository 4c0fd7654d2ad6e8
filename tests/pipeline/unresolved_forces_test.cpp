// A static solve never reports a state that does not balance the loads as an equilibrium. Three
// collars of 0.1 mm (a length typed in the wrong unit) under 45 m of pipe in a straight 30° hole:
// couplings of c·EA/ℓ ~ 1e16 N/m, so that the solver's last steps (below 1e-10 m) still move
// 1e7 N, 2 000 times the string's weight. That stop must fail with a message naming the shortest
// body, not pass as "converged" with its reactions of meganewtons. The same string with collars of
// 5 cm balances: the top carries W cos I (no fluid; the bit holds the string sideways only).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/case.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {
namespace {

constexpr double kSteelDensity = 7850.0;  // kg/m³ (fe/material.hpp built-in steel)
constexpr double kGravity = 9.81;         // m/s² (the case's default with a well)

io::Case ShortCollars(double collar_length) {
  return io::ParseCase(fmt::format(R"(name: short collars
units: SI
well:
  survey: [[0, 30, 0], [100, 30, 0]]
  hole: 0.2159
  bit_md: 90
string:
  - {{type: collar, od: 0.1715, id: 0.0714, length: {}, count: 3}}
  - {{type: pipe, od: 0.127, id: 0.1086, length: 9, count: 5}}
)",
                                   collar_length),
                       "short.yaml");
}

double TubeWeight(double od, double id) { return kGravity * kSteelDensity * kPi / 4.0 * (od * od - id * id); }

TEST(UnresolvedForces, CollarsOfATenthOfAMillimetreAreASolverErrorNamingTheShortestBody) {
  try {
    RunCase(ShortCollars(1e-4), AnalysisRequest::Only(Analysis::Static));
    FAIL() << "a static of 0.1 mm collars passed as converged";
  } catch (const SolverError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("forces are not resolved"), std::string::npos) << message;
    EXPECT_NE(message.find("the shortest body, 0.0003 m long"), std::string::npos) << message;
  }
}

TEST(UnresolvedForces, CollarsOfFiveCentimetresBalanceTheWeight) {
  const CaseResults results = RunCase(ShortCollars(0.05), AnalysisRequest::Only(Analysis::Static));
  ASSERT_TRUE(results.static_result);
  const analyses::StaticResult& equilibrium = *results.static_result;
  EXPECT_TRUE(equilibrium.converged);
  EXPECT_LT(equilibrium.residual_norm, 1e-3 * results.model.built.system.force_scale());
  const double inclination = 30.0 * kPi / 180.0;
  const double weight = TubeWeight(0.1715, 0.0714) * 0.15 + TubeWeight(0.127, 0.1086) * 45.0;
  const double top = equilibrium.reactions.back().force.x();  // along the string, up-hole
  std::printf("[ measure  ] 5 cm collars: the top carries %.6f N against W cos I = %.6f N (%+.2e)\n", top,
              weight * std::cos(inclination), top / (weight * std::cos(inclination)) - 1.0);
  EXPECT_NEAR(top, weight * std::cos(inclination), 1e-4 * weight);
}

}  // namespace
}  // namespace drillflex::pipeline
