// The static Newton solver on toy problems with exact equilibria: quadratic convergence, load
// stepping, line search, and the SolverError when it cannot converge.
#include "solvers/newton.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "toy_problems.hpp"

namespace drillflex::solvers {
namespace newton_test {

using ::testing::HasSubstr;
using ::testing::Not;
using testing::ScalarProblem;
using testing::SpringChain;
using testing::VonMisesTruss;

NewtonOptions PlainNewton() {
  NewtonOptions options;
  options.line_search.enabled = false;
  options.load_stepping.enabled = false;
  return options;
}

// Exact equilibrium of the chain: choose the spring elongation e*, load P = f(e*), q_i = i e*.
VecX ChainEquilibrium(int n, double elongation) {
  return VecX::LinSpaced(n, 1.0, n) * elongation;
}

TEST(SolveStatic, ConvergesQuadraticallyOnANonlinearSpringChain) {
  const int n = 10;
  const double k = 1.0e3, k3 = 1.0e5, elongation = 0.1;  // f(e*) = 100 + 100 N
  SpringChain chain(n, k, k3, k * elongation + k3 * std::pow(elongation, 3));
  const NewtonResult result = SolveStatic(chain, VecX::Zero(n), PlainNewton());
  ASSERT_TRUE(result.converged);
  EXPECT_LT((result.q - ChainEquilibrium(n, elongation)).norm(), 1e-9);
  // Order of convergence p_k = ln(r_{k+1}/r_k) / ln(r_k/r_{k−1}) → 2 for Newton; taken where
  // r_{k+1} is still well above round-off (1e-11 × force scale).
  const std::vector<double>& r = result.residual_history;
  ASSERT_GE(r.size(), 4u);
  int measured = 0;
  for (size_t i = 1; i + 1 < r.size(); ++i) {
    if (r[i + 1] < 1e-11 * result.force_scale || r[i] > 0.1 * result.force_scale) continue;
    const double order = std::log(r[i + 1] / r[i]) / std::log(r[i] / r[i - 1]);
    EXPECT_GT(order, 1.8) << "iteration " << i;
    ++measured;
  }
  EXPECT_GE(measured, 1);
}

TEST(SolveStatic, LoadSteppingReachesFullLoadWherePlainNewtonFails) {
  // A very soft start (k = 1 N/m) and strong hardening: the first Newton step from q = 0
  // overshoots e* by a factor 4e4 and |R| grows 6e13-fold; far from the root the cubic only
  // contracts by 2/3 per iteration, so plain Newton needs 31 iterations (measured, with the
  // divergence check off; with it on, it stops after the first).
  const int n = 5;
  const double k = 1.0, k3 = 1.0e6, elongation = 0.2;
  SpringChain chain(n, k, k3, k * elongation + k3 * std::pow(elongation, 3));
  NewtonOptions plain = PlainNewton();
  plain.max_iterations = 20;
  plain.divergence_factor = std::numeric_limits<double>::infinity();
  try {
    SolveStatic(chain, VecX::Zero(n), plain);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("no convergence within 20 iterations"));
  }
  plain.divergence_factor = NewtonOptions().divergence_factor;
  try {
    SolveStatic(chain, VecX::Zero(n), plain);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("diverging"));
  }

