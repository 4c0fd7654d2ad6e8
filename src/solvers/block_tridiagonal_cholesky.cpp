#include "solvers/block_tridiagonal_cholesky.hpp"

#include <algorithm>

#include <Eigen/Cholesky>

#include "core/error.hpp"

namespace drillflex::solvers {

using BlockMap = Eigen::Map<MatX>;
using ConstBlockMap = Eigen::Map<const MatX>;

bool BlockTridiagonalCholesky::Analyze(const SparseMat& pattern, const std::vector<Eigen::Index>& starts) {
  analysed_ = factorized_ = false;
  const Eigen::Index n = pattern.rows();
  if (!pattern.isCompressed() || pattern.cols() != n || starts.size() < 2 || starts.front() != 0 ||
      starts.back() != n || !std::is_sorted(starts.begin(), starts.end())) {
    return false;
  }
  starts_ = starts;
  const std::size_t blocks = starts.size() - 1;
  std::vector<std::size_t> block_of(static_cast<std::size_t>(n), 0);
  for (std::size_t k = 0; k < blocks; ++k) {
    if (size(k) <= 0) return false;
    for (Eigen::Index i = starts[k]; i < starts[k + 1]; ++i) block_of[static_cast<std::size_t>(i)] = k;
  }
  diagonal_.resize(blocks);
  below_.resize(blocks > 0 ? blocks - 1 : 0);
  coupling_.resize(below_.size());
  std::size_t offset = 0;
  for (std::size_t k = 0; k < blocks; ++k) {
    diagonal_[k] = offset;
    offset += static_cast<std::size_t>(size(k) * size(k));
    if (k + 1 < blocks) {
      below_[k] = offset;
      offset += static_cast<std::size_t>(size(k + 1) * size(k));
    }
  }
  assembled_size_ = offset;
  for (std::size_t k = 0; k + 1 < blocks; ++k) {
    coupling_[k] = offset;
    offset += static_cast<std::size_t>(size(k) * size(k + 1));
  }
  storage_.assign(offset, 0.0);
  entry_.assign(static_cast<std::size_t>(pattern.nonZeros()), -1);
  for (Eigen::Index j = 0; j < n; ++j) {
    const std::size_t bj = block_of[static_cast<std::size_t>(j)];
    for (int p = pattern.outerIndexPtr()[j]; p < pattern.outerIndexPtr()[j + 1]; ++p) {
      const Eigen::Index i = pattern.innerIndexPtr()[p];
      if (i < j) continue;  // the upper triangle mirrors the lower one
      const std::size_t bi = block_of[static_cast<std::size_t>(i)];
      if (bi != bj && bi != bj + 1) return false;
      const Eigen::Index row = i - starts[bi], column = j - starts[bj];
      const std::size_t base = bi == bj ? diagonal_[bj] : below_[bj];
      entry_[static_cast<std::size_t>(p)] =
          static_cast<std::ptrdiff_t>(base + static_cast<std::size_t>(column * size(bi) + row));
    }
  }
  analysed_ = true;
  return true;
}

bool BlockTridiagonalCholesky::Factorize(const double* values, const double* metric_values, double shift) {
  if (!analysed_) throw LogicError("BlockTridiagonalCholesky::Factorize before Analyze");
  factorized_ = false;
  std::fill(storage_.begin(), storage_.begin() + static_cast<std::ptrdiff_t>(assembled_size_), 0.0);
  double* data = storage_.data();
  for (std::size_t p = 0; p < entry_.size(); ++p) {
    if (entry_[p] < 0) continue;
    data[entry_[p]] = values[p] + (metric_values != nullptr ? shift * metric_values[p] : 0.0);
  }
  const std::size_t count = diagonal_.size();
  for (std::size_t k = 0; k < count; ++k) {
    BlockMap block(data + diagonal_[k], size(k), size(k));
    if (k > 0) {  // S_k = D_k − W_{k−1} W_{k−1}ᵀ = D_k − T_{k−1}ᵀ T_{k−1} (lower triangle)
      const ConstBlockMap previous(data + coupling_[k - 1], size(k - 1), size(k));
      block.selfadjointView<Eigen::Lower>().rankUpdate(previous.transpose(), -1.0);
    }
    const Eigen::LLT<Eigen::Ref<MatX>> factor(block);  // in place: C_k in the lower triangle
    if (factor.info() != Eigen::Success) return false;
    if (k + 1 < count) {  // T_k = C_k⁻¹ L_kᵀ
      BlockMap coupling(data + coupling_[k], size(k), size(k + 1));
      coupling = ConstBlockMap(data + below_[k], size(k + 1), size(k)).transpose();
      block.triangularView<Eigen::Lower>().solveInPlace(coupling);
    }
  }
  factorized_ = true;
  return true;
}

void BlockTridiagonalCholesky::SolveInPlace(VecX& x) const {
  if (!factorized_) throw LogicError("BlockTridiagonalCholesky::SolveInPlace without a factorization");
  const double* data = storage_.data();
  const std::size_t count = diagonal_.size();
  // Down the string: y_k = C_k⁻¹ (b_k − T_{k−1}ᵀ y_{k−1}).
  for (std::size_t k = 0; k < count; ++k) {
    auto part = x.segment(starts_[k], size(k));
    if (k > 0) {
      part.noalias() -= ConstBlockMap(data + coupling_[k - 1], size(k - 1), size(k)).transpose() *
                        x.segment(starts_[k - 1], size(k - 1));
    }
    ConstBlockMap(data + diagonal_[k], size(k), size(k)).triangularView<Eigen::Lower>().solveInPlace(part);
  }
  // Back up: x_k = C_k⁻ᵀ (y_k − T_k x_{k+1}).
  for (std::size_t k = count; k-- > 0;) {
    auto part = x.segment(starts_[k], size(k));
    if (k + 1 < count) {
      part.noalias() -= ConstBlockMap(data + coupling_[k], size(k), size(k + 1)) * x.segment(starts_[k + 1], size(k + 1));
    }
    ConstBlockMap(data + diagonal_[k], size(k), size(k)).transpose().triangularView<Eigen::Upper>().solveInPlace(part);
  }
}

}  // namespace drillflex::solvers
