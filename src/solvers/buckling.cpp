#include "solvers/buckling.hpp"

#include <Spectra/MatOp/SparseCholesky.h>
#include <Spectra/SymGEigsSolver.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "solvers/eigen_detail.hpp"

namespace drillflex::solvers {
namespace {

// ν = 1/λ at or below this fraction of the largest |ν| is round-off in directions without
// geometric stiffness (λ = ∞), not a buckling load.
constexpr double kRelativeNuFloor = 1e-10;

// The `count` largest positive ν (above the floor) as λ = 1/ν ascending, with their modes.
BucklingResult FromReciprocals(const VecX& nu, const MatX& vectors, Eigen::Index count) {
  const double floor = kRelativeNuFloor * (nu.size() > 0 ? nu.cwiseAbs().maxCoeff() : 0.0);
  std::vector<Eigen::Index> order;
  for (Eigen::Index i = 0; i < nu.size(); ++i) {
    if (nu[i] > floor) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return nu[a] > nu[b]; });
  order.resize(std::min<Index>(std::ssize(order), count));
  BucklingResult result;
  result.multipliers.resize(std::ssize(order));
  result.modes.resize(vectors.rows(), std::ssize(order));
  for (Index i = 0; i < std::ssize(order); ++i) {
    const Index j = i;
    result.multipliers[j] = 1.0 / nu[order[i]];
    result.modes.col(j) = vectors.col(order[i]);
  }
  detail::NormalizeSigns(result.modes);
  return result;
}

void CheckInputs(const SparseMat& K, const SparseMat& K_G) {
  detail::CheckSymmetric(K, K.rows(), "K");
  detail::CheckSymmetric(K_G, K.rows(), "K_G");
}

// y = (A − K X diag(ν) Xᵀ K) x with A = −K_G and X the K-orthonormal modes found so far:
// Wielandt deflation, which moves the found ν to 0 and keeps every other eigenpair.
class DeflatedProduct {
 public:
  using Scalar = double;

  DeflatedProduct(const SparseMat& a, const MatX& k_locked, const VecX& locked_nu)
      : a_(&a), k_locked_(&k_locked), locked_nu_(&locked_nu) {}

  Eigen::Index rows() const { return a_->rows(); }
  Eigen::Index cols() const { return a_->cols(); }

  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const VecX> x(x_in, rows());
    Eigen::Map<VecX> y(y_out, rows());
    y = *a_ * x;
    if (k_locked_->cols() > 0) {
      const VecX coefficients = locked_nu_->cwiseProduct(k_locked_->transpose() * x);
      y -= *k_locked_ * coefficients;
    }
  }

 private:
  const SparseMat* a_;
  const MatX* k_locked_;
  const VecX* locked_nu_;
};

}  // namespace

BucklingResult SolveBucklingDense(const SparseMat& K, const SparseMat& K_G, Index count) {
  CheckInputs(K, K_G);
  const Eigen::Index n = K.rows();
  if (count <= 0 || n == 0) return {VecX(0), MatX(n, 0)};
  detail::DenseDefinitePairs pairs;
  if (!detail::SolveDenseDefinite(-MatX(K_G), MatX(K), pairs)) {
    throw SolverError(fmt::format(
        "dense buckling solver ({} DOF): the stiffness matrix K is not positive definite (is "
        "the structure supported against rigid-body motion?)",
        n));
  }
  return FromReciprocals(pairs.values, pairs.vectors, count);
}

BucklingResult SolveBucklingLanczos(const SparseMat& K, const SparseMat& K_G, Index count) {
  CheckInputs(K, K_G);
  const Eigen::Index n = K.rows();
  const Eigen::Index wanted = std::min<Eigen::Index>(std::max<Index>(count, 0), n);
  if (wanted == 0) return {VecX(0), MatX(n, 0)};
  if (3 * wanted >= n) return SolveBucklingDense(K, K_G, count);
  using BOp = Spectra::SparseCholesky<double>;
  BOp cholesky(K);
  if (cholesky.info() != Spectra::CompInfo::Successful) {
    throw SolverError(fmt::format(
        "Lanczos buckling solver ({} DOF): the stiffness matrix K is not positive definite (is "
        "the structure supported against rigid-body motion?)",
        n));
  }
  const SparseMat a = -K_G;
  MatX locked(n, 0);
  MatX k_locked(n, 0);  // K X
  VecX locked_nu(0);
  DeflatedProduct op(a, k_locked, locked_nu);
  constexpr int kMaxRuns = 12;  // later runs find the missing copies of multiple eigenvalues
  for (int run = 0; run < kMaxRuns; ++run) {
    const Eigen::Index nev = std::min(wanted, n - locked.cols() - 2);
    if (nev < 1) break;
    Spectra::SymGEigsSolver<DeflatedProduct, BOp, Spectra::GEigsMode::Cholesky> solver(
        op, cholesky, nev, std::min(n, std::max<Eigen::Index>(2 * nev + 1, 20)));
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-12);
    const VecX nu = solver.eigenvalues();
    if (nu.size() == 0) {
      throw SolverError(
          fmt::format("Lanczos buckling solver ({} DOF): no eigenvalue converged", n));
    }
    const MatX vectors = solver.eigenvectors();  // K-normalised: xᵀ K x = 1
    double kept_floor = -std::numeric_limits<double>::infinity();  // ν of the last kept mode
    if (locked_nu.size() >= wanted) {
      VecX sorted = locked_nu;
      std::sort(sorted.data(), sorted.data() + sorted.size(), std::greater<>());
      kept_floor = sorted[wanted - 1];
    }
    const double largest_new = nu.maxCoeff();
    const Eigen::Index old = locked.cols();
    locked.conservativeResize(n, old + vectors.cols());
    locked.rightCols(vectors.cols()) = vectors;
    k_locked = K * locked;
    locked_nu.conservativeResize(old + nu.size());
    locked_nu.tail(nu.size()) = nu;
    // Nothing new above the kept ones (or nothing positive left): no multiplier was missed.
    if (largest_new <= 0.0 || largest_new < kept_floor * (1.0 - 1e-8)) break;
  }
  return FromReciprocals(locked_nu, locked, wanted);
}

BucklingResult SolveBuckling(const SparseMat& K, const SparseMat& K_G, Index count) {
  if (K.rows() <= kDenseBucklingLimit) return SolveBucklingDense(K, K_G, count);
  return SolveBucklingLanczos(K, K_G, count);
}

}  // namespace drillflex::solvers
