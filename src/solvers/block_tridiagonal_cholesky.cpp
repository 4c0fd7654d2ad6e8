#include "solvers/block_tridiagonal_cholesky.hpp"

#include <algorithm>

#include <Eigen/Cholesky>

#include "core/error.hpp"

namespace drillflex::solvers {

using BlockMap = Eigen::Map<MatX>;
using ConstBlockMap = Eigen::Map<const MatX>;

bool BlockTridiagonalCholesky::Analyze(const SparseMat& pattern, const std::vector<Index>& starts) {
  factorized_ = false;
  return assembled_.Analyze(pattern, starts, false) && metric_assembled_.Analyze(pattern, starts, false);
}

bool BlockTridiagonalCholesky::Factorize(const double* values, const double* metric_values, double shift) {
  if (!assembled_.analysed()) throw LogicError("BlockTridiagonalCholesky::Factorize before Analyze");
  assembled_.Assign(values);
  if (metric_values == nullptr) return Factorize(assembled_, nullptr, 0.0);
  metric_assembled_.Assign(metric_values);
  return Factorize(assembled_, &metric_assembled_, shift);
}

void BlockTridiagonalCholesky::Layout(const std::vector<Index>& starts) {
  if (starts == starts_ && !storage_.empty()) return;
  starts_ = starts;
  const Index blocks = std::ssize(starts) - 1;
  diagonal_.resize(blocks);
  coupling_.resize(blocks > 0 ? blocks - 1 : 0);
  Index offset = 0;
  for (Index k = 0; k < blocks; ++k) {
    diagonal_[k] = offset;
    offset += size(k) * size(k);
    if (k + 1 < blocks) {
      coupling_[k] = offset;
      offset += size(k) * size(k + 1);
    }
  }
  storage_.assign(offset, 0.0);
}

bool BlockTridiagonalCholesky::Factorize(const SymmetricBlockMatrix& stiffness, const SymmetricBlockMatrix* metric,
                                         double shift, bool metric_coupled) {
  if (!stiffness.analysed() || (metric != nullptr && !metric->SameLayout(stiffness))) {
    throw LogicError("BlockTridiagonalCholesky::Factorize: a matrix not laid out in blocks, or two layouts");
  }
  factorized_ = false;
  Layout(stiffness.starts());
  double* data = storage_.data();
  const Index count = std::ssize(diagonal_);
  for (Index k = 0; k < count; ++k) {
    BlockMap block(data + diagonal_[k], size(k), size(k));  // D_k + σ M_k
    block = ConstBlockMap(stiffness.diagonal_block(k), size(k), size(k));
    if (metric != nullptr) block += shift * ConstBlockMap(metric->diagonal_block(k), size(k), size(k));
    if (k > 0) {  // S_k = D_k − W_{k−1} W_{k−1}ᵀ = D_k − T_{k−1}ᵀ T_{k−1} (lower triangle)
      const ConstBlockMap previous(data + coupling_[k - 1], size(k - 1), size(k));
      block.selfadjointView<Eigen::Lower>().rankUpdate(previous.transpose(), -1.0);
    }
    const Eigen::LLT<Eigen::Ref<MatX>> factor(block);  // in place: C_k in the lower triangle
    if (factor.info() != Eigen::Success) return false;
    if (k + 1 < count) {  // T_k = C_k⁻¹ L_kᵀ (L_k + σ M's block below the diagonal)
      BlockMap coupling(data + coupling_[k], size(k), size(k + 1));
      coupling = ConstBlockMap(stiffness.below_block(k), size(k + 1), size(k)).transpose();
      if (metric != nullptr && metric_coupled) {
        coupling += shift * ConstBlockMap(metric->below_block(k), size(k + 1), size(k)).transpose();
      }
      block.triangularView<Eigen::Lower>().solveInPlace(coupling);
    }
  }
  factorized_ = true;
  return true;
}

void BlockTridiagonalCholesky::SolveInPlace(VecX& x) const {
  if (!factorized_) throw LogicError("BlockTridiagonalCholesky::SolveInPlace without a factorization");
  const double* data = storage_.data();
  const Index count = std::ssize(diagonal_);
  // Down the string: y_k = C_k⁻¹ (b_k − T_{k−1}ᵀ y_{k−1}).
  for (Index k = 0; k < count; ++k) {
    auto part = x.segment(starts_[k], size(k));
    if (k > 0) {
      part.noalias() -= ConstBlockMap(data + coupling_[k - 1], size(k - 1), size(k)).transpose() *
                        x.segment(starts_[k - 1], size(k - 1));
    }
    ConstBlockMap(data + diagonal_[k], size(k), size(k)).triangularView<Eigen::Lower>().solveInPlace(part);
  }
  // Back up: x_k = C_k⁻ᵀ (y_k − T_k x_{k+1}).
  for (Index k = count; k-- > 0;) {
    auto part = x.segment(starts_[k], size(k));
    if (k + 1 < count) {
      part.noalias() -= ConstBlockMap(data + coupling_[k], size(k), size(k + 1)) * x.segment(starts_[k + 1], size(k + 1));
    }
    ConstBlockMap(data + diagonal_[k], size(k), size(k)).transpose().triangularView<Eigen::Upper>().solveInPlace(part);
  }
}

}  // namespace drillflex::solvers
