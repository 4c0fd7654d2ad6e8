#include "solvers/column_runs.hpp"

#include "core/error.hpp"

namespace drillflex::solvers {

void ColumnRuns::Analyze(const SparseMat& pattern) {
  if (!pattern.isCompressed()) throw LogicError("ColumnRuns::Analyze: the pattern is not compressed");
  runs_.clear();
  rows_ = pattern.rows();
  cols_ = pattern.cols();
  entries_ = pattern.nonZeros();
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  for (Index j = 0; j < cols_; ++j) {
    for (int p = outer[j]; p < outer[j + 1]; ++p) {
      if (p > outer[j] && inner[p] == inner[p - 1] + 1) {
        ++runs_.back().length;
      } else {
        runs_.push_back({j, inner[p], p, 1});
      }
    }
  }
}

VecX ColumnRuns::Multiply(const SparseMat& matrix, const VecX& x) const {
  if (matrix.rows() != rows_ || matrix.cols() != cols_ || matrix.nonZeros() != entries_ || !matrix.isCompressed() ||
      x.size() != cols_) {
    throw LogicError("ColumnRuns::Multiply: a matrix or vector of another shape than analysed");
  }
  VecX y = VecX::Zero(rows_);
  const double* values = matrix.valuePtr();
  for (const Run& run : runs_) {
    y.segment(run.row, run.length).noalias() +=
        x[run.column] * Eigen::Map<const VecX>(values + run.first, run.length);
  }
  return y;
}

}  // namespace drillflex::solvers
