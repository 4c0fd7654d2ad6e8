#include "solvers/iteration_matrix_lu.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/profile.hpp"

namespace drillflex::solvers {

void IterationMatrixLu::SetBlocks(std::vector<Eigen::Index> starts) {
  block_starts_ = std::move(starts);
  analysed_ = false;
}

bool IterationMatrixLu::SameBlockPattern(const SparseMat& matrix) const {
  if (!analysed_ || !matrix.isCompressed() || matrix.rows() + 1 != std::ssize(analysed_outer_) ||
      matrix.nonZeros() != std::ssize(analysed_inner_)) {
    return false;
  }
  return std::equal(analysed_outer_.begin(), analysed_outer_.end(), matrix.outerIndexPtr()) &&
         std::equal(analysed_inner_.begin(), analysed_inner_.end(), matrix.innerIndexPtr());
}

bool IterationMatrixLu::FactorizeBlocks(const SparseMat& matrix) {
  if (block_starts_.empty() || !matrix.isCompressed()) return false;
  if (!SameBlockPattern(matrix)) {
    block_pattern_fits_ = blocks_.Analyze(matrix, block_starts_);
    analysed_outer_.assign(matrix.outerIndexPtr(), matrix.outerIndexPtr() + matrix.rows() + 1);
    analysed_inner_.assign(matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros());
    analysed_ = true;
  }
  if (!block_pattern_fits_) return false;
  // max |a_ij| in one pass; a NaN or an infinity makes the sum of the entries times 0 a NaN.
  const Eigen::Map<const VecX> values(matrix.valuePtr(), matrix.nonZeros());
  double largest = 0.0, poison = 0.0;
  for (Eigen::Index j = 0; j < values.size(); ++j) {
    largest = std::max(largest, std::abs(values[j]));
    poison += 0.0 * values[j];
  }
  if (!std::isfinite(poison)) {
    throw SolverError(fmt::format("the {}x{} iteration matrix has non-finite entries", matrix.rows(), matrix.cols()));
  }
  blocks_.Factorize(matrix);
  return blocks_.smallest_pivot() > options_.block_pivot_tolerance * largest;
}

void IterationMatrixLu::Factorize(const SparseMat& matrix) {
  const profile::Scope scope("solver: LU factorization");
  method_ = Method::kNone;
  if (matrix.rows() <= options_.dense_limit) {
    dense_.compute(MatX(matrix));
    const auto pivots = dense_.matrixLU().diagonal();
    if (!pivots.allFinite() || pivots.cwiseAbs().minCoeff() <= 1e-14 * pivots.cwiseAbs().maxCoeff()) {
      throw SolverError(fmt::format("the dense {}x{} matrix is singular or not finite", matrix.rows(), matrix.cols()));
    }
    method_ = Method::kDense;
    return;
  }
  if (FactorizeBlocks(matrix)) {
    method_ = Method::kBlockTridiagonal;
    return;
  }
  const auto [lower, upper] = BandWidths(matrix);
  const bool banded = static_cast<double>(2 * lower + upper + 1) * static_cast<double>(matrix.rows()) <=
                      options_.band_storage_limit * static_cast<double>(matrix.nonZeros());
  if (banded) {
    band_.Factorize(matrix);
    method_ = Method::kBanded;
  } else {
    sparse_.Factorize(matrix);
    method_ = Method::kSparse;
  }
}

void IterationMatrixLu::SolveInPlace(VecX& x) {
  const profile::Scope scope("solver: LU solve");
  switch (method_) {
    case Method::kDense:
      x = dense_.solve(x);
      return;
    case Method::kBlockTridiagonal:
      blocks_.SolveInPlace(x);
      return;
    case Method::kBanded:
      band_.SolveInPlace(x);
      return;
    case Method::kSparse:
      x = sparse_.Solve(x);
      return;
    case Method::kNone:
      break;
  }
  throw LogicError("IterationMatrixLu::SolveInPlace before a successful Factorize");
}

}  // namespace drillflex::solvers
