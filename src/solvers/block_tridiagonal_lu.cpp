#include "solvers/block_tridiagonal_lu.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include <fmt/format.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/error.hpp"

namespace drillflex::solvers {

template <typename Scalar>
bool BlockTridiagonalLuOf<Scalar>::Analyze(Index rows, Index cols,
                                 const std::vector<std::pair<Index, Index>>& entries,
                                 std::vector<Index> starts) {
  analyzed_ = false;
  const Index n = rows;
  if (cols != n || starts.size() < 2 || starts.front() != 0 || starts.back() != n) return false;
  for (Index k = 0; k + 1 < std::ssize(starts); ++k) {
    if (starts[k + 1] <= starts[k]) return false;
  }
  starts_ = std::move(starts);
  const Index blocks = std::ssize(starts_) - 1;
  diagonal_at_.assign(blocks, 0);
  upper_at_.assign(blocks - 1, 0);
  lower_at_.assign(blocks - 1, 0);
  Index size = 0;
  for (Index k = 0; k < blocks; ++k) {
    diagonal_at_[k] = size;
    size += BlockSize(k) * BlockSize(k);
    if (k + 1 < blocks) {
      upper_at_[k] = size;
      size += BlockSize(k) * BlockSize(k + 1);
      lower_at_[k] = size;
      size += BlockSize(k + 1) * BlockSize(k);
    }
  }
  std::vector<Index> block_of(n);
  for (Index k = 0; k < blocks; ++k) {
    std::fill(block_of.begin() + starts_[k], block_of.begin() + starts_[k + 1], k);
  }
  slot_offsets_.clear();
  slot_offsets_.reserve(entries.size());
  for (const auto& [row, col] : entries) {
    const auto bi = block_of[row];
    const auto bj = block_of[col];
    // Column major within the block, whose rows are those of block bi.
    const Index at = (row - starts_[bi]) + (col - starts_[bj]) * BlockSize(bi);
    if (bi == bj) {
      slot_offsets_.push_back(diagonal_at_[bi] + at);
    } else if (bi == bj + 1) {
      slot_offsets_.push_back(lower_at_[bj] + at);
    } else if (bi + 1 == bj) {
      slot_offsets_.push_back(upper_at_[bi] + at);
    } else {
      return false;
    }
  }
  // Consecutive entries that land in consecutive slots (a column's rows within one block) as runs.
  runs_.clear();
  for (Index s = 0; s < std::ssize(slot_offsets_); ++s) {
    if (!runs_.empty() && runs_.back().from + runs_.back().length == s &&
        runs_.back().to + runs_.back().length == slot_offsets_[s]) {
      ++runs_.back().length;
    } else {
      runs_.push_back({s, slot_offsets_[s], 1});
    }
  }
  storage_.assign(size, Scalar(0.0));
  middle_ = blocks / 2;
  coupled_.assign(blocks, Matrix());
  factors_.assign(blocks, SmallLu<Scalar>());
  for (Index k = 0; k < middle_; ++k) coupled_[k].resize(BlockSize(k), BlockSize(k + 1));
  for (Index k = middle_ + 1; k < blocks; ++k) coupled_[k].resize(BlockSize(k), BlockSize(k - 1));
  analyzed_ = true;
  return true;
}

namespace {

double Magnitude(double a) { return std::abs(a); }
double Magnitude(const std::complex<double>& z) { return std::abs(z.real()) + std::abs(z.imag()); }

}  // namespace

template <typename Scalar>
std::pair<double, double> BlockTridiagonalLuOf<Scalar>::Norms() const {
  double row_sum_norm = 0.0, largest2 = 0.0;  // max |a|² (no hypot per entry)
  Eigen::VectorXd rows;
  auto add = [&](const ConstBlock& block) {
    for (Index j = 0; j < block.cols(); ++j) {
      rows += block.col(j).unaryExpr([](const Scalar& a) { return Magnitude(a); });
      largest2 = std::max(largest2, block.col(j).cwiseAbs2().maxCoeff());
    }
  };
  for (Index k = 0; k < std::ssize(diagonal_at_); ++k) {
    rows.setZero(BlockSize(k));
    add(Diagonal(k));
    if (k > 0) add(Lower(k - 1));
    if (k + 1 < std::ssize(diagonal_at_)) add(Upper(k));
    row_sum_norm = std::max(row_sum_norm, rows.maxCoeff());
  }
  return {row_sum_norm, std::sqrt(largest2)};
}

template <typename Scalar>
void BlockTridiagonalLuOf<Scalar>::Factorize(const Sparse& matrix) {
  if (!analyzed_ || matrix.nonZeros() != std::ssize(slot_offsets_) || !matrix.isCompressed()) {
    throw LogicError(fmt::format("BlockTridiagonalLu::Factorize: the matrix ({} entries) does not have the analysed "
                                 "pattern ({} entries)", matrix.nonZeros(), slot_offsets_.size()));
  }
  const Scalar* values = matrix.valuePtr();
  for (const Run& run : runs_) std::copy_n(values + run.from, run.length, storage_.data() + run.to);
  Factorize();
}

namespace {

// The smallest |u_jj|² of an LU factorization (no hypot per pivot).
template <typename Lu>
double SmallestPivot2(const Lu& lu) {
  double smallest2 = std::numeric_limits<double>::infinity();
  const auto pivots = lu.matrixLU().diagonal();
  for (Index j = 0; j < pivots.size(); ++j) smallest2 = std::min(smallest2, std::norm(pivots(j)));
  return smallest2;
}

// Below this many blocks both sweeps run on the calling thread: a thread's start costs more.
constexpr Index kParallelBlocks = 16;

// Runs the two independent sweeps, side by side on two OpenMP threads when `parallel` and the caller
// allows more than one thread, one after the other otherwise; an exception in either is rethrown here.
template <typename First, typename Second>
void RunBoth(bool parallel, const First& first, const Second& second) {
#ifdef _OPENMP
  parallel = parallel && omp_get_max_threads() > 1;
#else
  static_cast<void>(parallel);  // without OpenMP the pragma below is ignored: one after the other
#endif
  std::exception_ptr failure;
  auto guarded = [&failure](const auto& task) {
    try {
      task();
    } catch (...) {
#pragma omp critical(drillflex_block_lu_failure)
      if (!failure) failure = std::current_exception();
    }
  };
#pragma omp parallel sections num_threads(2) if (parallel)
  {
#pragma omp section
    guarded(first);
#pragma omp section
    guarded(second);
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

template <typename Scalar>
double BlockTridiagonalLuOf<Scalar>::FactorizeFromTop() {  // S_0 … S_{m−1} and X_k
  double smallest2 = std::numeric_limits<double>::infinity();
  for (Index k = 0; k < middle_; ++k) {
    if (k == 0) {
      factors_[0].compute(Diagonal(0));
    } else {
      top_schur_ = Diagonal(k);
      top_schur_.noalias() -= Lower(k - 1).lazyProduct(coupled_[k - 1]);
      factors_[k].compute(top_schur_);
    }
    smallest2 = std::min(smallest2, SmallestPivot2(factors_[k]));
    coupled_[k] = Upper(k);
    factors_[k].solveInPlace(coupled_[k]);
  }
  return smallest2;
}

template <typename Scalar>
double BlockTridiagonalLuOf<Scalar>::FactorizeFromBottom() {  // T_{N−1} … T_{m+1} and Y_k
  double smallest2 = std::numeric_limits<double>::infinity();
  const Index last = std::ssize(diagonal_at_) - 1;
  for (Index k = last; k > middle_; --k) {
    if (k == last) {
      factors_[k].compute(Diagonal(k));
    } else {
      bottom_schur_ = Diagonal(k);
      bottom_schur_.noalias() -= Upper(k).lazyProduct(coupled_[k + 1]);
      factors_[k].compute(bottom_schur_);
    }
    smallest2 = std::min(smallest2, SmallestPivot2(factors_[k]));
    coupled_[k] = Lower(k - 1);
    factors_[k].solveInPlace(coupled_[k]);
  }
  return smallest2;
}

template <typename Scalar>
void BlockTridiagonalLuOf<Scalar>::Factorize() {
  if (!analyzed_) throw LogicError("BlockTridiagonalLu::Factorize before a successful Analyze");
  const Index blocks = std::ssize(diagonal_at_), m = middle_;
  double top2 = std::numeric_limits<double>::infinity(), bottom2 = top2;
  RunBoth(blocks >= kParallelBlocks, [&] { top2 = FactorizeFromTop(); }, [&] { bottom2 = FactorizeFromBottom(); });
  top_schur_ = Diagonal(m);  // S_m = D_m − L_{m−1} X_{m−1} − U_m Y_{m+1}
  if (m > 0) top_schur_.noalias() -= Lower(m - 1).lazyProduct(coupled_[m - 1]);
  if (m + 1 < blocks) top_schur_.noalias() -= Upper(m).lazyProduct(coupled_[m + 1]);
  factors_[m].compute(top_schur_);
  smallest_pivot_ = std::sqrt(std::min({top2, bottom2, SmallestPivot2(factors_[m])}));
}

template <typename Scalar>
template <typename Target>
void BlockTridiagonalLuOf<Scalar>::SolveColumns(Target& x) const {
  const Index blocks = std::ssize(diagonal_at_), m = middle_;
  const auto rows = [&](Index k) { return x.middleRows(starts_[k], BlockSize(k)); };
  const bool parallel = blocks >= kParallelBlocks;
  RunBoth(
      parallel,
      [&] {  // w_k = S_k⁻¹ (f_k − L_{k−1} w_{k−1}), k < m
        for (Index k = 0; k < m; ++k) {
          auto block = rows(k);
          if (k > 0) block.noalias() -= Lower(k - 1) * rows(k - 1);
          factors_[k].solveInPlace(block);
        }
      },
      [&] {  // z_k = T_k⁻¹ (f_k − U_k z_{k+1}), k > m
        for (Index k = blocks - 1; k > m; --k) {
          auto block = rows(k);
          if (k + 1 < blocks) block.noalias() -= Upper(k) * rows(k + 1);
          factors_[k].solveInPlace(block);
        }
      });
  auto middle = rows(m);  // x_m = S_m⁻¹ (f_m − L_{m−1} w_{m−1} − U_m z_{m+1})
  if (m > 0) middle.noalias() -= Lower(m - 1) * rows(m - 1);
  if (m + 1 < blocks) middle.noalias() -= Upper(m) * rows(m + 1);
  factors_[m].solveInPlace(middle);
  RunBoth(
      parallel,
      [&] {  // x_k = w_k − X_k x_{k+1}, k < m
        for (Index k = m; k-- > 0;) rows(k).noalias() -= coupled_[k] * rows(k + 1);
      },
      [&] {  // x_k = z_k − Y_k x_{k−1}, k > m
        for (Index k = m + 1; k < blocks; ++k) rows(k).noalias() -= coupled_[k] * rows(k - 1);
      });
}

template <typename Scalar>
typename BlockTridiagonalLuOf<Scalar>::Matrix BlockTridiagonalLuOf<Scalar>::Solve(const Matrix& rhs) const {
  if (!analyzed_ || rhs.rows() != starts_.back()) {
    throw LogicError("BlockTridiagonalLu::Solve: no factorization, or a right-hand side of the wrong size");
  }
  Matrix x = rhs;
  SolveColumns(x);
  return x;
}

template <typename Scalar>
void BlockTridiagonalLuOf<Scalar>::SolveInPlace(Vector& x) const {
  if (!analyzed_ || x.size() != starts_.back()) {
    throw LogicError("BlockTridiagonalLu::SolveInPlace: no factorization, or a right-hand side of the wrong size");
  }
  SolveColumns(x);
}

template <typename Scalar>
typename BlockTridiagonalLuOf<Scalar>::Matrix BlockTridiagonalLuOf<Scalar>::Multiply(const Matrix& x) const {
  if (!analyzed_ || x.rows() != starts_.back()) throw LogicError("BlockTridiagonalLu::Multiply: wrong size or no pattern");
  Matrix y(x.rows(), x.cols());
  const Index blocks = std::ssize(diagonal_at_);
  for (Index k = 0; k < blocks; ++k) {
    auto row = y.middleRows(starts_[k], BlockSize(k));
    row.noalias() = Diagonal(k) * x.middleRows(starts_[k], BlockSize(k));
    if (k > 0) row.noalias() += Lower(k - 1) * x.middleRows(starts_[k - 1], BlockSize(k - 1));
    if (k + 1 < blocks) row.noalias() += Upper(k) * x.middleRows(starts_[k + 1], BlockSize(k + 1));
  }
  return y;
}

template class BlockTridiagonalLuOf<double>;
template class BlockTridiagonalLuOf<std::complex<double>>;

}  // namespace drillflex::solvers
