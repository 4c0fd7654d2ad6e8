// The Lanczos path of SolveModes: Spectra's shift-invert generalized solver with a deflated
// operator (see eigen.hpp for why).
#include <Eigen/SparseCholesky>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "solvers/buckling.hpp"
#include "solvers/eigen.hpp"
#include "solvers/eigen_detail.hpp"
#include "solvers/linear_solver.hpp"

namespace drillflex::solvers {
namespace {

// y = (I − X Xᵀ M)(K − σM)⁻¹ z, with X the M-orthonormal modes found so far. Spectra's
// shift-invert mode calls it with z = M x, so the operator is (I − X Xᵀ M)(K − σM)⁻¹ M: the
// found modes move to ν = 0 and every other eigenpair stays (ν = 1/(ω² − σ)).
class DeflatedShiftInvert {
 public:
  using Scalar = double;

  DeflatedShiftInvert(SparseLinearSolver& solver, const MatX& locked, const MatX& locked_times_m)
      : solver_(&solver), locked_(&locked), locked_times_m_(&locked_times_m) {}

  Eigen::Index rows() const { return solver_->size(); }
  Eigen::Index cols() const { return solver_->size(); }
  void set_shift(double /*sigma*/) {}  // K − σM is factorized before the solver is built

  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const VecX> x(x_in, rows());
    Eigen::Map<VecX> y(y_out, rows());
    y = solver_->Solve(VecX(x));
    if (locked_->cols() > 0) y -= *locked_ * (locked_times_m_->transpose() * y);
  }

 private:
  SparseLinearSolver* solver_;
  const MatX* locked_;
  const MatX* locked_times_m_;
};

// A pole σ slightly below the requested shift, so that K − σM stays regular when the shift is
// an eigenvalue (ω² = 0 of free-free bodies): δ = 1e-9 · max K_ii/M_ii (≈ 1e-9 of the highest
// ω²), far below the lowest elastic ω² of the models meant here, yet giving cond(K − σM) ≈ 1e9.
double PoleBelowShift(const SparseMat& K, const SparseMat& M, double shift) {
  double scale = 0.0;
  for (Eigen::Index i = 0; i < K.rows(); ++i) {
    const double mass = M.coeff(i, i);
    if (mass > 0.0) scale = std::max(scale, std::abs(K.coeff(i, i)) / mass);
  }
  if (scale == 0.0) scale = 1.0;
  return shift - 1e-9 * scale;
}

// The pole of the shift-invert: the shift itself when K − shift·M is regular, so that the wanted
// eigenvalues stay well separated after inversion; slightly below it only when K − shift·M is
// singular or nearly so (a free-free model's ω² = 0, or a shift on an eigenvalue). Regular: its
// Cholesky (positive definite: a supported model asked for its lowest modes) or, indefinite (a
// string with a mode of negative stiffness under torque, or a shift inside the spectrum), its
// LDLᵀ has no pivot below 1e-12 of the largest. With the pole 1e-9·max(K_ii/M_ii) below zero, a 3 km
// string whose lowest ω² are ~1e-2 needed forty times more Lanczos iterations than with the pole at
// zero; the bundled example's modes (one ω² < 0 under its TOB, the lowest lateral at 76 rad²/s²,
// the pole −15 906) five runs and 2 564 solves for its lowest lateral mode.
double ChoosePole(const SparseMat& K, const SparseMat& M, double shift) {
  const SparseMat shifted = K - shift * M;
  auto regular = [](const VecX& pivots) {
    const VecX magnitudes = pivots.cwiseAbs();
    return magnitudes.size() > 0 && magnitudes.minCoeff() > 1e-12 * magnitudes.maxCoeff();
  };
  Eigen::SimplicialLLT<SparseMat> cholesky(shifted);
  if (cholesky.info() == Eigen::Success) {
    if (regular(cholesky.matrixL().nestedExpression().diagonal().cwiseAbs2())) return shift;
  } else {
    Eigen::SimplicialLDLT<SparseMat> ldlt(shifted);
    if (ldlt.info() == Eigen::Success && regular(ldlt.vectorD())) return shift;
  }
  return PoleBelowShift(K, M, shift);
}

struct LanczosPairs {
  VecX eigenvalues;
  MatX vectors;
};

// One Lanczos run on the deflated operator for the `nev` eigenvalues nearest the pole.
LanczosPairs RunLanczos(DeflatedShiftInvert& op, const SparseMat& M, Eigen::Index nev,
                        double pole) {
  using BOp = Spectra::SparseSymMatProd<double>;
  using Solver = Spectra::SymGEigsShiftSolver<DeflatedShiftInvert, BOp,
                                              Spectra::GEigsMode::ShiftInvert>;
  BOp m_op(M);
  const Eigen::Index n = M.rows();
  const Eigen::Index ncv = std::min(n, std::max<Eigen::Index>(2 * nev + 1, 20));
  Solver solver(op, m_op, nev, ncv, pole);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
  if (solver.info() != Spectra::CompInfo::Successful && solver.eigenvalues().size() == 0) {
    throw SolverError(fmt::format(
        "Lanczos modal solver ({} DOF): no eigenvalue converged near the shift {:.6g} rad²/s²",
        n, pole));
  }
  return {solver.eigenvalues(), solver.eigenvectors()};
}

// Rayleigh quotients xᵀKx / xᵀMx (second-order accurate in the mode error) and M-normalisation.
void RefineByRayleighQuotient(const SparseMat& K, const SparseMat& M, LanczosPairs& pairs) {
  for (Eigen::Index j = 0; j < pairs.vectors.cols(); ++j) {
    const VecX mx = M * pairs.vectors.col(j);
    const double mass = pairs.vectors.col(j).dot(mx);
    pairs.vectors.col(j) /= std::sqrt(mass);
    pairs.eigenvalues[j] = pairs.vectors.col(j).dot(K * pairs.vectors.col(j));
  }
}

}  // namespace

