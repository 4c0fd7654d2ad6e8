#include "solvers/shifted_cholesky.hpp"

#include <algorithm>
#include <cstddef>

#include <Eigen/SparseCholesky>
#include <fmt/format.h>

#include "core/error.hpp"
#include "core/profile.hpp"
#include "solvers/linear_solver.hpp"

// LAPACK's banded Cholesky (Fortran interface; liblapack comes with libsuitesparse-dev).
extern "C" {
void dpbtrf_(const char* uplo, const int* n, const int* kd, double* ab, const int* ldab, int* info,
             std::size_t uplo_length);
void dpbtrs_(const char* uplo, const int* n, const int* kd, const int* nrhs, const double* ab, const int* ldab,
             double* b, const int* ldb, int* info, std::size_t uplo_length);
}

namespace drillflex::solvers {

struct ShiftedCholesky::Factors {
  Eigen::SimplicialLLT<SparseMat, Eigen::Lower, Eigen::AMDOrdering<int>> amd;
};

ShiftedCholesky::ShiftedCholesky(const SparseMat& stiffness, const SparseMat& metric, std::vector<Eigen::Index> blocks)
    : metric_given_(metric), factors_(std::make_unique<Factors>()), blocks_(std::move(blocks)) {
  if (stiffness.rows() != stiffness.cols() || metric.rows() != metric.cols() || stiffness.rows() != metric.rows()) {
    throw LogicError(fmt::format("ShiftedCholesky: H is {}x{}, M {}x{}", stiffness.rows(), stiffness.cols(),
                                 metric.rows(), metric.cols()));
  }
  Build(stiffness);
}

namespace {
// The position of entry (row, column) in a compressed column-major matrix's values, or −1.
int EntryIndex(const SparseMat& matrix, int row, int column) {
  const int* begin = matrix.innerIndexPtr() + matrix.outerIndexPtr()[column];
  const int* end = matrix.innerIndexPtr() + matrix.outerIndexPtr()[column + 1];
  const int* found = std::lower_bound(begin, end, row);
  return found != end && *found == row ? static_cast<int>(found - matrix.innerIndexPtr()) : -1;
}

bool SamePattern(const SparseMat& a, const std::vector<int>& outer, const std::vector<int>& inner) {
  return a.isCompressed() && a.outerSize() + 1 == std::ssize(outer) && a.nonZeros() == std::ssize(inner) &&
         std::equal(outer.begin(), outer.end(), a.outerIndexPtr()) &&
         std::equal(inner.begin(), inner.end(), a.innerIndexPtr());
}
}  // namespace

void ShiftedCholesky::Build(const SparseMat& stiffness) {
  SparseMat copy;
  if (!stiffness.isCompressed()) {
    copy = stiffness;
    copy.makeCompressed();
  }
  const SparseMat& first = stiffness.isCompressed() ? stiffness : copy;
  first_outer_.assign(first.outerIndexPtr(), first.outerIndexPtr() + first.outerSize() + 1);
  first_inner_.assign(first.innerIndexPtr(), first.innerIndexPtr() + first.nonZeros());
  factorized_ = false;
  block_modified_ = false;
  metric_given_.makeCompressed();
  tangent_runs_.Analyze(first);
  metric_runs_.Analyze(metric_given_);
  by_blocks_ = !blocks_.empty() && block_stiffness_.Analyze(first, blocks_, true) &&
               block_metric_.Analyze(metric_given_, blocks_, false);
  if (by_blocks_) {
    block_stiffness_.Assign(first.valuePtr());
    block_metric_.Assign(metric_given_.valuePtr());
    metric_coupled_ = !block_metric_.BlockDiagonal();
    return;
  }
  const SparseMat transposed = stiffness.transpose();
  const SparseMat symmetric = 0.5 * (stiffness + transposed);
  // Sums keep every entry of both patterns (explicit zeros too), so the three share one pattern in
  // one order and H + σM is formed entry by entry.
  stiffness_ = symmetric + 0.0 * metric_given_;
  metric_ = metric_given_ + 0.0 * symmetric;
  stiffness_.makeCompressed();
  metric_.makeCompressed();
  if (stiffness_.nonZeros() != metric_.nonZeros()) throw LogicError("ShiftedCholesky: the patterns differ");
  original_.assign(stiffness_.valuePtr(), stiffness_.valuePtr() + stiffness_.nonZeros());
  from_entry_.assign(stiffness_.nonZeros(), -1);
  from_transposed_.assign(stiffness_.nonZeros(), -1);
  for (int j = 0; j < stiffness_.outerSize(); ++j) {
    for (int k = stiffness_.outerIndexPtr()[j]; k < stiffness_.outerIndexPtr()[j + 1]; ++k) {
      const int i = stiffness_.innerIndexPtr()[k];
      from_entry_[k] = EntryIndex(first, i, j);
      from_transposed_[k] = EntryIndex(first, j, i);
    }
  }
  banded_ = FactorizeInOwnOrder(stiffness_);
  if (banded_) {
    half_bandwidth_ = static_cast<int>(HalfBandwidth(stiffness_));
    band_.resize(static_cast<std::size_t>(half_bandwidth_ + 1) * static_cast<std::size_t>(stiffness_.rows()));
  } else {
    shifted_ = stiffness_;
    factors_->amd.analyzePattern(shifted_);
  }
}

void ShiftedCholesky::SetStiffness(const SparseMat& stiffness) {
  const profile::Scope scope("solver: Cholesky setup");
  if (!SamePattern(stiffness, first_outer_, first_inner_)) {
    Build(stiffness);
    return;
  }
  factorized_ = false;
  if (by_blocks_) {
    block_stiffness_.Assign(stiffness.valuePtr());
    block_modified_ = false;
    return;
  }
  const double* h = stiffness.valuePtr();
  double* out = stiffness_.valuePtr();
  for (Index k = 0; k < std::ssize(from_entry_); ++k) {
    const int a = from_entry_[k], b = from_transposed_[k];
    out[k] = 0.5 * ((a >= 0 ? h[a] : 0.0) + (b >= 0 ? h[b] : 0.0));
  }
  original_.assign(out, out + stiffness_.nonZeros());
}

VecX ShiftedCholesky::StiffnessTimes(const VecX& x) const {
  return by_blocks_ ? block_stiffness_.Multiply(x) : VecX(stiffness_ * x);
}

VecX ShiftedCholesky::MetricTimes(const VecX& x) const {
  // M's own pattern, summed as the union pattern was (its extra entries are zeros): the trust
  // region's norms to the last bit as before (a step's length decides its acceptance, and a
  // hook-loaded string's solve, tests/analyses/bit_bottom_static_test.cpp, is that sensitive).
  return metric_runs_.Multiply(metric_given_, x);
}

ShiftedCholesky::~ShiftedCholesky() = default;
ShiftedCholesky::ShiftedCholesky(ShiftedCholesky&&) noexcept = default;
ShiftedCholesky& ShiftedCholesky::operator=(ShiftedCholesky&&) noexcept = default;

bool ShiftedCholesky::Factorize(double shift) {
  const profile::Scope scope("solver: Cholesky factorization");
  ++count_;
  const double* h = stiffness_.valuePtr();
  const double* m = metric_.valuePtr();
  const int* outer = stiffness_.outerIndexPtr();
  const int* inner = stiffness_.innerIndexPtr();
  const int n = static_cast<int>(stiffness_.rows());  // LAPACK's int
  bool ok = false;
  if (by_blocks_) {
    ok = block_factors_.Factorize(block_stiffness_, &block_metric_, shift, metric_coupled_);
  } else if (banded_) {
    // Lower band storage: ab(i − j, j) = A(i, j) for j ≤ i ≤ j + kd (0-based, ldab = kd + 1).
    const int ldab = half_bandwidth_ + 1;
    std::fill(band_.begin(), band_.end(), 0.0);
    for (int j = 0; j < n; ++j) {
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        const int i = inner[k];
        if (i >= j) band_[static_cast<std::size_t>(j) * ldab + (i - j)] = h[k] + shift * m[k];
      }
    }
    int info = 0;
    dpbtrf_("L", &n, &half_bandwidth_, band_.data(), &ldab, &info, 1);
    ok = info == 0;
  } else {
    double* a = shifted_.valuePtr();
    for (Eigen::Index k = 0; k < shifted_.nonZeros(); ++k) a[k] = h[k] + shift * m[k];
    factors_->amd.factorize(shifted_);
    ok = factors_->amd.info() == Eigen::Success;
  }
  // A failed factorization leaves the factors unusable: the last good one is gone too.
  factorized_ = ok;
  if (ok) shift_ = shift;
  return ok;
}

