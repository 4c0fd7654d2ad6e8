#include "solvers/problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace drillflex::solvers {
namespace {

void CheckSize(const VecX& x, Index expected, const char* name) {
  if (x.size() != expected) {
    std::string message = "FiniteDifferenceIterationMatrix: ";
    message.append(name).append(" has size ").append(std::to_string(x.size()));
    message.append(", expected ").append(std::to_string(expected));
    throw LogicError(message);
  }
}

// Adds coefficient · (R(x + h e_j) − R(x − h e_j)) / (2h) for every column j to `dense`,
// where `evaluate(j, step)` returns R with the j-th variable perturbed by `step`.
template <typename Evaluate>
void AddCentralDifferences(Index n, double coefficient, const Evaluate& evaluate,
                           const std::vector<double>& steps, MatX& dense) {
  for (Index j = 0; j < n; ++j) {
    const double step = steps[j];
    const VecX plus = evaluate(j, step);
    const VecX minus = evaluate(j, -step);
    dense.col(j) += (coefficient / (2.0 * step)) * (plus - minus);
  }
}

std::vector<double> RelativeSteps(const VecX& x, double h) {
  std::vector<double> steps(x.size());
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    steps[j] = h * std::max(1.0, std::abs(x[j]));
  }
  return steps;
}

}  // namespace

SparseMat FiniteDifferenceIterationMatrix(const Problem& problem, double t, const VecX& q,
                                          const VecX& v, const VecX& a, double cK, double cD,
                                          double cM, double h) {
  const Index n = problem.num_velocities();
  CheckSize(q, problem.num_positions(), "q");
  CheckSize(v, n, "v");
  CheckSize(a, n, "a");
  MatX dense = MatX::Zero(n, n);
  if (cK != 0.0) {
    const std::vector<double> steps(n, h);
    AddCentralDifferences(
        n, cK,
        [&](Index j, double step) {
          VecX dv = VecX::Zero(n);
          dv[j] = step;
          return problem.Residual(t, problem.Increment(q, dv), v, a);
        },
        steps, dense);
  }
  if (cD != 0.0) {
    AddCentralDifferences(
        n, cD,
        [&](Index j, double step) {
          VecX perturbed = v;
          perturbed[j] += step;
          return problem.Residual(t, q, perturbed, a);
        },
        RelativeSteps(v, h), dense);
  }
  if (cM != 0.0) {
    AddCentralDifferences(
        n, cM,
        [&](Index j, double step) {
          VecX perturbed = a;
          perturbed[j] += step;
          return problem.Residual(t, q, v, perturbed);
        },
        RelativeSteps(a, h), dense);
  }
  SparseMat result = dense.sparseView(0.0, 0.0);  // keeps every non-zero entry
  result.makeCompressed();
  return result;
}

double RelativeMatrixError(const SparseMat& a, const SparseMat& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    throw LogicError("RelativeMatrixError: matrices of different sizes");
  }
  const double scale = std::max(a.norm(), b.norm());
  if (scale == 0.0) return 0.0;
  return SparseMat(a - b).norm() / scale;
}

double RelativeMatrixError(const MatX& a, const MatX& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    throw LogicError("RelativeMatrixError: matrices of different sizes");
  }
  const double scale = std::max(a.norm(), b.norm());
  if (scale == 0.0) return 0.0;
  return (a - b).norm() / scale;
}

// The 3 km bench string at c = 1000: 0.28 N, which then sets its tolerance (1e-8 of its weight asks
// 0.009 N; the floor was 759 N while the state held absolute frame origins).
double ResidualRoundoffFloor(StaticProblem& problem, const VecX& q, double time) {
  const VecX resolution = problem.StateResolution(q);
  if (resolution.size() != problem.num_velocities()) return 0.0;
  VecX signed_resolution = resolution;
  std::uint32_t state = 2463534242u;  // xorshift32 (Marsaglia 2003), a fixed sequence
  for (Eigen::Index j = 0; j < signed_resolution.size(); ++j) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    if (state & 1u) signed_resolution[j] = -signed_resolution[j];
  }
  const VecX zero = VecX::Zero(problem.num_velocities());
  const VecX here = problem.Residual(time, q, zero, zero);
  const VecX moved = problem.Residual(time, problem.Increment(q, signed_resolution), zero, zero);
  const double noise = (moved - here).norm();
  return std::isfinite(noise) ? noise : 0.0;
}

}  // namespace drillflex::solvers
