#include "solvers/spectrum_count.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>

#include "solvers/linear_solver.hpp"

namespace drillflex::solvers {
namespace {

template <typename Ordering>
int NegativePivots(const SparseMat& matrix) {
  Eigen::SimplicialLDLT<SparseMat, Eigen::Lower, Ordering> ldlt(matrix);
  if (ldlt.info() != Eigen::Success) return -1;
  const VecX pivots = ldlt.vectorD();
  // A pivot this small against the largest is round-off of a zero one: its sign means nothing.
  const double floor = 1e-13 * pivots.cwiseAbs().maxCoeff();
  int negative = 0;
  for (Eigen::Index j = 0; j < pivots.size(); ++j) {
    if (!std::isfinite(pivots(j)) || !(std::abs(pivots(j)) > floor)) return -1;
    if (pivots(j) < 0.0) ++negative;
  }
  return negative;
}

// Negative pivots of K_s − σM for the symmetric part K_s, in the ordering of linear_solver.hpp.
int NegativePivotsOfShifted(const SparseMat& symmetric, const SparseMat& M, double sigma) {
  SparseMat shifted = symmetric - sigma * M;
  shifted.makeCompressed();
  if (shifted.rows() == 0) return 0;
  return FactorizeInOwnOrder(shifted) ? NegativePivots<Eigen::NaturalOrdering<int>>(shifted)
                                      : NegativePivots<Eigen::AMDOrdering<int>>(shifted);
}

SparseMat SymmetricPart(const SparseMat& K) { return 0.5 * (K + SparseMat(K.transpose())); }

}  // namespace

int CountEigenvaluesBelow(const SparseMat& K, const SparseMat& M, double sigma) {
  return NegativePivotsOfShifted(SymmetricPart(K), M, sigma);
}

int CountEigenvaluesBetween(const SparseMat& K, const SparseMat& M, double lowest, double highest) {
  const SparseMat symmetric = SymmetricPart(K);
  const int below_highest = NegativePivotsOfShifted(symmetric, M, highest);
  const int below_lowest = NegativePivotsOfShifted(symmetric, M, lowest);
  return below_highest >= 0 && below_lowest >= 0 ? below_highest - below_lowest : -1;
}

}  // namespace drillflex::solvers
