#include "solvers/block_tridiagonal_lu.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"

namespace drillflex::solvers {

template <typename Scalar>
bool BlockTridiagonalLuOf<Scalar>::Analyze(Eigen::Index rows, Eigen::Index cols,
                                 const std::vector<std::pair<Eigen::Index, Eigen::Index>>& entries,
                                 std::vector<Eigen::Index> starts) {
  analyzed_ = false;
  const Eigen::Index n = rows;
  if (cols != n || starts.size() < 2 || starts.front() != 0 || starts.back() != n) return false;
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    if (starts[k + 1] <= starts[k]) return false;
  }
  starts_ = std::move(starts);
  const std::size_t blocks = starts_.size() - 1;
  diagonal_at_.assign(blocks, 0);
  upper_at_.assign(blocks - 1, 0);
  lower_at_.assign(blocks - 1, 0);
  std::size_t size = 0;
  for (std::size_t k = 0; k < blocks; ++k) {
    diagonal_at_[k] = size;
    size += static_cast<std::size_t>(BlockSize(k) * BlockSize(k));
    if (k + 1 < blocks) {
      upper_at_[k] = size;
      size += static_cast<std::size_t>(BlockSize(k) * BlockSize(k + 1));
      lower_at_[k] = size;
      size += static_cast<std::size_t>(BlockSize(k + 1) * BlockSize(k));
    }
  }
  std::vector<int> block_of(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < blocks; ++k) {
    std::fill(block_of.begin() + starts_[k], block_of.begin() + starts_[k + 1], static_cast<int>(k));
  }
  slot_offsets_.clear();
  slot_offsets_.reserve(entries.size());
  for (const auto& [row, col] : entries) {
    const auto bi = static_cast<std::size_t>(block_of[static_cast<std::size_t>(row)]);
    const auto bj = static_cast<std::size_t>(block_of[static_cast<std::size_t>(col)]);
    // Column major within the block, whose rows are those of block bi.
    const auto at = static_cast<std::size_t>((row - starts_[bi]) + (col - starts_[bj]) * BlockSize(bi));
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
  storage_.assign(size, Scalar(0.0));
  coupled_.resize(blocks - 1);
  factors_.assign(blocks, SmallLu<Scalar>());
  for (std::size_t k = 0; k + 1 < blocks; ++k) coupled_[k].resize(BlockSize(k), BlockSize(k + 1));
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
    for (Eigen::Index j = 0; j < block.cols(); ++j) {
      rows += block.col(j).unaryExpr([](const Scalar& a) { return Magnitude(a); });
      largest2 = std::max(largest2, block.col(j).cwiseAbs2().maxCoeff());
    }
  };
  for (std::size_t k = 0; k < diagonal_at_.size(); ++k) {
    rows.setZero(BlockSize(k));
    add(Diagonal(k));
    if (k > 0) add(Lower(k - 1));
    if (k + 1 < diagonal_at_.size()) add(Upper(k));
    row_sum_norm = std::max(row_sum_norm, rows.maxCoeff());
  }
  return {row_sum_norm, std::sqrt(largest2)};
}

template <typename Scalar>
void BlockTridiagonalLuOf<Scalar>::Factorize(const Sparse& matrix) {
  if (!analyzed_ || matrix.nonZeros() != static_cast<Eigen::Index>(slot_offsets_.size()) || !matrix.isCompressed()) {
    throw LogicError(fmt::format("BlockTridiagonalLu::Factorize: the matrix ({} entries) does not have the analysed "
                                 "pattern ({} entries)", matrix.nonZeros(), slot_offsets_.size()));
  }
  const Scalar* values = matrix.valuePtr();
  for (std::size_t s = 0; s < slot_offsets_.size(); ++s) storage_[slot_offsets_[s]] = values[s];
  Factorize();
}

template <typename Scalar>
void BlockTridiagonalLuOf<Scalar>::Factorize() {
  if (!analyzed_) throw LogicError("BlockTridiagonalLu::Factorize before a successful Analyze");
  double smallest2 = std::numeric_limits<double>::infinity();  // min |u_jj|², no hypot per pivot
  auto factor = [&](std::size_t k, const auto& schur) {
    factors_[k].compute(schur);
    const auto pivots = factors_[k].matrixLU().diagonal();
    for (Eigen::Index j = 0; j < pivots.size(); ++j) smallest2 = std::min(smallest2, std::norm(pivots(j)));
  };
  factor(0, Diagonal(0));
  for (std::size_t k = 0; k + 1 < diagonal_at_.size(); ++k) {
    coupled_[k] = Upper(k);
    factors_[k].solveInPlace(coupled_[k]);
    schur_ = Diagonal(k + 1);
    schur_.noalias() -= Lower(k).lazyProduct(coupled_[k]);
    factor(k + 1, schur_);
  }
  smallest_pivot_ = std::sqrt(smallest2);
}

template <typename Scalar>
typename BlockTridiagonalLuOf<Scalar>::Matrix BlockTridiagonalLuOf<Scalar>::Solve(const Matrix& rhs) const {
  if (!analyzed_ || rhs.rows() != starts_.back()) {
    throw LogicError("BlockTridiagonalLu::Solve: no factorization, or a right-hand side of the wrong size");
  }
  Matrix x = rhs;
  Matrix block;
  const std::size_t blocks = diagonal_at_.size();
  for (std::size_t k = 0; k < blocks; ++k) {  // w_k = S_k⁻¹ (f_k − L_{k−1} w_{k−1})
    block = x.middleRows(starts_[k], BlockSize(k));
    if (k > 0) block.noalias() -= Lower(k - 1) * x.middleRows(starts_[k - 1], BlockSize(k - 1));
    x.middleRows(starts_[k], BlockSize(k)) = factors_[k].solve(block);
  }
  for (std::size_t k = blocks - 1; k-- > 0;) {  // x_k = w_k − X_k x_{k+1}
    x.middleRows(starts_[k], BlockSize(k)).noalias() -= coupled_[k] * x.middleRows(starts_[k + 1], BlockSize(k + 1));
  }
  return x;
}

template <typename Scalar>
void BlockTridiagonalLuOf<Scalar>::SolveInPlace(Vector& x) const {
  if (!analyzed_ || x.size() != starts_.back()) {
    throw LogicError("BlockTridiagonalLu::SolveInPlace: no factorization, or a right-hand side of the wrong size");
  }
  const std::size_t blocks = diagonal_at_.size();
  for (std::size_t k = 0; k < blocks; ++k) {  // w_k = S_k⁻¹ (f_k − L_{k−1} w_{k−1})
    auto block = x.segment(starts_[k], BlockSize(k));
    if (k > 0) block.noalias() -= Lower(k - 1) * x.segment(starts_[k - 1], BlockSize(k - 1));
    factors_[k].solveInPlace(block);
  }
  for (std::size_t k = blocks - 1; k-- > 0;) {  // x_k = w_k − X_k x_{k+1}
    x.segment(starts_[k], BlockSize(k)).noalias() -= coupled_[k] * x.segment(starts_[k + 1], BlockSize(k + 1));
  }
}

template <typename Scalar>
typename BlockTridiagonalLuOf<Scalar>::Matrix BlockTridiagonalLuOf<Scalar>::Multiply(const Matrix& x) const {
  if (!analyzed_ || x.rows() != starts_.back()) throw LogicError("BlockTridiagonalLu::Multiply: wrong size or no pattern");
  Matrix y(x.rows(), x.cols());
  const std::size_t blocks = diagonal_at_.size();
  for (std::size_t k = 0; k < blocks; ++k) {
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
