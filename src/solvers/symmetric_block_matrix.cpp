#include "solvers/symmetric_block_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/error.hpp"

namespace drillflex::solvers {

using BlockMap = Eigen::Map<const MatX>;
constexpr Index kOutside = -1;
constexpr std::uint32_t kNotRead = std::numeric_limits<std::uint32_t>::max();

bool SymmetricBlockMatrix::Analyze(const SparseMat& pattern, const std::vector<Index>& starts,
                                   bool symmetrize) {
  analysed_ = false;
  const Index n = pattern.rows();
  if (!pattern.isCompressed() || pattern.cols() != n || starts.size() < 2 || starts.front() != 0 ||
      starts.back() != n || !std::is_sorted(starts.begin(), starts.end())) {
    return false;
  }
  starts_ = starts;
  const Index blocks = std::ssize(starts) - 1;
  block_of_.assign(n, 0);
  diagonal_.resize(blocks);
  below_.resize(blocks > 0 ? blocks - 1 : 0);
  Index offset = 0;
  for (Index k = 0; k < blocks; ++k) {
    if (block_size(k) <= 0) return false;
    for (Index i = starts[k]; i < starts[k + 1]; ++i) block_of_[i] = k;
    diagonal_[k] = offset;
    offset += block_size(k) * block_size(k);
    if (k + 1 < blocks) {
      below_[k] = offset;
      offset += block_size(k + 1) * block_size(k);
    }
  }
  if (offset >= kNotRead || pattern.nonZeros() >= kNotRead) return false;
  values_.assign(offset, 0.0);
  symmetrize_ = symmetrize;
  slot_.assign(pattern.nonZeros(), kNotRead);
  diagonal_entries_.clear();
  for (Index j = 0; j < n; ++j) {
    for (int p = pattern.outerIndexPtr()[j]; p < pattern.outerIndexPtr()[j + 1]; ++p) {
      const Index i = pattern.innerIndexPtr()[p];
      if (i < j && !symmetrize) continue;  // the upper triangle mirrors the lower one
      const Index slot = Slot(std::max(i, j), std::min(i, j));
      if (slot == kOutside) return false;
      slot_[p] = static_cast<std::uint32_t>(slot);
      if (symmetrize && i == j) diagonal_entries_.push_back(static_cast<std::uint32_t>(p));
    }
  }
  analysed_ = true;
  return true;
}

Index SymmetricBlockMatrix::Slot(Index row, Index column) const {
  const Index bi = block_of_[row], bj = block_of_[column];
  if (bi != bj && bi != bj + 1) return kOutside;
  const Index base = bi == bj ? diagonal_[bj] : below_[bj];
  return base + (column - starts_[bj]) * block_size(bi) + (row - starts_[bi]);
}

void SymmetricBlockMatrix::Assign(const double* values) {
  if (!analysed_) throw LogicError("SymmetricBlockMatrix::Assign before Analyze");
  std::fill(values_.begin(), values_.end(), 0.0);
  double* data = values_.data();
  // Halves of a symmetrized pair: 0 + ½a + ½b is ½(a + b) to the last bit (scaling by ½ is exact),
  // and a diagonal entry's two halves are the entry.
  const double weight = symmetrize_ ? 0.5 : 1.0;
  for (Index p = 0; p < std::ssize(slot_); ++p) {
    if (slot_[p] != kNotRead) data[slot_[p]] += weight * values[p];
  }
  for (const std::uint32_t p : diagonal_entries_) data[slot_[p]] += 0.5 * values[p];
}

void SymmetricBlockMatrix::AddOuterProduct(const std::vector<Index>& indices, const std::vector<double>& values,
                                           double scale) {
  for (Index b = 0; b < std::ssize(indices); ++b) {
    for (Index a = 0; a < std::ssize(indices); ++a) {
      if (indices[a] < indices[b]) continue;  // the lower triangle holds the pair
      const Index slot = Slot(indices[a], indices[b]);
      if (slot == kOutside) throw LogicError("SymmetricBlockMatrix::AddOuterProduct: an entry outside the blocks");
      values_[slot] += scale * values[a] * values[b];
    }
  }
}

VecX SymmetricBlockMatrix::Multiply(const std::vector<double>& values, const VecX& x) const {
  if (values.size() != values_.size()) throw LogicError("SymmetricBlockMatrix::Multiply: values of another layout");
  VecX y(x.size());
  const Index count = std::ssize(diagonal_);
  for (Index k = 0; k < count; ++k) {
    auto out = y.segment(starts_[k], block_size(k));
    out.noalias() = BlockMap(values.data() + diagonal_[k], block_size(k), block_size(k))
                        .selfadjointView<Eigen::Lower>() * x.segment(starts_[k], block_size(k));
    if (k > 0) {  // A(k, k−1) = L_{k−1}
      out.noalias() += BlockMap(values.data() + below_[k - 1], block_size(k), block_size(k - 1)) *
                       x.segment(starts_[k - 1], block_size(k - 1));
    }
    if (k + 1 < count) {  // A(k, k+1) = L_kᵀ
      out.noalias() += BlockMap(values.data() + below_[k], block_size(k + 1), block_size(k)).transpose() *
                       x.segment(starts_[k + 1], block_size(k + 1));
    }
  }
  return y;
}

double SymmetricBlockMatrix::LargestDiagonal() const {
  double largest = 0.0;
  for (Index k = 0; k < std::ssize(diagonal_); ++k) {
    largest = std::max(largest, BlockMap(values_.data() + diagonal_[k], block_size(k), block_size(k))
                                    .diagonal().cwiseAbs().maxCoeff());
  }
  return largest;
}

bool SymmetricBlockMatrix::BlockDiagonal() const {
  for (Index k = 0; k < std::ssize(below_); ++k) {
    const BlockMap block(values_.data() + below_[k], block_size(k + 1), block_size(k));
    if (!block.isZero(0.0)) return false;
  }
  return true;
}

}  // namespace drillflex::solvers
