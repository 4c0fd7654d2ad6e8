// y = A x for a compressed column-major sparse matrix whose columns hold their rows in contiguous
// runs (a string's tangent or mass matrix: a body's rows in one run a block), with the same
// arithmetic as Eigen's sparse product — y_i accumulates A(i, j) x_j column by column, j ascending —
// so the sums are the same to the last bit, without an index load per entry: each run is one
// vectorized y(rows) += x_j A(rows, j).
#pragma once

#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace drillflex::solvers {

class ColumnRuns {
 public:
  // The runs of a pattern (compressed, column major).
  void Analyze(const SparseMat& pattern);
  // A x for `matrix` of the analysed pattern (its size and entry count are checked; LogicError).
  VecX Multiply(const SparseMat& matrix, const VecX& x) const;

 private:
  struct Run {
    Index column, row;
    Index first;  // index of its first value
    Index length;
  };
  std::vector<Run> runs_;
  Index rows_ = 0, cols_ = 0, entries_ = -1;
};

}  // namespace drillflex::solvers
