#include "solvers/eigen.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <fmt/format.h>

#include "core/dense_eigen.hpp"
#include "core/error.hpp"
#include "solvers/eigen_detail.hpp"

namespace drillflex::solvers {
namespace detail {

void CheckSymmetric(const SparseMat& matrix, Eigen::Index n, const char* name) {
  if (matrix.rows() != n || matrix.cols() != n) {
    throw LogicError(fmt::format("eigen solver: {} is {}x{}, expected {}x{}", name, matrix.rows(),
                                 matrix.cols(), n, n));
  }
  const SparseMat transposed = matrix.transpose();
  if (SparseMat(matrix - transposed).norm() > 1e-10 * matrix.norm()) {
    throw LogicError(fmt::format("eigen solver: {} is not symmetric", name));
  }
}

void NormalizeSigns(MatX& vectors) {
  for (Eigen::Index j = 0; j < vectors.cols(); ++j) {
    Eigen::Index largest = 0;
    vectors.col(j).cwiseAbs().maxCoeff(&largest);
    if (vectors(largest, j) < 0.0) vectors.col(j) = -vectors.col(j);
  }
}

bool SolveDenseDefinite(const MatX& a, const MatX& b, DenseDefinitePairs& pairs) {
  const Eigen::LLT<MatX> cholesky(b);
  if (cholesky.info() != Eigen::Success) return false;
  // C = L⁻¹ A L⁻ᵀ from two triangular solves.
  MatX c = cholesky.matrixL().solve(a);
  c = cholesky.matrixL().solve(c.transpose()).transpose();
  const DenseEigenpairs solved = SymmetricEigen(c);
  if (!solved.converged) {
    throw SolverError(fmt::format("dense eigen solver ({} DOF): no convergence", a.rows()));
  }
  pairs.values = solved.values;
  pairs.vectors = cholesky.matrixU().solve(solved.vectors);
  return true;
}

ModalResult SelectNearest(const VecX& eigenvalues, const MatX& vectors, Eigen::Index count,
                          double shift) {
  std::vector<Index> order(eigenvalues.size());
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return std::abs(eigenvalues[a] - shift) < std::abs(eigenvalues[b] - shift);
  });
  order.resize(std::min<Index>(count, eigenvalues.size()));
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return eigenvalues[a] < eigenvalues[b]; });
  ModalResult result;
  result.eigenvalues.resize(std::ssize(order));
  result.vectors.resize(vectors.rows(), std::ssize(order));
  for (Index i = 0; i < std::ssize(order); ++i) {
    const Index column = i;
    result.eigenvalues[column] = eigenvalues[order[i]];
    result.vectors.col(column) = vectors.col(order[i]);
  }
  NormalizeSigns(result.vectors);
  return result;
}

}  // namespace detail

ModalResult SolveModesDense(const SparseMat& K, const SparseMat& M, Index count, double shift) {
  const Eigen::Index n = K.rows();
  detail::CheckSymmetric(K, n, "K");
  detail::CheckSymmetric(M, n, "M");
  if (count <= 0 || n == 0) return {VecX(0), MatX(n, 0)};
  const MatX m_dense(M);
  detail::DenseDefinitePairs pairs;
  if (!detail::SolveDenseDefinite(MatX(K), m_dense, pairs)) {
    throw SolverError(fmt::format(
        "dense modal solver ({} DOF): the mass matrix is not positive definite", n));
  }
  ModalResult result =
      detail::SelectNearest(pairs.values, pairs.vectors, std::min<Eigen::Index>(count, n), shift);
  // Exact M-normalisation (the reduction gives it up to round-off).
  for (Eigen::Index j = 0; j < result.vectors.cols(); ++j) {
    const double mass = result.vectors.col(j).dot(m_dense * result.vectors.col(j));
    result.vectors.col(j) /= std::sqrt(mass);
  }
  return result;
}

ModalResult SolveModes(const SparseMat& K, const SparseMat& M, Index count, double shift) {
  if (K.rows() <= kDenseModalLimit) return SolveModesDense(K, M, count, shift);
  return SolveModesLanczos(K, M, count, shift);
}

