#include "solvers/linear_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "solvers/band_lu.hpp"

namespace drillflex::solvers {

struct SparseLinearSolver::Factors {
  Eigen::SimplicialLDLT<SparseMat, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_amd;
  Eigen::SimplicialLDLT<SparseMat, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt_natural;
  Eigen::SparseLU<SparseMat, Eigen::COLAMDOrdering<int>> lu_colamd;
  Eigen::SparseLU<SparseMat, Eigen::NaturalOrdering<int>> lu_natural;
};

namespace {

// Backward error threshold above which an LDLT solution is not trusted.
constexpr double kLdltBackwardErrorLimit = 1e-10;

// ‖A − Aᵀ‖_F ≤ 1e-12 ‖A‖_F, summed entry by entry (a_ji found by binary search in the sorted
// column i) and stopped as soon as the asymmetry exceeds the limit: forming Aᵀ and A − Aᵀ took
// 1.9 ms of every 9 ms factorization of the bundled example's 1872² transient iteration matrix,
// which is unsymmetric (friction, gyroscopic terms) from its first entries on.
bool IsNumericallySymmetric(const SparseMat& matrix, double norm) {
  const double limit = 1e-24 * norm * norm;
  const int* outer = matrix.outerIndexPtr();
  const int* inner = matrix.innerIndexPtr();
  const double* values = matrix.valuePtr();
  double asymmetry = 0.0;
  for (Eigen::Index j = 0; j < matrix.outerSize(); ++j) {
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int i = inner[k];
      if (i == j) continue;
      const int* begin = inner + outer[i];
      const int* end = inner + outer[i + 1];
      const int* found = std::lower_bound(begin, end, j);
      const double mirror = (found != end && *found == j) ? values[found - inner] : 0.0;
      const double difference = values[k] - mirror;
      asymmetry += difference * difference;
      if (asymmetry > limit) return false;
    }
  }
  return true;
}

bool AllFinite(const SparseMat& matrix) {
  const double* values = matrix.valuePtr();
  return std::all_of(values, values + matrix.nonZeros(),
                     [](double x) { return std::isfinite(x); });
}

std::string SizeText(const SparseMat& matrix) {
  return fmt::format("{}x{}", matrix.rows(), matrix.cols());
}

// Normwise backward error ‖A x − b‖ / (‖A‖_F ‖x‖ + ‖b‖) (Rigal–Gaches, with the Frobenius norm),
// ‖A‖_F given (taken once a factorization: it was a third of a Lanczos solve's time).
double BackwardError(const SparseMat& a, double a_norm, const MatX& x, const MatX& b) {
  const double denominator = a_norm * x.norm() + b.norm();
  if (denominator == 0.0) return 0.0;
  return (a * x - b).norm() / denominator;
}

}  // namespace

Eigen::Index HalfBandwidth(const SparseMat& matrix) {
  const auto [lower, upper] = BandWidths(matrix);
  return std::max(lower, upper);
}

bool FactorizeInOwnOrder(const SparseMat& matrix) {
  return static_cast<double>(matrix.rows()) * static_cast<double>(HalfBandwidth(matrix)) <=
         8.0 * static_cast<double>(std::max<Eigen::Index>(matrix.nonZeros(), 1));
}

SparseLinearSolver::SparseLinearSolver() : factors_(std::make_unique<Factors>()) {}
SparseLinearSolver::~SparseLinearSolver() = default;
SparseLinearSolver::SparseLinearSolver(SparseLinearSolver&&) noexcept = default;
SparseLinearSolver& SparseLinearSolver::operator=(SparseLinearSolver&&) noexcept = default;

bool SparseLinearSolver::SamePattern(const SparseMat& matrix) const {
  if (matrix.rows() != matrix_.rows() || matrix.cols() != matrix_.cols() ||
      matrix.nonZeros() != matrix_.nonZeros()) {
    return false;
  }
  const Eigen::Index n = matrix.outerSize();
  return std::equal(matrix.outerIndexPtr(), matrix.outerIndexPtr() + n + 1,
                    matrix_.outerIndexPtr()) &&
         std::equal(matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros(),
                    matrix_.innerIndexPtr());
}