ModalResult SolveModesLanczos(const SparseMat& K, const SparseMat& M, Index count, double shift) {
  const Eigen::Index n = K.rows();
  detail::CheckSymmetric(K, n, "K");
  detail::CheckSymmetric(M, n, "M");
  const Eigen::Index wanted = std::min<Eigen::Index>(std::max<Index>(count, 0), n);
  if (wanted == 0) return {VecX(0), MatX(n, 0)};
  // Spectra needs nev < ncv ≤ n; near-full spectra are a dense job anyway.
  if (3 * wanted >= n) return SolveModesDense(K, M, count, shift);

  // The lowest modes of a positive definite K (a supported structure): the largest 1/ω² of
  // M x = (1/ω²) K x by Lanczos on the Cholesky factor of K (the buckling solver with K_G = −M)
  // converge about twice as fast as shift-invert (1000-body string, 10 modes: 0.35 s against
  // 0.72 s). A K that is not positive definite falls through to shift-invert.
  if (shift == 0.0) {
    try {
      const BucklingResult lowest = SolveBucklingLanczos(K, SparseMat(-M), count);
      if (lowest.multipliers.size() == wanted) {
        ModalResult result{lowest.multipliers, lowest.modes};
        for (Eigen::Index j = 0; j < result.vectors.cols(); ++j) {
          result.vectors.col(j) /= std::sqrt(result.vectors.col(j).dot(M * result.vectors.col(j)));
        }
        return result;
      }
    } catch (const SolverError&) {
      // K singular or indefinite (a free structure, or one loaded beyond buckling).
    }
  }

  const double pole = ChoosePole(K, M, shift);
  SparseLinearSolver solver;
  try {
    solver.Factorize(SparseMat(K - pole * M), MatrixSymmetry::kSymmetric);
  } catch (const SolverError& error) {
    throw SolverError(fmt::format("Lanczos modal solver ({} DOF): K − σM at σ = {:.6g} cannot be "
                                  "factorized ({})",
                                  n, pole, error.what()));
  }
  MatX locked(n, 0);         // M-orthonormal modes found so far
  MatX locked_times_m(n, 0);  // M X
  VecX locked_values(0);
  DeflatedShiftInvert op(solver, locked, locked_times_m);
  constexpr int kMaxRuns = 12;  // each run after the first finds the missing copies of a multiple
  for (int run = 0; run < kMaxRuns; ++run) {
    const Eigen::Index nev = std::min(wanted, n - locked.cols() - 2);
    if (nev < 1) break;
    LanczosPairs found = RunLanczos(op, M, nev, pole);
    RefineByRayleighQuotient(K, M, found);
    // Distance to the shift of the farthest mode that would be kept now.
    double kept_radius = std::numeric_limits<double>::infinity();
    if (locked_values.size() >= wanted) {
      VecX distances = (locked_values.array() - shift).abs();
      std::sort(distances.data(), distances.data() + distances.size());
      kept_radius = distances[wanted - 1];
    }
    const double nearest_new = (found.eigenvalues.array() - shift).abs().minCoeff();
    const Eigen::Index old = locked.cols();
    locked.conservativeResize(n, old + found.vectors.cols());
    locked.rightCols(found.vectors.cols()) = found.vectors;
    locked_times_m = M * locked;
    locked_values.conservativeResize(old + found.eigenvalues.size());
    locked_values.tail(found.eigenvalues.size()) = found.eigenvalues;
    // Nothing new inside the kept set: no eigenvalue was missed (with a relative margin).
    if (nearest_new > kept_radius * (1.0 + 1e-8) + 1e-14 * std::abs(shift)) break;
  }
  return detail::SelectNearest(locked_values, locked, wanted, shift);
}

}  // namespace drillflex::solvers