  NewtonOptions stepping = plain;
  stepping.load_stepping.enabled = true;
  stepping.load_stepping.min_step = 1e-6;
  const NewtonResult result = SolveStatic(chain, VecX::Zero(n), stepping);
  ASSERT_TRUE(result.converged);
  EXPECT_EQ(result.load_factor, 1.0);
  EXPECT_GT(result.load_steps, 1);
  EXPECT_GE(result.rejected_steps, 1);
  EXPECT_LT((result.q - ChainEquilibrium(n, elongation)).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(SolveStatic, AnIterationBudgetEndsALongContinuationWithAMessage) {
  // The chain of the test above takes more than 8 iterations in all with load stepping; with a
  // budget of 8 the solve stops, says so, and keeps the last converged load factor.
  const int n = 5;
  const double k = 1.0, k3 = 1.0e6, elongation = 0.2;
  SpringChain chain(n, k, k3, k * elongation + k3 * std::pow(elongation, 3));
  NewtonOptions stepping = PlainNewton();
  stepping.max_iterations = 20;
  stepping.load_stepping.enabled = true;
  stepping.load_stepping.min_step = 1e-6;
  const NewtonResult free_run = SolveStatic(chain, VecX::Zero(n), stepping);
  ASSERT_TRUE(free_run.converged);
  ASSERT_GT(free_run.iterations, 8);
  stepping.max_total_iterations = 8;
  try {
    SolveStatic(chain, VecX::Zero(n), stepping);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("the budget of 8 iterations in all is spent"));
    // The step was not cut below the minimum step: the message does not say so.
    EXPECT_THAT(std::string(error.what()), Not(HasSubstr("cut below the minimum")));
  }
  stepping.throw_on_failure = false;
  const NewtonResult stopped = SolveStatic(chain, VecX::Zero(n), stepping);
  EXPECT_FALSE(stopped.converged);
  EXPECT_LT(stopped.load_factor, 1.0);
  EXPECT_LE(stopped.iterations, 8 + stepping.max_iterations);
  EXPECT_TRUE(stopped.q.allFinite());
}

// A budget that runs out right after a load step converged: the message says where the
// continuation stopped and that its last step converged, not that a step failed.
TEST(SolveStatic, ABudgetSpentAfterAConvergedStepSaysTheStepConverged) {
  const int n = 4;
  SpringChain linear(n, 1.0, 0.0, 0.3);  // linear springs: one Newton iteration a load step
  NewtonOptions stepping = PlainNewton();
  stepping.load_stepping.enabled = true;
  stepping.load_stepping.initial_step = 0.25;
  stepping.load_stepping.max_step = 0.25;
  stepping.max_total_iterations = 1;
  try {
    SolveStatic(linear, VecX::Zero(n), stepping);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    const std::string message = error.what();
    EXPECT_THAT(message, HasSubstr("stopped at load factor 0.25, the last it converged"));
    EXPECT_THAT(message, HasSubstr("the budget of 1 iterations in all is spent"));
    EXPECT_THAT(message, Not(HasSubstr("failed")));
  }
}

TEST(SolveStatic, FollowsAVonMisesTrussUpToNearItsLimitPoint) {
  // EA = 1e7 N, b = 1 m, h = 0.1 m (shallow). Choose w* on the rising branch and apply the load
  // the truss carries there, F(w*), so w* is the exact answer.
  VonMisesTruss probe(1.0e7, 1.0, 0.1, 0.0);
  const double w_exact = 0.035;  // the limit point is at w ≈ 0.042 m
  VonMisesTruss truss(1.0e7, 1.0, 0.1, probe.InternalForce(w_exact));
  ASSERT_GT(probe.InternalForce(w_exact), 0.97 * probe.LimitLoad());
  const NewtonResult result = SolveStatic(truss, VecX::Zero(1));
  ASSERT_TRUE(result.converged);
  EXPECT_NEAR(result.q[0], w_exact, 1e-10);
}

TEST(SolveStatic, StopsAtTheLimitPointAndSaysWhere) {
  // Beyond the limit load there is no nearby equilibrium: the load steps shrink at the limit
  // point λ* = P_max / P and the error reports the load factor reached.
  VonMisesTruss probe(1.0e7, 1.0, 0.1, 0.0);
  const double load = 1.05 * probe.LimitLoad();
  VonMisesTruss truss(1.0e7, 1.0, 0.1, load);
  NewtonOptions options;
  options.throw_on_failure = false;
  options.load_stepping.min_step = 1e-5;
  const NewtonResult result = SolveStatic(truss, VecX::Zero(1), options);
  EXPECT_FALSE(result.converged);
  const double limit_factor = probe.LimitLoad() / load;
  EXPECT_LE(result.load_factor, limit_factor);
  EXPECT_GT(result.load_factor, limit_factor * (1.0 - 1e-4));  // measured 3.8e-6 below
  EXPECT_TRUE(result.q.allFinite());

  options.throw_on_failure = true;
  try {
    SolveStatic(truss, VecX::Zero(1), options);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    const std::string message = error.what();
    EXPECT_THAT(message, HasSubstr("load factor"));
    EXPECT_THAT(message, HasSubstr("last converged 0.95"));  // λ* = 1/1.05 = 0.952
    EXPECT_THAT(message, HasSubstr("residual norm"));
    EXPECT_THAT(message, HasSubstr("iterations"));
  }
}

TEST(SolveStatic, LineSearchRescuesAStepIntoTheInvalidDomain) {
  // R(q) = √q − 2, root q = 4, from q = 25: the full Newton step goes to q = −5, where √q is NaN.
  auto residual = [](double q, double) { return std::sqrt(q) - 2.0; };
  auto derivative = [](double q, double) { return 0.5 / std::sqrt(q); };
  ScalarProblem problem(residual, derivative);
  const VecX start = VecX::Constant(1, 25.0);
  NewtonOptions plain = PlainNewton();
  plain.force_scale = 1.0;
  try {
    SolveStatic(problem, start, plain);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("non-finite"));
  }
  NewtonOptions searched = plain;
  searched.line_search.enabled = true;
  const NewtonResult result = SolveStatic(problem, start, searched);
  ASSERT_TRUE(result.converged);
  EXPECT_NEAR(result.q[0], 4.0, 1e-7);
}

