#include "model/block_pattern.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace drillflex::model {

BlockPattern::BlockPattern(const std::vector<Body>& bodies, const std::vector<std::pair<Index, Index>>& coupled,
                           Index size) {
  const Index count = std::ssize(bodies);
  offsets_.resize(count);
  sizes_.resize(count);
  std::vector<std::vector<Index>> neighbours(count);
  for (Index b = 0; b < count; ++b) {
    offsets_[b] = bodies[b].v_offset;
    sizes_[b] = bodies[b].velocity_count();
    neighbours[b].push_back(b);
  }
  for (const auto& [a, b] : coupled) {
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  column_bodies_.resize(count);
  std::vector<Index> column_size(size, 0);
  for (Index b = 0; b < count; ++b) {
    auto& list = neighbours[b];
    // Ascending rows within a column: sort by offset, drop repeats.
    std::sort(list.begin(), list.end(), [&](Index x, Index y) { return offsets_[x] < offsets_[y]; });
    list.erase(std::unique(list.begin(), list.end()), list.end());
    Index position = 0;
    for (Index a : list) {
      column_bodies_[b].emplace_back(a, position);
      position += sizes_[a];
    }
    for (Index j = 0; j < sizes_[b]; ++j) column_size[offsets_[b] + j] = position;
  }
  // The compressed arrays, written directly (inserting ~1e6 entries one by one costs ~40 ms).
  zero_ = SparseMat(size, size);
  Index nonzeros = 0;
  for (Index c : column_size) nonzeros += c;
  zero_.resizeNonZeros(nonzeros);
  int* outer = zero_.outerIndexPtr();
  int* inner = zero_.innerIndexPtr();
  outer[0] = 0;
  for (Index col = 0; col < size; ++col) outer[col + 1] = outer[col] + column_size[col];
  for (Index b = 0; b < count; ++b) {
    for (Index j = 0; j < sizes_[b]; ++j) {
      int* rows = inner + outer[offsets_[b] + j];
      for (const auto& [a, position] : column_bodies_[b]) {
        for (Index i = 0; i < sizes_[a]; ++i) rows[position + i] = offsets_[a] + i;
      }
    }
  }
  std::fill(zero_.valuePtr(), zero_.valuePtr() + nonzeros, 0.0);
}

void BlockPattern::Prepare(SparseMat& matrix) const {
  const bool same = matrix.isCompressed() && matrix.rows() == zero_.rows() && matrix.cols() == zero_.cols() &&
                    matrix.nonZeros() == zero_.nonZeros() &&
                    std::equal(zero_.outerIndexPtr(), zero_.outerIndexPtr() + zero_.outerSize() + 1,
                               matrix.outerIndexPtr());
  if (!same) matrix = zero_;
}

void BlockPattern::ZeroColumns(Index body, SparseMat& matrix) const {
  const int* outer = matrix.outerIndexPtr();
  std::fill(matrix.valuePtr() + outer[offsets_[body]], matrix.valuePtr() + outer[offsets_[body] + sizes_[body]], 0.0);
}

Index BlockPattern::PositionInColumn(Index row_body, Index col_body) const {
  for (const auto& [a, position] : column_bodies_[col_body]) {
    if (a == row_body) return position;
  }
  throw LogicError("BlockPattern: a block outside the model's sparsity pattern");
}

void BlockPattern::Add(const MatX& block, const std::vector<Index>& body_indices, SparseMat& matrix) const {
  for (auto b = body_indices.begin(); b != body_indices.end(); ++b) {
    if (std::find(body_indices.begin(), b, *b) == b) AddColumns(block, body_indices, *b, matrix);  // once a body
  }
}

void BlockPattern::AddColumns(const MatX& block, std::span<const Index> body_indices, Index column_body,
                              SparseMat& matrix) const {
  const int* outer = matrix.outerIndexPtr();
  double* values = matrix.valuePtr();
  Index col_local = 0;
  bool found = false;
  for (Index b : body_indices) {
    if (b != column_body) {
      col_local += sizes_[b];
      continue;
    }
    found = true;
    Index row_local = 0;
    for (Index a : body_indices) {
      const Index position = PositionInColumn(a, b);
      for (Index j = 0; j < sizes_[b]; ++j) {
        Eigen::Map<VecX>(values + outer[offsets_[b] + j] + position, sizes_[a]) +=
            block.col(col_local + j).segment(row_local, sizes_[a]);
      }
      row_local += sizes_[a];
    }
    col_local += sizes_[b];
  }
  if (!found) throw LogicError("BlockPattern: the column body is not one of the block's bodies");
}

}  // namespace drillflex::model
