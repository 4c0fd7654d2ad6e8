#include "core/dense_eigen.hpp"

#include <Eigen/Eigenvalues>

namespace drillflex {

DenseEigenpairs SymmetricEigen(const MatX& a, bool with_vectors) {
  const Eigen::SelfAdjointEigenSolver<MatX> solver(a, with_vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
  DenseEigenpairs out;
  out.converged = solver.info() == Eigen::Success;
  if (!out.converged) return out;
  out.values = solver.eigenvalues();
  if (with_vectors) out.vectors = solver.eigenvectors();
  return out;
}

DenseEigenpairs GeneralizedSymmetricEigen(const MatX& a, const MatX& b, bool with_vectors) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> solver(
      a, b, (with_vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly) | Eigen::Ax_lBx);
  DenseEigenpairs out;
  out.converged = solver.info() == Eigen::Success;
  if (!out.converged) return out;
  out.values = solver.eigenvalues();
  if (with_vectors) out.vectors = solver.eigenvectors();
  return out;
}

GeneralEigenpairs GeneralEigen(const MatX& a, bool with_vectors) {
  const Eigen::EigenSolver<MatX> solver(a, with_vectors);
  GeneralEigenpairs out;
  out.converged = solver.info() == Eigen::Success;
  if (!out.converged) return out;
  out.values = solver.eigenvalues();
  if (with_vectors) out.vectors = solver.eigenvectors();
  return out;
}

}  // namespace drillflex
