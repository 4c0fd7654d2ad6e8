// Block LU of a block-tridiagonal matrix, real or complex: a string's dynamic matrix K − ω²M + iωD,
// or the iteration matrix K + c_D D + c_M M of a time step, its coordinates numbered body by body,
// couples each body only with its two neighbours (the coupling elements). With D_k the diagonal
// blocks, U_k = A(k, k+1) and L_k = A(k+1, k), the N blocks are eliminated from both ends toward the
// middle block m = ⌊N/2⌋ (a "twisted" or two-way block Thomas algorithm: Golub & Van Loan,
// "Matrix Computations", 4th ed., 2013, §4.5.1 for the one-way sweep; van der Vorst, Parallel
// Comput. 5, 1987, for the two-way one):
//   from the top    S_0 = D_0,         X_k = S_k⁻¹ U_k,      S_{k+1} = D_{k+1} − L_k X_k       (k < m)
//   from the bottom T_{N−1} = D_{N−1}, Y_k = T_k⁻¹ L_{k−1},  T_{k−1} = D_{k−1} − U_{k−1} Y_k   (k > m)
//   the middle      S_m = D_m − L_{m−1} X_{m−1} − U_m Y_{m+1},
// each S_k, T_k factorized by dense LU with partial pivoting (solvers/small_lu.hpp). Solve: w_k =
// S_k⁻¹ (f_k − L_{k−1} w_{k−1}) down to m − 1, z_k = T_k⁻¹ (f_k − U_k z_{k+1}) up to m + 1,
// x_m = S_m⁻¹ (f_m − L_{m−1} w_{m−1} − U_m z_{m+1}), then x_k = w_k − X_k x_{k+1} (k < m) and
// x_k = z_k − Y_k x_{k−1} (k > m). The two sweeps are independent: with two or more OpenMP threads
// they run side by side (the bundled example's factorization 1.1 → ~0.6 ms), and as the algorithm
// does not depend on the threads, neither do the results (to the last bit).
//
// Why: the symbolic work of a general sparse LU (depth-first searches, supernode bookkeeping) costs
// more than the arithmetic on such a matrix. For 965 bodies of 18 coordinates (17 370, the 3 km
// string of bench/vibration_bench) the flops are 965 × ~14 000 complex multiply-adds (≈ 1e8 real
// flops) in dense 18 × 18 products. For the 1872 real coordinates of the bundled example (104
// bodies) the factorization takes ~25 000 flops a body, against the ~9e6 of LAPACK's banded LU
// (band 2 × 35).
//
// The matrix lives in the object's own block storage (every D_k, U_k, L_k dense, column major, one
// after the other): a caller that assembles many matrices of one pattern (a frequency sweep)
// writes the values there directly (values(), at slot_offsets()), with no sparse matrix between.
//
// The pivoting stays inside each S_k: not the row exchanges across blocks of a banded LU, so a
// nearly singular S_k (a leading part of the string at its own resonance, undamped) can make the
// factorization inaccurate although the whole matrix is well conditioned. The caller therefore
// checks every solution's backward error (solvers/harmonic.hpp) and factorizes generally when it
// misses; smallest_pivot() reports the smallest |u_jj| of all the S_k.
#pragma once

#include <complex>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/small_lu.hpp"

namespace drillflex::solvers {

template <typename Scalar>
class BlockTridiagonalLuOf {
 public:
  using Sparse = Eigen::SparseMatrix<Scalar>;
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

  // Takes the blocks (starts[k] the first row of block k, ascending, starts.front() = 0,
  // starts.back() = n) and the matrix's pattern (any scalar type; column major). Returns false, and
  // stays unusable, when the blocks do not partition 0 … n − 1 or an entry lies outside the
  // block-tridiagonal structure.
  template <typename PatternScalar>
  bool Analyze(const Eigen::SparseMatrix<PatternScalar>& pattern, std::vector<Index> starts) {
    std::vector<std::pair<Index, Index>> entries;  // (row, column) of each stored entry
    entries.reserve(pattern.nonZeros());
    for (Index col = 0; col < pattern.outerSize(); ++col) {
      for (typename Eigen::SparseMatrix<PatternScalar>::InnerIterator it(pattern, col); it; ++it) {
        entries.emplace_back(it.row(), col);
      }
    }
    return Analyze(pattern.rows(), pattern.cols(), entries, std::move(starts));
  }
  bool analyzed() const { return analyzed_; }