VecX FrequenciesHz(const VecX& eigenvalues) {
  return eigenvalues.unaryExpr(
      [](double w2) { return std::sqrt(std::max(w2, 0.0)) / (2.0 * kPi); });
}

namespace {

// u = x e^{st} in M ü + D u̇ + K u = 0 gives ẏ = A y for y = (u, u̇) with
// A = [[0, I], [−M⁻¹K, −M⁻¹D]] (e.g. Géradin & Rixen, "Mechanical Vibrations", §2.9).
MatX StateSpaceMatrix(const MatX& K, const MatX& D, const MatX& M) {
  const Eigen::Index n = K.rows();
  const Eigen::LLT<MatX> mass(M);  // reads the lower triangle
  if (mass.info() != Eigen::Success) {
    throw SolverError(fmt::format(
        "damped modal solver ({} DOF): the mass matrix is not positive definite", n));
  }
  MatX a = MatX::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n).setIdentity();
  a.bottomLeftCorner(n, n) = -mass.solve(K);
  a.bottomRightCorner(n, n) = -mass.solve(D);
  return a;
}

}  // namespace

ComplexModes SolveDampedModes(const SparseMat& K, const SparseMat& D, const SparseMat& M,
                              Index count) {
  const Eigen::Index n = K.rows();
  if (K.cols() != n || D.rows() != n || D.cols() != n || M.rows() != n || M.cols() != n) {
    throw LogicError("SolveDampedModes: K, D and M must be square and of the same size");
  }
  detail::CheckSymmetric(M, n, "M");
  return SolveDampedModes(MatX(K), MatX(D), MatX(M), count);
}

ComplexModes SolveDampedModes(const MatX& K, const MatX& D, const MatX& M, Index count,
                              bool with_vectors) {
  const Eigen::Index n = K.rows();
  if (K.cols() != n || D.rows() != n || D.cols() != n || M.rows() != n || M.cols() != n) {
    throw LogicError("SolveDampedModes: K, D and M must be square and of the same size");
  }
  const GeneralEigenpairs solver = GeneralEigen(StateSpaceMatrix(K, D, M), with_vectors);
  if (!solver.converged) {
    throw SolverError(fmt::format("damped modal solver ({} DOF): the eigen solver did not converge",
                                  n));
  }
  const Eigen::VectorXcd all_values = solver.values;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < all_values.size(); ++i) {
    if (all_values[i].imag() >= 0.0) kept.push_back(i);  // one of each conjugate pair
  }
  std::stable_sort(kept.begin(), kept.end(), [&](Eigen::Index a, Eigen::Index b) {
    return std::abs(all_values[a]) < std::abs(all_values[b]);
  });
  kept.resize(std::min<Index>(std::ssize(kept), std::max<Index>(count, 0)));
  const Index m = std::ssize(kept);
  ComplexModes modes;
  modes.eigenvalues.resize(m);
  if (with_vectors) modes.vectors.resize(n, m);
  modes.natural_frequencies.resize(m);
  modes.damped_frequencies.resize(m);
  modes.damping_ratios.resize(m);
  for (Eigen::Index j = 0; j < m; ++j) {
    const std::complex<double> s = all_values[kept[j]];
    if (with_vectors) {
      Eigen::VectorXcd x = solver.vectors.col(kept[j]).head(n);
      Eigen::Index largest = 0;
      x.cwiseAbs().maxCoeff(&largest);
      x *= std::abs(x[largest]) / x[largest];  // largest entry real and positive
      modes.vectors.col(j) = x.normalized();
    }
    modes.eigenvalues[j] = s;
    modes.natural_frequencies[j] = std::abs(s);
    modes.damped_frequencies[j] = s.imag();
    modes.damping_ratios[j] = std::abs(s) > 0.0 ? -s.real() / std::abs(s) : 0.0;
  }
  return modes;
}

}  // namespace drillflex::solvers
