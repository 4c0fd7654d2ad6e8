#include "analyses/dynamic_relaxation.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analyses/linearization.hpp"
#include "analyses/modes_analysis.hpp"
#include "core/error.hpp"
#include "solvers/eigen.hpp"
#include "solvers/linear_solver.hpp"

namespace drillflex::analyses {
namespace {

SparseMat StaticTangent(const model::SystemModel& model, const VecX& q, const model::LoadParameters& parameters) {
  const VecX zero = VecX::Zero(model.num_velocities());
  const SparseMat tangent = model.IterationMatrix(0.0, q, zero, zero, parameters, 1.0, 0.0, 0.0);
  return tangent;
}

// ω₁² of the string at q: the lowest eigenvalue of the (symmetrized) tangent above the rigid-body
// range; the lowest non-zero one if all are rigid-body-like.
double LowestElasticEigenvalue(const model::SystemModel& model, const VecX& q) {
  const int count = std::min<Index>(8, model.num_velocities());
  const solvers::ModalResult modes = LowestModes(Linearize(model, q, 1.0), count);
  const double largest = std::abs(modes.eigenvalues.tail<1>()[0]);
  for (Eigen::Index i = 0; i < modes.eigenvalues.size(); ++i) {
    if (modes.eigenvalues[i] > 1e-10 * largest && modes.eigenvalues[i] > 1e-8) return modes.eigenvalues[i];
  }
  throw SolverError("dynamic relaxation: the string has no elastic mode among its lowest eight (is it supported?)");
}

}  // namespace

RelaxationResult SolveByDynamicRelaxation(const model::SystemModel& model, const RelaxationOptions& options,
                                          const model::LoadParameters& parameters) {
  const Index n = model.num_velocities();
  const VecX zero = VecX::Zero(n);
  RelaxationResult result;
  result.q = model.ReferencePositions();
  const double omega = std::sqrt(LowestElasticEigenvalue(model, result.q));
  const double h = 1.0 / omega;  // pseudo time step, s
  const double damping = 2.0 * options.damping_ratio * omega;
  VecX v = VecX::Zero(n);
  solvers::SparseLinearSolver solver;
  for (int step = 1; step <= options.max_steps; ++step) {
    const SparseMat mass = model.MassMatrix(result.q);
    const VecX residual = model.Residual(0.0, result.q, zero, zero, parameters);
    // (M/h + C + h K) v₁ = M v₀/h − R(q₀) with C = 2 ζ ω₁ M (header).
    const SparseMat matrix = ((1.0 / h + damping) * mass + h * StaticTangent(model, result.q, parameters)).pruned();
    solver.Factorize(matrix, solvers::MatrixSymmetry::kAuto);
    v = solver.Solve(VecX(mass * v / h - residual));
    result.q = model.Increment(result.q, h * v);
    result.steps = step;
    result.kinetic_energy = 0.5 * v.dot(mass * v);
    if (!std::isfinite(result.kinetic_energy)) break;
    if ((h * v).lpNorm<Eigen::Infinity>() <= options.increment_tolerance) {
      result.converged = true;
      break;
    }
  }
  result.residual_norm = model.Residual(0.0, result.q, zero, zero, parameters).norm();
  if (!result.converged) {
    throw SolverError(fmt::format(
        "dynamic relaxation did not converge in {} steps (last pseudo-kinetic energy {:.3g} J, |R| = {:.3g} N)",
        result.steps, result.kinetic_energy, result.residual_norm));
  }
  return result;
}

}  // namespace drillflex::analyses