VecX ShiftedCholesky::Solve(const VecX& rhs) const {
  const profile::Scope scope("solver: Cholesky solve");
  if (!factorized_) throw LogicError("ShiftedCholesky::Solve: no positive definite factorization held");
  if (by_blocks_) {
    VecX x = rhs;
    block_factors_.SolveInPlace(x);
    return x;
  }
  if (!banded_) return factors_->amd.solve(rhs);
  VecX x = rhs;
  const int n = static_cast<int>(x.size()), ldab = half_bandwidth_ + 1, one = 1;  // LAPACK's int
  int info = 0;
  dpbtrs_("L", &n, &half_bandwidth_, &one, band_.data(), &ldab, x.data(), &n, &info, 1);
  if (info != 0) throw LogicError(fmt::format("ShiftedCholesky::Solve: dpbtrs info {}", info));
  return x;
}

void ShiftedCholesky::AddOuterProduct(const std::vector<Index>& indices, const std::vector<double>& values,
                                      double scale) {
  factorized_ = false;
  if (by_blocks_) {
    if (!block_modified_) block_original_ = block_stiffness_.values();
    block_modified_ = true;
    block_stiffness_.AddOuterProduct(indices, values, scale);
    return;
  }
  for (Index j = 0; j < std::ssize(indices); ++j) {
    for (Index i = 0; i < std::ssize(indices); ++i) {
      stiffness_.coeffRef(indices[i], indices[j]) += scale * values[i] * values[j];
    }
  }
  if (stiffness_.nonZeros() != std::ssize(original_) || !stiffness_.isCompressed()) {
    throw LogicError("ShiftedCholesky::AddOuterProduct: an entry outside the pattern");
  }
  factorized_ = false;
}

void ShiftedCholesky::RestoreStiffness() {
  factorized_ = false;
  if (by_blocks_) {
    if (block_modified_) std::swap(block_stiffness_.values(), block_original_);
    block_modified_ = false;
    return;
  }
  std::copy(original_.begin(), original_.end(), stiffness_.valuePtr());
  factorized_ = false;
}

}  // namespace drillflex::solvers