  // The block storage: its size, where each stored entry of the analysed pattern goes (in the
  // pattern's order), and the values (entries of the blocks outside the pattern stay zero).
  Index storage_size() const { return std::ssize(storage_); }
  const std::vector<Index>& slot_offsets() const { return slot_offsets_; }
  Scalar* values() { return storage_.data(); }
  const Scalar* values() const { return storage_.data(); }
  // ‖A‖∞ with |a| measured as |Re a| + |Im a| (|a| if real), and max |a_ij|, of the values held.
  std::pair<double, double> Norms() const;

  // Factorizes the values held (values() keeps them). Throws LogicError before Analyze.
  void Factorize();
  // Writes a matrix with the analysed pattern (compressed) into the storage, then factorizes.
  void Factorize(const Sparse& matrix);
  // The smallest |u_jj| of the LU factors of the S_k (0 before a factorization).
  double smallest_pivot() const { return smallest_pivot_; }

  // X with A X = F (F n × m) for the last factorized A.
  Matrix Solve(const Matrix& rhs) const;
  // x ← A⁻¹ x (no allocation once warm).
  void SolveInPlace(Vector& x) const;
  // A X for the values held.
  Matrix Multiply(const Matrix& x) const;

 private:
  bool Analyze(Index rows, Index cols, const std::vector<std::pair<Index, Index>>& entries,
               std::vector<Index> starts);
  // The two sweeps of the factorization (header); each returns the smallest |u_jj|² of its blocks.
  double FactorizeFromTop();
  double FactorizeFromBottom();
  // x ← A⁻¹ x for a vector or a matrix of right-hand sides.
  template <typename Target>
  void SolveColumns(Target& x) const;
  Index BlockSize(Index k) const { return starts_[k + 1] - starts_[k]; }
  using ConstBlock = Eigen::Map<const Matrix>;
  ConstBlock Diagonal(Index k) const { return {storage_.data() + diagonal_at_[k], BlockSize(k), BlockSize(k)}; }
  ConstBlock Upper(Index k) const { return {storage_.data() + upper_at_[k], BlockSize(k), BlockSize(k + 1)}; }
  ConstBlock Lower(Index k) const { return {storage_.data() + lower_at_[k], BlockSize(k + 1), BlockSize(k)}; }

  bool analyzed_ = false;
  std::vector<Index> starts_;
  std::vector<Scalar> storage_;  // D_0, U_0, L_0, D_1, U_1, L_1, …, D_N (each column major)
  std::vector<Index> diagonal_at_, upper_at_, lower_at_;  // where D_k, U_k, L_k begin
  std::vector<Index> slot_offsets_;
  // The same as runs of entries that are consecutive in both (a column's rows within one block):
  // the pattern's entries [from, from + length) go to the storage at [to, to + length). A string's
  // matrix copies in ~50k runs of a body's 18 rows instead of ~1e6 single entries.
  struct Run {
    Index from, to, length;
  };
  std::vector<Run> runs_;
  Index middle_ = 0;                // m = ⌊N/2⌋, where the two sweeps meet
  std::vector<SmallLu<Scalar>> factors_;  // LU of S_k (k ≤ m) and T_k (k > m)
  std::vector<Matrix> coupled_;           // X_k = S_k⁻¹ U_k (k < m), Y_k = T_k⁻¹ L_{k−1} (k > m)
  Matrix top_schur_, bottom_schur_;       // S_k and T_k being formed (one each sweep)
  double smallest_pivot_ = 0.0;
};

using BlockTridiagonalLu = BlockTridiagonalLuOf<std::complex<double>>;
using RealBlockTridiagonalLu = BlockTridiagonalLuOf<double>;

}  // namespace drillflex::solvers