void SparseLinearSolver::Factorize(const SparseMat& matrix_in, MatrixSymmetry symmetry) {
  if (matrix_in.rows() != matrix_in.cols()) {
    throw LogicError(
        fmt::format("SparseLinearSolver: matrix {} is not square", SizeText(matrix_in)));
  }
  SparseMat matrix = matrix_in;
  matrix.makeCompressed();
  if (!AllFinite(matrix)) {
    throw SolverError(fmt::format(
        "SparseLinearSolver: the {} matrix has non-finite entries (NaN or Inf)", SizeText(matrix)));
  }
  const bool same_pattern = factorized_ && SamePattern(matrix);
  if (!same_pattern) {
    ldlt_analyzed_ = false;
    lu_analyzed_ = false;
    natural_order_ = FactorizeInOwnOrder(matrix);  // see the header for the measurements
  }
  matrix_ = std::move(matrix);
  matrix_norm_ = matrix_.norm();
  factorized_ = false;
  const bool symmetric =
      symmetry == MatrixSymmetry::kSymmetric ||
      (symmetry == MatrixSymmetry::kAuto && IsNumericallySymmetric(matrix_, matrix_norm_));
  if (!symmetric) {
    FactorizeLu();
    return;
  }
  use_lu_ = false;
  auto factorize_ldlt = [&](auto& ldlt) {
    if (!ldlt_analyzed_) ldlt.analyzePattern(matrix_);
    ldlt_analyzed_ = true;
    ldlt.factorize(matrix_);
    return ldlt.info() == Eigen::Success;
  };
  const bool ok = natural_order_ ? factorize_ldlt(factors_->ldlt_natural)
                                 : factorize_ldlt(factors_->ldlt_amd);
  if (!ok) {
    FactorizeLu();  // a zero pivot without pivoting: LU with partial pivoting may still work
    return;
  }
  factorized_ = true;
}

void SparseLinearSolver::FactorizeLu() {
  use_lu_ = true;
  auto factorize_lu = [&](auto& lu) {
    if (!lu_analyzed_) lu.analyzePattern(matrix_);
    lu_analyzed_ = true;
    lu.factorize(matrix_);
    if (lu.info() != Eigen::Success) {
      throw SolverError(fmt::format("SparseLinearSolver: the {} matrix is singular (LU: {})",
                                    SizeText(matrix_), lu.lastErrorMessage()));
    }
  };
  if (natural_order_) {
    factorize_lu(factors_->lu_natural);
  } else {
    factorize_lu(factors_->lu_colamd);
  }
  factorized_ = true;
}

VecX SparseLinearSolver::Solve(const VecX& rhs) {
  return SolveColumns(MatX(rhs)).col(0);
}

MatX SparseLinearSolver::SolveColumns(const MatX& rhs) {
  if (!factorized_) throw LogicError("SparseLinearSolver::Solve before a successful Factorize");
  if (rhs.rows() != matrix_.rows()) {
    throw LogicError("SparseLinearSolver::Solve: right-hand side of the wrong size");
  }
  MatX x;
  if (!use_lu_) {
    x = natural_order_ ? MatX(factors_->ldlt_natural.solve(rhs))
                       : MatX(factors_->ldlt_amd.solve(rhs));
    if (!x.allFinite() || BackwardError(matrix_, matrix_norm_, x, rhs) > kLdltBackwardErrorLimit) {
      FactorizeLu();
    }
  }
  if (use_lu_) {
    x = natural_order_ ? MatX(factors_->lu_natural.solve(rhs))
                       : MatX(factors_->lu_colamd.solve(rhs));
  }
  if (!x.allFinite()) {
    throw SolverError(fmt::format(
        "SparseLinearSolver: the solution of the {} system is not finite (the matrix is "
        "singular or nearly so)",
        SizeText(matrix_)));
  }
  return x;
}

}  // namespace drillflex::solvers
