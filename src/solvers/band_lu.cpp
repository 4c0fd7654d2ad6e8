#include "solvers/band_lu.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include <fmt/format.h>

#include "core/error.hpp"

// LAPACK's banded LU (Fortran interface; liblapack comes with libsuitesparse-dev).
extern "C" {
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku, double* ab, const int* ldab, int* ipiv,
             int* info);
void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku, const int* nrhs, const double* ab,
             const int* ldab, const int* ipiv, double* b, const int* ldb, int* info, std::size_t trans_length);
}

namespace drillflex::solvers {

std::pair<int, int> BandWidths(const SparseMat& matrix) {
  int lower = 0, upper = 0;
  for (Eigen::Index col = 0; col < matrix.outerSize(); ++col) {
    for (SparseMat::InnerIterator it(matrix, col); it; ++it) {
      const int offset = static_cast<int>(it.row() - it.col());
      lower = std::max(lower, offset);
      upper = std::max(upper, -offset);
    }
  }
  return {lower, upper};
}

void BandLuSolver::Factorize(const SparseMat& matrix) {
  if (matrix.rows() != matrix.cols()) {
    throw LogicError(fmt::format("BandLuSolver: matrix {}x{} is not square", matrix.rows(), matrix.cols()));
  }
  factorized_ = false;
  size_ = static_cast<int>(matrix.rows());
  std::tie(lower_, upper_) = BandWidths(matrix);
  // Band storage (LAPACK dgbtrf): A(i, j) at ab[kl + ku + i − j + j·ldab], ldab = 2 kl + ku + 1; the
  // first kl rows are room for the fill of the row interchanges.
  const int ldab = 2 * lower_ + upper_ + 1;
  band_.assign(static_cast<std::size_t>(ldab) * static_cast<std::size_t>(size_), 0.0);
  pivots_.resize(static_cast<std::size_t>(size_));
  for (Eigen::Index col = 0; col < matrix.outerSize(); ++col) {
    double* column = band_.data() + col * ldab + lower_ + upper_ - col;
    for (SparseMat::InnerIterator it(matrix, col); it; ++it) {
      if (!std::isfinite(it.value())) {
        throw SolverError(fmt::format("BandLuSolver: the {}x{} matrix has non-finite entries", size_, size_));
      }
      column[it.row()] += it.value();
    }
  }
  if (size_ == 0) {
    factorized_ = true;
    return;
  }
  int info = 0;
  dgbtrf_(&size_, &size_, &lower_, &upper_, band_.data(), &ldab, pivots_.data(), &info);
  if (info < 0) throw LogicError(fmt::format("BandLuSolver: dgbtrf argument {} is invalid", -info));
  // U's diagonal is row kl + ku of the factored storage.
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (int j = 0; j < size_; ++j) {
    const double pivot = std::abs(band_[static_cast<std::size_t>(j) * ldab + lower_ + upper_]);
    largest = std::max(largest, pivot);
    smallest = std::min(smallest, pivot);
  }
  if (info > 0 || !(smallest > 1e-14 * largest)) {
    throw SolverError(fmt::format("BandLuSolver: the {}x{} matrix is singular (smallest pivot {:.3g} of {:.3g})",
                                  size_, size_, smallest, largest));
  }
  factorized_ = true;
}

void BandLuSolver::SolveInPlace(VecX& rhs) const {
  if (!factorized_) throw LogicError("BandLuSolver::Solve before a successful Factorize");
  if (rhs.size() != size_) throw LogicError("BandLuSolver::Solve: right-hand side of the wrong size");
  if (size_ == 0) return;
  const int ldab = 2 * lower_ + upper_ + 1;
  const int one = 1;
  int info = 0;
  dgbtrs_("N", &size_, &lower_, &upper_, &one, band_.data(), &ldab, pivots_.data(), rhs.data(), &size_, &info, 1);
  if (info != 0) throw LogicError(fmt::format("BandLuSolver: dgbtrs argument {} is invalid", -info));
}

VecX BandLuSolver::Solve(const VecX& rhs) const {
  VecX x = rhs;
  SolveInPlace(x);
  return x;
}

}  // namespace drillflex::solvers