TEST(SolveStatic, LineSearchCutsTheOvershootOfAHardeningChain) {
  // The soft-start chain of the load stepping test (31 plain Newton iterations) with the line
  // search: the first step is cut back to α ≈ 1e-5, then Newton converges (7 iterations).
  const int n = 5;
  const double k = 1.0, k3 = 1.0e6, elongation = 0.2;
  SpringChain chain(n, k, k3, k * elongation + k3 * std::pow(elongation, 3));
  NewtonOptions options = PlainNewton();
  options.max_iterations = 20;
  options.line_search.enabled = true;
  const NewtonResult result = SolveStatic(chain, VecX::Zero(n), options);
  ASSERT_TRUE(result.converged);
  EXPECT_LE(result.iterations, 10);
  EXPECT_LT((result.q - ChainEquilibrium(n, elongation)).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(SolveStatic, ReportsWhereAndWhyForAnUnsolvableProblem) {
  // R(q) = q² + 1 has no real root: Newton wanders, every load step fails.
  auto residual = [](double q, double) { return q * q + 1.0; };
  auto derivative = [](double q, double) { return 2.0 * q; };
  ScalarProblem problem(residual, derivative);
  NewtonOptions options;
  options.force_scale = 1.0;
  options.max_iterations = 30;
  try {
    SolveStatic(problem, VecX::Constant(1, 0.7), options);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    const std::string message = error.what();
    EXPECT_THAT(message, HasSubstr("static Newton solver failed at load factor"));
    EXPECT_THAT(message, HasSubstr("last converged 0"));
    EXPECT_THAT(message, HasSubstr("residual norm"));
    EXPECT_THAT(message, HasSubstr("tolerance 1e-08 N"));
    EXPECT_THAT(message, HasSubstr("iterations in this step"));
  }
  options.throw_on_failure = false;
  const NewtonResult result = SolveStatic(problem, VecX::Constant(1, 0.7), options);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.load_factor, 0.0);
  EXPECT_EQ(result.q[0], 0.7);
  EXPECT_DOUBLE_EQ(result.residual_norm, 0.7 * 0.7 + 1.0);
}

TEST(SolveStatic, PlainNewtonFailureNamesTheIterationLimit) {
  auto residual = [](double q, double) { return q * q + 1.0; };
  auto derivative = [](double q, double) { return 2.0 * q; };
  ScalarProblem problem(residual, derivative);
  NewtonOptions options = PlainNewton();
  options.force_scale = 1.0;
  options.max_iterations = 7;
  try {
    SolveStatic(problem, VecX::Constant(1, 0.7), options);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    const std::string message = error.what();
    EXPECT_THAT(message, HasSubstr("load stepping off"));
    EXPECT_THAT(message, HasSubstr("no convergence within 7 iterations"));
  }
}

TEST(SolveStatic, ReportsASingularIterationMatrix) {
  // R = q² − 1 started at q = 0, where dR/dq = 0.
  auto residual = [](double q, double) { return q * q - 1.0; };
  auto derivative = [](double q, double) { return 2.0 * q; };
  ScalarProblem problem(residual, derivative);
  try {
    SolveStatic(problem, VecX::Zero(1), PlainNewton());
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("cannot be factorized"));
  }
}

TEST(SolveStatic, IncrementToleranceStopsAtRoundOff) {
  // A residual tolerance far below round-off (1e-20 of the force scale) can only be met through
  // the increment criterion.
  const int n = 10;
  SpringChain chain(n, 1.0e3, 1.0e5, 200.0);
  NewtonOptions options = PlainNewton();
  options.residual_tolerance = 1e-20;
  options.increment_tolerance = 1e-13;
  const NewtonResult result = SolveStatic(chain, VecX::Zero(n), options);
  ASSERT_TRUE(result.converged);
  EXPECT_LT((result.q - ChainEquilibrium(n, 0.1)).norm(), 1e-11);
  options.increment_tolerance = 0.0;
  EXPECT_THROW(SolveStatic(chain, VecX::Zero(n), options), SolverError);
}

