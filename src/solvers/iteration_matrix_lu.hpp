// The LU of a time step's iteration matrix, by the cheapest method its shape allows:
//   - dense (partial pivoting) up to dense_limit coordinates: a 72-coordinate cantilever solves in
//     ~2 µs against ~12 µs sparse;
//   - block tridiagonal (solvers/block_tridiagonal_lu.hpp) when the problem names coordinate blocks
//     (a string's bodies) and the matrix couples each block only with its neighbours;
//   - banded (LAPACK, solvers/band_lu.hpp) when the band storage is at most band_storage_limit
//     times the entries;
//   - sparse (solvers/linear_solver.hpp) otherwise.
// The block LU pivots only within a block's Schur complement. Every factorization checks its
// smallest pivot against the largest entry of the matrix and, below block_pivot_tolerance of it,
// factorizes the same matrix banded (row exchanges across blocks) instead.
#pragma once

#include <vector>

#include <Eigen/LU>

#include "core/types.hpp"
#include "solvers/band_lu.hpp"
#include "solvers/block_tridiagonal_lu.hpp"
#include "solvers/linear_solver.hpp"

namespace drillflex::solvers {

struct IterationMatrixLuOptions {
  int dense_limit = 200;            // coordinates
  double band_storage_limit = 4.0;  // (2 kl + ku + 1) n ≤ this · nnz
  double block_pivot_tolerance = 1e-12;  // smallest block pivot ≥ this · max |a_ij|
};

class IterationMatrixLu {
 public:
  enum class Method { kNone, kDense, kBlockTridiagonal, kBanded, kSparse };

  explicit IterationMatrixLu(IterationMatrixLuOptions options = {}) : options_(options) {}

  // The coordinate blocks (first coordinate of each, ascending from 0, then n) for the block
  // tridiagonal LU; empty: none. The next Factorize analyses the pattern against them.
  void SetBlocks(std::vector<Eigen::Index> starts);

  // Factorizes a square matrix. Throws SolverError if it has non-finite entries or is singular to
  // working precision.
  void Factorize(const SparseMat& matrix);
  // x ← A⁻¹ x for the last factorized A.
  void SolveInPlace(VecX& x);

  Method method() const { return method_; }

 private:
  bool SameBlockPattern(const SparseMat& matrix) const;
  bool FactorizeBlocks(const SparseMat& matrix);

  IterationMatrixLuOptions options_;
  Method method_ = Method::kNone;
  std::vector<Eigen::Index> block_starts_;
  // The pattern the block LU was analysed for (outer and inner indices), and whether it fits.
  std::vector<int> analysed_outer_, analysed_inner_;
  bool analysed_ = false, block_pattern_fits_ = false;
  RealBlockTridiagonalLu blocks_;
  Eigen::PartialPivLU<MatX> dense_;
  BandLuSolver band_;
  SparseLinearSolver sparse_;
};

}  // namespace drillflex::solvers
