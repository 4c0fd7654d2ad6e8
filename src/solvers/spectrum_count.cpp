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

}  // namespace

int CountEigenvaluesBelow(const SparseMat& K, const SparseMat& M, double sigma) {
  SparseMat shifted = SparseMat(0.5 * (K + SparseMat(K.transpose()))) - sigma * M;
  shifted.makeCompressed();
  if (shifted.rows() == 0) return 0;
  // The ordering rule of linear_solver.hpp: a narrow band in its own order, any other by AMD.
  const bool narrow = static_cast<double>(shifted.rows()) * static_cast<double>(HalfBandwidth(shifted)) <=
                      8.0 * static_cast<double>(shifted.nonZeros());
  return narrow ? NegativePivots<Eigen::NaturalOrdering<int>>(shifted)
                : NegativePivots<Eigen::AMDOrdering<int>>(shifted);
}

}  // namespace drillflex::solvers