// A spring chain that counts its iteration matrices and allows their reuse.
// A spring chain that counts its iteration matrices and says whether they may be reused.
class ReusableChain final : public StaticProblem {
 public:
  ReusableChain(int n, double k, double k3, double load, bool reusable = true)
      : chain_(n, k, k3, load), reusable_(reusable) {}
  Index num_positions() const override { return chain_.num_positions(); }
  Index num_velocities() const override { return chain_.num_velocities(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return chain_.Increment(q, dv); }
  VecX Residual(double t, const VecX& q, const VecX& v, const VecX& a) const override {
    return chain_.Residual(t, q, v, a);
  }
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, double cK,
                            double cD, double cM) const override {
    ++matrices;
    return chain_.IterationMatrix(t, q, v, a, cK, cD, cM);
  }
  bool CanReuseIterationMatrix() const override { return reusable_; }
  void SetLoadFactor(double load_factor) override { chain_.SetLoadFactor(load_factor); }
  mutable int matrices = 0;

 private:
  SpringChain chain_;
  bool reusable_;
};

TEST(SolveStatic, ReusesTheIterationMatrixWhenAllowed) {
  // Linear chain (k3 = 0): one matrix, one iteration, exact answer q_i = i P / k.
  ReusableChain linear(8, 500.0, 0.0, 10.0);
  const NewtonResult exact = SolveStatic(linear, VecX::Zero(8));
  ASSERT_TRUE(exact.converged);
  EXPECT_EQ(linear.matrices, 1);
  EXPECT_EQ(exact.iterations, 1);
  EXPECT_LT((exact.q - ChainEquilibrium(8, 10.0 / 500.0)).norm(), 1e-14);
  // Mildly nonlinear chain: modified Newton (one matrix per load step) converges linearly, so it
  // takes more iterations than matrices.
  const double k = 1.0e3, k3 = 1.0e4, elongation = 0.1;  // f(e*) = 100 + 10 N
  ReusableChain chain(8, k, k3, k * elongation + k3 * std::pow(elongation, 3));
  NewtonOptions options;
  options.max_iterations = 60;
  const NewtonResult result = SolveStatic(chain, VecX::Zero(8), options);
  ASSERT_TRUE(result.converged);
  EXPECT_LT(chain.matrices, result.iterations);
  // Linear convergence stops just below |R| ≤ 1e-8 × 110 N; the position error is then bounded
  // by |K⁻¹| |R| ≤ (8/k)(1.1e-6 N) ≈ 9e-9 m.
  EXPECT_LT((result.q - ChainEquilibrium(8, elongation)).cwiseAbs().maxCoeff(), 1e-8);
}

