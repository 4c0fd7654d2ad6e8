#include "solvers/shifted_cholesky.hpp"

#include <Eigen/SparseCholesky>
#include <fmt/format.h>

#include "core/error.hpp"
#include "solvers/linear_solver.hpp"

namespace drillflex::solvers {

struct ShiftedCholesky::Factors {
  Eigen::SimplicialLLT<SparseMat, Eigen::Lower, Eigen::NaturalOrdering<int>> natural;
  Eigen::SimplicialLLT<SparseMat, Eigen::Lower, Eigen::AMDOrdering<int>> amd;
};

ShiftedCholesky::ShiftedCholesky(const SparseMat& stiffness, const SparseMat& metric)
    : factors_(std::make_unique<Factors>()) {
  if (stiffness.rows() != stiffness.cols() || metric.rows() != metric.cols() || stiffness.rows() != metric.rows()) {
    throw LogicError(fmt::format("ShiftedCholesky: H is {}x{}, M {}x{}", stiffness.rows(), stiffness.cols(),
                                 metric.rows(), metric.cols()));
  }
  const SparseMat transposed = stiffness.transpose();
  const SparseMat symmetric = 0.5 * (stiffness + transposed);
  // Sums keep every entry of both patterns (explicit zeros too), so the three share one pattern in
  // one order and H + σM is formed entry by entry.
  stiffness_ = symmetric + 0.0 * metric;
  metric_ = metric + 0.0 * symmetric;
  stiffness_.makeCompressed();
  metric_.makeCompressed();
  if (stiffness_.nonZeros() != metric_.nonZeros()) throw LogicError("ShiftedCholesky: the patterns differ");
  shifted_ = stiffness_;
  natural_order_ = FactorizeInOwnOrder(stiffness_);
  if (natural_order_) {
    factors_->natural.analyzePattern(shifted_);
  } else {
    factors_->amd.analyzePattern(shifted_);
  }
}

ShiftedCholesky::~ShiftedCholesky() = default;
ShiftedCholesky::ShiftedCholesky(ShiftedCholesky&&) noexcept = default;
ShiftedCholesky& ShiftedCholesky::operator=(ShiftedCholesky&&) noexcept = default;

bool ShiftedCholesky::Factorize(double shift) {
  ++count_;
  const double* h = stiffness_.valuePtr();
  const double* m = metric_.valuePtr();
  double* a = shifted_.valuePtr();
  for (Eigen::Index k = 0; k < shifted_.nonZeros(); ++k) a[k] = h[k] + shift * m[k];
  bool ok = false;
  if (natural_order_) {
    factors_->natural.factorize(shifted_);
    ok = factors_->natural.info() == Eigen::Success;
  } else {
    factors_->amd.factorize(shifted_);
    ok = factors_->amd.info() == Eigen::Success;
  }
  // A failed factorization leaves the factors unusable: the last good one is gone too.
  factorized_ = ok;
  if (ok) shift_ = shift;
  return ok;
}

VecX ShiftedCholesky::Solve(const VecX& rhs) const {
  if (!factorized_) throw LogicError("ShiftedCholesky::Solve: no positive definite factorization held");
  return natural_order_ ? VecX(factors_->natural.solve(rhs)) : VecX(factors_->amd.solve(rhs));
}

}  // namespace drillflex::solvers
