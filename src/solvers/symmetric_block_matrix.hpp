// A symmetric block-tridiagonal matrix in dense block storage: a string's symmetrized tangent
// stiffness H = (K + Kᵀ)/2 or its mass matrix, coordinates numbered body by body, each body coupled
// only to its neighbours. Holds the lower triangle of each diagonal block D_k and the blocks below
// it, L_k = A(k+1, k), column major, one after the other (solvers/block_tridiagonal_cholesky.hpp
// factorizes from them).
//
// Why: the trust region (solvers/energy_trust_region.hpp) multiplies by H a few dozen times an
// iteration and factorizes H + σM up to twenty; through the compressed sparse matrix of the union
// of H's and M's patterns (~940k entries on 965 bodies) every product walked index arrays and every
// factorization scattered entry by entry into blocks. Here a matrix is scattered once, when it is
// set, and its products are dense block products.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace drillflex::solvers {

class SymmetricBlockMatrix {
 public:
  // Lays out the blocks (starts[k] the first row of block k, ascending from 0, then n) and maps the
  // entries of `pattern` (compressed, column major) into them: with `symmetrize`, A(i, j) and A(j, i)
  // each give half of the stored entry, else only the lower triangle is read. False, and unusable,
  // when the blocks do not partition the rows or an entry lies outside the block-tridiagonal shape.
  bool Analyze(const SparseMat& pattern, const std::vector<Index>& starts, bool symmetrize);
  // The values from a matrix of the analysed pattern (its values in the pattern's order).
  void Assign(const double* values);
  // A ← A + scale a aᵀ for a sparse a (`indices`, `values`) within the blocks' shape. Throws LogicError
  // for a pair of coordinates outside it.
  void AddOuterProduct(const std::vector<Index>& indices, const std::vector<double>& values, double scale);
  // A x; the same with another set of values of this layout (`values()` of a copy).
  VecX Multiply(const VecX& x) const { return Multiply(values_, x); }
  VecX Multiply(const std::vector<double>& values, const VecX& x) const;
  // xᵀ A x.
  double Quadratic(const VecX& x) const { return x.dot(Multiply(x)); }
  // max |A_ii|.
  double LargestDiagonal() const;
  // True when every L_k is zero (a mass matrix: bodies without shared inertia).
  bool BlockDiagonal() const;

  bool analysed() const { return analysed_; }
  Index rows() const { return starts_.empty() ? 0 : starts_.back(); }
  Index block_count() const { return std::ssize(diagonal_); }
  Index block_start(Index k) const { return starts_[k]; }
  Index block_size(Index k) const { return starts_[k + 1] - starts_[k]; }
  const double* diagonal_block(Index k) const { return values_.data() + diagonal_[k]; }
  const double* below_block(Index k) const { return values_.data() + below_[k]; }
  const std::vector<Index>& starts() const { return starts_; }
  // The block values themselves (D_k, L_k one after the other): to keep and put back a copy.
  std::vector<double>& values() { return values_; }
  const std::vector<double>& values() const { return values_; }
  // Whether `other` has the same blocks (so that its values line up with these).
  bool SameLayout(const SymmetricBlockMatrix& other) const { return starts_ == other.starts_; }

 private:
  Index Slot(Index row, Index column) const;  // row ≥ column; -1 outside
  std::vector<Index> starts_;
  std::vector<Index> block_of_;        // per row
  std::vector<Index> diagonal_, below_;  // offsets of D_k and L_k in values_
  std::vector<double> values_;
  // Per entry of the analysed pattern: its place (kNotRead: an upper entry, not symmetrizing), each
  // entry weighted ½ when symmetrizing, the diagonal's entries (`diagonal_entries_`) a second ½.
  std::vector<std::uint32_t> slot_;
  std::vector<std::uint32_t> diagonal_entries_;
  bool symmetrize_ = false;
  bool analysed_ = false;
};

}  // namespace drillflex::solvers