// NewtonOptions::reuse_contraction on a problem whose matrix is not reusable by itself: from a start
// near the equilibrium (a neighbour's), the factorization is kept while each step contracts |R| to a
// quarter or less, so fewer matrices than iterations; without it, one a step. Both reach the chain's
// exact equilibrium.
TEST(SolveStatic, KeepsTheFactorizationWhileTheResidualContracts) {
  const int n = 8;
  const double k = 1.0e3, k3 = 1.0e4, elongation = 0.1;
  const VecX start = ChainEquilibrium(n, 0.97 * elongation);  // 3 % short of the equilibrium
  NewtonOptions options = PlainNewton();
  options.max_iterations = 40;
  ReusableChain plain(n, k, k3, k * elongation + k3 * std::pow(elongation, 3), false);
  const NewtonResult full = SolveStatic(plain, start, options);
  ASSERT_TRUE(full.converged);
  EXPECT_EQ(plain.matrices, full.iterations);
  options.reuse_contraction = 0.25;
  ReusableChain kept(n, k, k3, k * elongation + k3 * std::pow(elongation, 3), false);
  const NewtonResult modified = SolveStatic(kept, start, options);
  ASSERT_TRUE(modified.converged);
  EXPECT_LT(kept.matrices, modified.iterations);
  EXPECT_LT((modified.q - ChainEquilibrium(n, elongation)).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(SolveStatic, RejectsAStartOfTheWrongSize) {
  SpringChain chain(3, 1.0, 1.0, 1.0);
  EXPECT_THROW(SolveStatic(chain, VecX::Zero(2)), LogicError);
}


// Two unit masses: a stiff linear spring (K x₂ = K) and a soft hardening one (ε x₁ + x₁³ = 1, ε =
// 1e-6: stiff only once stretched, like a hanging string's lateral stiffness that comes with its
// tension). From rest, Newton's first step wants x₁ = 1/ε = 1e6.
class SoftAndStiff final : public StaticProblem {
 public:
  Index num_positions() const override { return 2; }
  Index num_velocities() const override { return 2; }
  VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }
  VecX Residual(double, const VecX& q, const VecX&, const VecX&) const override {
    VecX r(2);
    r << kSoft * q[0] + std::pow(q[0], 3) - 1.0, kStiff * (q[1] - 1.0);
    return r;
  }
  SparseMat IterationMatrix(double, const VecX& q, const VecX&, const VecX&, double cK, double,
                            double cM) const override {
    SparseMat matrix(2, 2);
    matrix.insert(0, 0) = cK * (kSoft + 3.0 * q[0] * q[0]) + cM;
    matrix.insert(1, 1) = cK * kStiff + cM;
    return matrix;
  }
  void SetLoadFactor(double) override {}
  static constexpr double kSoft = 1e-6, kStiff = 1e6;
};

// Trust radius 0.05, one solve at full load, |R| to 1e-12 N.
NewtonOptions SoftAndStiffOptions() {
  NewtonOptions options;
  options.max_increment = 0.05;
  options.max_iterations = 300;
  options.load_stepping.enabled = false;
  options.line_search.enabled = false;
  options.residual_tolerance = 1e-12;
  options.force_scale = 1.0;
  return options;
}

TEST(SolveStatic, MassShiftSolvesAgainInsteadOfCuttingAndReachesTheSameRoot) {
  // Trust radius 0.05. Cut to it, the first step moves both springs by 5e-8 of their correction;
  // with the mass shift, that step is solved again with σM added (σ raised until the step is within
  // the radius), and the solve still ends in Newton's quadratic convergence at the root
  // (x₁³ + ε x₁ = 1). (On this decoupled toy the plain cut is the faster: 31 iterations against
  // 142; the shift pays where the soft direction is coupled to the rest, as a long string's free
  // top is: docs/validation.md, the 3 km bench.)
  NewtonOptions options = SoftAndStiffOptions();
  SoftAndStiff cut_problem;
  const NewtonResult cut = SolveStatic(cut_problem, VecX::Zero(2), options);
  options.mass_shift = true;
  int resolved = 0;
  options.log = [&](const std::string& line) { resolved += line.find("not acceptable with shift") != std::string::npos; };
  SoftAndStiff shifted_problem;
  const NewtonResult shifted = SolveStatic(shifted_problem, VecX::Zero(2), options);
  ASSERT_TRUE(cut.converged);
  ASSERT_TRUE(shifted.converged);
  const double root = 1.0 - SoftAndStiff::kSoft / 3.0;  // x³ + εx = 1 to first order in ε
  for (const NewtonResult* result : {&cut, &shifted}) {
    EXPECT_NEAR(result->q[0], root, 1e-9);
    EXPECT_NEAR(result->q[1], 1.0, 1e-12);
  }
  std::printf("[ measure  ] iterations: trust radius %d, mass shift %d (%d solved again)\n", cut.iterations,
              shifted.iterations, resolved);
  EXPECT_GT(resolved, 0);
  // The end game is Newton's: the last residuals fall quadratically.
  const auto& history = shifted.residual_history;
  ASSERT_GE(history.size(), 3u);
  const double last = history[history.size() - 1], before = history[history.size() - 2];
  EXPECT_LT(last, 1e-3 * before);
}

TEST(SolveStatic, MassShiftEndGameFinishesWithPlainNewtonOnceNearTheRoot) {
  // The same toy with the end game (NewtonOptions::end_game_residual = 0.5): once a shifted step
  // brings |R| below 0.5 (x₁ > 0.79), plain Newton takes over and converges in a few steps; an end
  // game tried from farther out that fails (|R| grows, or 6 steps do not converge) is given up
  // and the shifted steps go on from where it began.
  NewtonOptions options = SoftAndStiffOptions();
  options.mass_shift = true;
  SoftAndStiff plain_problem;
  const NewtonResult plain = SolveStatic(plain_problem, VecX::Zero(2), options);
  options.end_game_residual = 0.5;
  int end_game_steps = 0;
  options.log = [&](const std::string& line) { end_game_steps += line.find("end game") != std::string::npos; };
  SoftAndStiff problem;
  const NewtonResult finished = SolveStatic(problem, VecX::Zero(2), options);
  ASSERT_TRUE(plain.converged);
  ASSERT_TRUE(finished.converged);
  const double root = 1.0 - SoftAndStiff::kSoft / 3.0;
  EXPECT_NEAR(finished.q[0], root, 1e-9);
  EXPECT_NEAR(finished.q[1], 1.0, 1e-12);
  EXPECT_GT(end_game_steps, 0);
  EXPECT_LE(end_game_steps, 6);  // the first end game, from |R| < 0.5, converges
  std::printf("[ measure  ] iterations: mass shift %d, with the end game %d (%d of them plain Newton)\n",
              plain.iterations, finished.iterations, end_game_steps);
  EXPECT_LT(finished.iterations, plain.iterations);
}

// Two stiff springs in series (k = 1e12 N/m, a c = 1000 drill-pipe joint) from a wall at 3600.1 m,
// a load P = 1 N at the end: the positions are stored absolutely, so their rounding unit 4.5e-13 m
// makes |R| noisy at ~k·ε·|q| ≈ 0.8 N, far above the tolerance 1e-8 × P asks. With the state's
// resolution known (StateResolution) the solver raises the tolerance to the measured floor and
// converges; without it, it cannot.
class FarStiffSprings final : public StaticProblem {
 public:
  explicit FarStiffSprings(bool tells_resolution) : tells_resolution_(tells_resolution) {}
  Index num_positions() const override { return 2; }
  Index num_velocities() const override { return 2; }
  VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }
  VecX Residual(double, const VecX& q, const VecX&, const VecX&) const override {
    const double first = kStiffness * (q[0] - kWall), second = kStiffness * (q[1] - q[0] - kLength);
    VecX r(2);
    r << first - second, second - kLoad;
    return r;
  }
  SparseMat IterationMatrix(double, const VecX&, const VecX&, const VecX&, double cK, double, double cM) const override {
    MatX matrix(2, 2);
    matrix << 2.0 * cK * kStiffness + cM, -cK * kStiffness, -cK * kStiffness, cK * kStiffness + cM;
    return matrix.sparseView();
  }
  double ForceScale() const override { return kLoad; }
  VecX StateResolution(const VecX& q) const override {
    if (!tells_resolution_) return {};
    return std::numeric_limits<double>::epsilon() * q.cwiseAbs();
  }
  static constexpr double kStiffness = 1e12, kWall = 3600.1, kLength = 0.3, kLoad = 1.0;

 private:
  bool tells_resolution_;
};

