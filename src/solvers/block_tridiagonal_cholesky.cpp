#include "solvers/block_tridiagonal_cholesky.hpp"

#include <algorithm>

#include <Eigen/Cholesky>

#include "core/error.hpp"
#include "solvers/two_sweeps.hpp"

namespace drillflex::solvers {

using BlockMap = Eigen::Map<MatX>;
using ConstBlockMap = Eigen::Map<const MatX>;

bool BlockTridiagonalCholesky::Analyze(const SparseMat& pattern, const std::vector<Eigen::Index>& starts) {
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

void BlockTridiagonalCholesky::Layout(const std::vector<Eigen::Index>& starts) {
  if (starts == starts_ && !storage_.empty()) return;
  starts_ = starts;
  const std::size_t blocks = starts.size() - 1;
  diagonal_.resize(blocks);
  coupling_.resize(blocks > 0 ? blocks - 1 : 0);
  std::size_t offset = 0;
  for (std::size_t k = 0; k < blocks; ++k) {
    diagonal_[k] = offset;
    offset += static_cast<std::size_t>(size(k) * size(k));
    if (k + 1 < blocks) {
      coupling_[k] = offset;
      offset += static_cast<std::size_t>(size(k) * size(k + 1));
    }
  }
  storage_.assign(offset, 0.0);
  middle_ = blocks / 2;
}

bool BlockTridiagonalCholesky::Factorize(const SymmetricBlockMatrix& stiffness, const SymmetricBlockMatrix* metric,
                                         double shift, bool metric_coupled) {
  if (!stiffness.analysed() || (metric != nullptr && !metric->SameLayout(stiffness))) {
    throw LogicError("BlockTridiagonalCholesky::Factorize: a matrix not laid out in blocks, or two layouts");
  }
  factorized_ = false;
  Layout(stiffness.starts());
  double* data = storage_.data();
  const std::size_t count = diagonal_.size(), m = middle_;
  // D_k + σ M_k into C_k's place; L_k (+ σ M's) transposed into the coupling's place: L_kᵀ from the
  // top, L_k from the bottom.
  auto load_diagonal = [&](std::size_t k) {
    BlockMap block(data + diagonal_[k], size(k), size(k));
    block = ConstBlockMap(stiffness.diagonal_block(k), size(k), size(k));
    if (metric != nullptr) block += shift * ConstBlockMap(metric->diagonal_block(k), size(k), size(k));
    return block;
  };
  const bool coupled = metric != nullptr && metric_coupled;
  auto below = [&](const SymmetricBlockMatrix& matrix, std::size_t k) {  // L_k of a matrix (n_{k+1} × n_k)
    return ConstBlockMap(matrix.below_block(k), size(k + 1), size(k));
  };
  bool top_ok = true, bottom_ok = true;
  RunBoth(
      count >= kParallelBlocks,
      [&] {  // k = 0 … m−1: S_k = D_k − T_{k−1}ᵀ T_{k−1}, C_k C_kᵀ = S_k, T_k = C_k⁻¹ L_kᵀ
        for (std::size_t k = 0; k < m && top_ok; ++k) {
          BlockMap block = load_diagonal(k);
          if (k > 0) {
            const ConstBlockMap previous(data + coupling_[k - 1], size(k - 1), size(k));
            block.selfadjointView<Eigen::Lower>().rankUpdate(previous.transpose(), -1.0);
          }
          const Eigen::LLT<Eigen::Ref<MatX>> factor(block);  // in place: C_k in the lower triangle
          if (factor.info() != Eigen::Success) {
            top_ok = false;
            break;
          }
          BlockMap coupling(data + coupling_[k], size(k), size(k + 1));
          coupling = below(stiffness, k).transpose();
          if (coupled) coupling += shift * below(*metric, k).transpose();
          block.triangularView<Eigen::Lower>().solveInPlace(coupling);
        }
      },
      [&] {  // k = N−1 … m+1: S_k = D_k − V_{k+1}ᵀ V_{k+1}, C_k C_kᵀ = S_k, V_k = C_k⁻¹ L_{k−1}
        for (std::size_t k = count - 1; k > m && bottom_ok; --k) {
          BlockMap block = load_diagonal(k);
          if (k + 1 < count) {
            const ConstBlockMap previous(data + coupling_[k], size(k + 1), size(k));
            block.selfadjointView<Eigen::Lower>().rankUpdate(previous.transpose(), -1.0);
          }
          const Eigen::LLT<Eigen::Ref<MatX>> factor(block);
          if (factor.info() != Eigen::Success) {
            bottom_ok = false;
            break;
          }
          BlockMap coupling(data + coupling_[k - 1], size(k), size(k - 1));
          coupling = below(stiffness, k - 1);
          if (coupled) coupling += shift * below(*metric, k - 1);
          block.triangularView<Eigen::Lower>().solveInPlace(coupling);
        }
      });
  if (!top_ok || !bottom_ok) return false;
  // The middle block last: S_m = D_m − T_{m−1}ᵀ T_{m−1} − V_{m+1}ᵀ V_{m+1}.
  BlockMap block = load_diagonal(m);
  if (m > 0) {
    block.selfadjointView<Eigen::Lower>().rankUpdate(
        ConstBlockMap(data + coupling_[m - 1], size(m - 1), size(m)).transpose(), -1.0);
  }
  if (m + 1 < count) {
    block.selfadjointView<Eigen::Lower>().rankUpdate(
        ConstBlockMap(data + coupling_[m], size(m + 1), size(m)).transpose(), -1.0);
  }
  const Eigen::LLT<Eigen::Ref<MatX>> factor(block);
  if (factor.info() != Eigen::Success) return false;
  factorized_ = true;
  return true;
}

void BlockTridiagonalCholesky::SolveInPlace(VecX& x) const {
  if (!factorized_) throw LogicError("BlockTridiagonalCholesky::SolveInPlace without a factorization");
  const double* data = storage_.data();
  const std::size_t count = diagonal_.size(), m = middle_;
  const auto part = [&](std::size_t k) { return x.segment(starts_[k], size(k)); };
  const auto lower = [&](std::size_t k) {
    return ConstBlockMap(data + diagonal_[k], size(k), size(k)).triangularView<Eigen::Lower>();
  };
  const auto upper = [&](std::size_t k) {  // C_kᵀ
    return ConstBlockMap(data + diagonal_[k], size(k), size(k)).transpose().triangularView<Eigen::Upper>();
  };
  const auto top = [&](std::size_t k) { return ConstBlockMap(data + coupling_[k], size(k), size(k + 1)); };  // T_k
  const auto bottom = [&](std::size_t k) { return ConstBlockMap(data + coupling_[k - 1], size(k), size(k - 1)); };  // V_k
  const bool parallel = count >= kParallelBlocks;
  // Forward: y_k = C_k⁻¹ (b_k − T_{k−1}ᵀ y_{k−1}) down to m − 1, y_k = C_k⁻¹ (b_k − V_{k+1}ᵀ y_{k+1})
  // up to m + 1, then y_m = C_m⁻¹ (b_m − T_{m−1}ᵀ y_{m−1} − V_{m+1}ᵀ y_{m+1}).
  RunBoth(
      parallel,
      [&] {
        for (std::size_t k = 0; k < m; ++k) {
          if (k > 0) part(k).noalias() -= top(k - 1).transpose() * part(k - 1);
          lower(k).solveInPlace(part(k));
        }
      },
      [&] {
        for (std::size_t k = count - 1; k > m; --k) {
          if (k + 1 < count) part(k).noalias() -= bottom(k + 1).transpose() * part(k + 1);
          lower(k).solveInPlace(part(k));
        }
      });
  if (m > 0) part(m).noalias() -= top(m - 1).transpose() * part(m - 1);
  if (m + 1 < count) part(m).noalias() -= bottom(m + 1).transpose() * part(m + 1);
  lower(m).solveInPlace(part(m));
  // Back: x_m = C_m⁻ᵀ y_m, x_k = C_k⁻ᵀ (y_k − T_k x_{k+1}) below m, x_k = C_k⁻ᵀ (y_k − V_k x_{k−1}) above.
  upper(m).solveInPlace(part(m));
  RunBoth(
      parallel,
      [&] {
        for (std::size_t k = m; k-- > 0;) {
          part(k).noalias() -= top(k) * part(k + 1);
          upper(k).solveInPlace(part(k));
        }
      },
      [&] {
        for (std::size_t k = m + 1; k < count; ++k) {
          part(k).noalias() -= bottom(k) * part(k - 1);
          upper(k).solveInPlace(part(k));
        }
      });
}

}  // namespace drillflex::solvers