TEST(SolveStatic, ToleranceNeverBelowTheResidualsRoundoffFloor) {
  NewtonOptions options;
  options.load_stepping.enabled = false;
  options.max_iterations = 20;
  // Millimetres from the equilibrium: kN of residual for Newton to take away.
  const VecX start =
      (VecX(2) << FarStiffSprings::kWall + 1e-3, FarStiffSprings::kWall + FarStiffSprings::kLength + 3e-3).finished();
  const double end = FarStiffSprings::kWall + FarStiffSprings::kLength + 2.0 * FarStiffSprings::kLoad / FarStiffSprings::kStiffness;
  FarStiffSprings told(true);
  const NewtonResult solved = SolveStatic(told, start, options);
  const double unit = std::numeric_limits<double>::epsilon() * (FarStiffSprings::kWall + FarStiffSprings::kLength);
  std::printf("round-off tolerance %.3e N (k ε |q| = %.3e N), |R| %.3e N, %d iterations\n", solved.tolerance,
              FarStiffSprings::kStiffness * unit, solved.residual_norm, solved.iterations);
  EXPECT_TRUE(solved.converged);
  EXPECT_LE(solved.residual_norm, solved.tolerance);
  // The floor is the spring's force over a rounding unit or two of its ends, not more.
  EXPECT_GT(solved.tolerance, 0.1 * FarStiffSprings::kStiffness * unit);
  EXPECT_LT(solved.tolerance, 10.0 * FarStiffSprings::kStiffness * unit);
  // The end stands where P/k puts it, to a rounding unit.
  EXPECT_GE(solved.iterations, 1);
  EXPECT_NEAR(solved.q[1], end, 4.0 * unit);
  // Not told, the solver asks for 1e-8 N, which no representable state reaches.
  FarStiffSprings untold(false);
  EXPECT_THROW(SolveStatic(untold, start, options), SolverError);
}

}  // namespace newton_test
}  // namespace drillflex::solvers
