#include "solvers/projected_harmonic.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>

#include <fmt/format.h>

#include "core/dense_eigen.hpp"
#include "core/error.hpp"
#include "solvers/linear_solver.hpp"
#include "solvers/serial_eigen.hpp"

namespace drillflex::solvers {
namespace {

using Complex = std::complex<double>;

// Removes from `column` its M-projection on the first `filled` columns of `basis` (classical
// Gram–Schmidt, twice: Kahan's "twice is enough", Parlett, The Symmetric Eigenvalue Problem,
// §6.9) and returns its M-norm after that.
double OrthogonalizeInMass(const MatX& basis, Eigen::Index filled, const SparseMat& M, VecX& column) {
  for (int pass = 0; pass < 2; ++pass) {
    const VecX m_column = M * column;
    column -= basis.leftCols(filled) * (basis.leftCols(filled).transpose() * m_column);
  }
  return std::sqrt(std::max(0.0, column.dot(M * column)));
}

// Vᵀ A V over the rows where A has entries (an annulus group's matrix lives on its bodies only).
MatX Project(const SparseMat& matrix, const MatX& basis) {
  if (matrix.size() == 0) return MatX();
  std::vector<bool> used(matrix.rows(), false);
  for (Eigen::Index col = 0; col < matrix.outerSize(); ++col) {
    for (SparseMat::InnerIterator it(matrix, col); it; ++it) used[it.row()] = true;
  }
  std::vector<Eigen::Index> rows;
  for (Index i = 0; i < std::ssize(used); ++i) {
    if (used[i]) rows.push_back(i);
  }
  const MatX product = matrix * basis;
  return basis(rows, Eigen::all).transpose() * product(rows, Eigen::all);
}

}  // namespace

namespace {

// Appends the columns of `block` to the first `filled` columns of `basis`, each M-orthonormalized
// (dropped when already in the span). Returns the new count.
Eigen::Index AppendOrthonormal(MatX& basis, Eigen::Index filled, const SparseMat& M, MatX block) {
  if (basis.cols() < filled + block.cols()) basis.conservativeResize(Eigen::NoChange, filled + block.cols());
  const VecX before = (block.transpose() * (M * block)).diagonal().cwiseMax(0.0).cwiseSqrt();
  // The block against the basis so far, twice (matrix products), then each column against the
  // block's columns already taken (and once more against all, for round-off).
  for (int pass = 0; pass < 2 && filled > 0; ++pass) {
    block -= basis.leftCols(filled) * (basis.leftCols(filled).transpose() * (M * block));
  }
  for (Eigen::Index c = 0; c < block.cols(); ++c) {
    VecX column = block.col(c);
    if (!(before[c] > 0.0)) continue;
    const double after = OrthogonalizeInMass(basis, filled, M, column);
    if (!(after > 1e-8 * before[c])) continue;
    basis.col(filled++) = column / after;
  }
  return filled;
}

// The expansion frequencies: `shifts` spread evenly over the band (the middles of equal parts),
// and the top of each pattern band (a single-frequency band's frequency) not already one of them:
// a band's top is half a spacing from the nearest even shift, where its loads alone (without the
// other patterns' vectors there) were least well held.
std::vector<double> ExpansionFrequencies(const KrylovBasisOptions& options, double step) {
  std::vector<double> frequencies;
  for (int j = 0; j < options.shifts; ++j) frequencies.push_back(options.lowest_frequency + (j + 0.5) * step);
  for (const FrequencyBand& band : options.pattern_bands) {
    const bool known = std::any_of(frequencies.begin(), frequencies.end(),
                                   [&](double f) { return std::abs(f - band.highest) <= 1e-9 * band.highest; });
    if (!known && band.highest > 0.0) frequencies.push_back(band.highest);
  }
  return frequencies;
}

// The load patterns expanded at ω: those whose band reaches within one shift spacing of it (all
// without bands), and a single-frequency band only at its frequency.
std::vector<Eigen::Index> PatternsAt(const KrylovBasisOptions& options, double omega, double step, Eigen::Index count) {
  std::vector<Eigen::Index> columns;
  for (Eigen::Index c = 0; c < count; ++c) {
    if (options.pattern_bands.empty()) {
      columns.push_back(c);
      continue;
    }
    const FrequencyBand& band = options.pattern_bands[c];
    const bool single = !(band.highest > band.lowest);
    const bool near = single ? std::abs(omega - band.lowest) <= 1e-9 * band.lowest
                             : omega >= band.lowest - step && omega <= band.highest + step;
    if (near) columns.push_back(c);
  }
  return columns;
}

}  // namespace

KrylovBasis BuildKrylovBasis(const SparseMat& K, const SparseMat& M, const MatX& load_patterns,
                             const KrylovBasisOptions& options) {
  const Eigen::Index n = K.rows();
  if (M.rows() != n || M.cols() != n || K.cols() != n || load_patterns.rows() != n) {
    throw LogicError(fmt::format("BuildKrylovBasis: K {}x{}, M {}x{}, loads {} rows", K.rows(), K.cols(), M.rows(),
                                 M.cols(), load_patterns.rows()));
  }
  if (!(options.highest_frequency > 0.0) || !(options.lowest_frequency >= 0.0) ||
      options.lowest_frequency > options.highest_frequency || options.shifts < 1 || options.depth < 1) {
    throw LogicError("BuildKrylovBasis: needs 0 <= lowest <= highest frequency, highest > 0, shifts and depth >= 1");
  }
  if (!options.pattern_bands.empty() && std::ssize(options.pattern_bands) != load_patterns.cols()) {
    throw LogicError(fmt::format("BuildKrylovBasis: {} pattern bands for {} load patterns", options.pattern_bands.size(),
                                 load_patterns.cols()));
  }
  const SerialEigenProducts serial;
  KrylovBasis basis;
  basis.vectors.resize(n, 0);
  Eigen::Index filled = 0;
  SparseLinearSolver solver;
  try {
    solver.Factorize(K, MatrixSymmetry::kSymmetric);
  } catch (const SolverError&) {
    // K singular (a free rigid-body motion): σ₀ = −(10⁻² ω_hi)².
    const double pole = 1e-4 * options.highest_frequency * options.highest_frequency;
    solver.Factorize(SparseMat(K + pole * M), MatrixSymmetry::kSymmetric);
  }
  filled = AppendOrthonormal(basis.vectors, filled, M, solver.SolveColumns(load_patterns));
  if (options.extra_vectors.cols() > 0) {
    if (options.extra_vectors.rows() != n) throw LogicError("BuildKrylovBasis: the extra vectors need n rows");
    filled = AppendOrthonormal(basis.vectors, filled, M, options.extra_vectors);
  }
  const double step = (options.highest_frequency - options.lowest_frequency) / options.shifts;
  for (const double omega : ExpansionFrequencies(options, step)) {
    const std::vector<Eigen::Index> columns = PatternsAt(options, omega, step, load_patterns.cols());
    if (columns.empty()) continue;
    basis.shifts.push_back(omega);
    // Indefinite inside the spectrum: LU (an LDLT without pivoting would fail its backward-error check).
    solver.Factorize(SparseMat(K - (omega * omega) * M), MatrixSymmetry::kUnsymmetric);
    MatX block = solver.SolveColumns(MatX(load_patterns(Eigen::all, columns)));
    for (int k = 0; k < options.depth; ++k) {
      filled = AppendOrthonormal(basis.vectors, filled, M, block);
      if (k + 1 < options.depth) block = solver.SolveColumns(MatX(M * block));
    }
  }
  basis.vectors.conservativeResize(n, filled);
  return basis;
}

ProjectedHarmonicSolver::ProjectedHarmonicSolver(const LinearSystem& system, const std::vector<SparseMat>& terms,
                                                 MatX basis, const std::vector<FrequencyTermCoefficients>& reference,
                                                 ProjectedSolveOptions options)
    : options_(options), basis_(std::move(basis)) {
  const Eigen::Index n = system.stiffness.rows();
  auto check = [n](const SparseMat& matrix, const char* name, bool may_be_empty) {
    if (may_be_empty && matrix.size() == 0) return;
    if (matrix.rows() != n || matrix.cols() != n) {
      throw LogicError(fmt::format("ProjectedHarmonicSolver: {} is {}x{}, K is {}x{}", name, matrix.rows(),
                                   matrix.cols(), n, n));
    }
  };
  check(system.mass, "M", false);
  check(system.damping, "D", true);
  check(system.gyroscopic, "G", true);
  for (const SparseMat& term : terms) check(term, "a frequency term", false);
  if (basis_.rows() != n) {
    throw LogicError(fmt::format("ProjectedHarmonicSolver: the basis has {} rows, K {}", basis_.rows(), n));
  }
  if (!reference.empty() && reference.size() != terms.size()) {
    throw LogicError("ProjectedHarmonicSolver: one reference coefficient pair per term");
  }
  const SerialEigenProducts serial;
  stiffness_ = Project(system.stiffness, basis_);
  mass_ = Project(system.mass, basis_);
  damping_ = Project(system.damping, basis_);
  gyroscopic_ = Project(system.gyroscopic, basis_);
  for (const SparseMat& term : terms) {
    // A term that is K itself (a hysteretic loss factor) takes K's projection.
    const bool is_stiffness = term.nonZeros() == system.stiffness.nonZeros() && SparseMat(term - system.stiffness).norm() == 0.0;
    terms_.push_back(is_stiffness ? stiffness_ : Project(term, basis_));
  }
  // The Ritz modes of (K_r, M_ref,r).
  MatX reference_mass = mass_;
  for (Index t = 0; t < std::ssize(reference); ++t) reference_mass += reference[t].mass * terms_[t];
  const DenseEigenpairs ritz = GeneralizedSymmetricEigen(0.5 * (stiffness_ + stiffness_.transpose()),
                                                         0.5 * (reference_mass + reference_mass.transpose()));
  if (!ritz.converged) {
    throw SolverError("reduced harmonic response: the projected mass is not positive definite");
  }
  const MatX& psi = ritz.vectors;
  ritz_eigenvalues_ = ritz.values;
  basis_ = basis_ * psi;
  for (MatX* matrix : {&stiffness_, &mass_, &damping_, &gyroscopic_}) {
    if (matrix->size() > 0) *matrix = psi.transpose() * (*matrix) * psi;
  }
  for (MatX& term : terms_) term = psi.transpose() * term * psi;
}

Eigen::MatrixXcd ProjectedHarmonicSolver::Assemble(double frequency, double rotor_speed,
                                                   const std::vector<FrequencyTermCoefficients>& terms) const {
  // Vᵀ A(ω) V = K_r − ω² M_r + iω (D_r + Ω G_r) + Σ_t (−ω² a_t + iω b_t) T_t,r.
  const double omega2 = frequency * frequency;
  Eigen::MatrixXcd reduced(stiffness_.rows(), stiffness_.cols());
  reduced.real() = stiffness_ - omega2 * mass_;
  reduced.imag().setZero();
  if (damping_.size() > 0) reduced.imag() += frequency * damping_;
  if (gyroscopic_.size() > 0 && rotor_speed != 0.0) reduced.imag() += (frequency * rotor_speed) * gyroscopic_;
  for (Index t = 0; t < std::ssize(terms); ++t) {
    if (terms[t].mass != 0.0) reduced.real() -= (omega2 * terms[t].mass) * terms_[t];
    if (terms[t].damping != 0.0) reduced.imag() += (frequency * terms[t].damping) * terms_[t];
  }
  return reduced;
}

namespace {

// The near/far preconditioner of ProjectedHarmonicSolver (see the header).
class NearFarSplit {
 public:
  NearFarSplit(const Eigen::MatrixXcd& matrix, std::vector<Eigen::Index> near, std::vector<Eigen::Index> far)
      : near_(std::move(near)), far_(std::move(far)) {
    const Eigen::VectorXcd diagonal = matrix.diagonal();
    far_inverse_ = diagonal(far_).cwiseInverse();
    near_far_ = matrix(near_, far_);
    far_near_ = matrix(far_, near_);
    if (!near_.empty()) {
      const Eigen::MatrixXcd schur = matrix(near_, near_) - near_far_ * far_inverse_.asDiagonal() * far_near_;
      lu_.compute(schur);
    }
  }
  bool Regular() const { return far_inverse_.allFinite() && (near_.empty() || lu_.rcond() > 1e-14); }

  Eigen::MatrixXcd Apply(const Eigen::MatrixXcd& residual) const {
    Eigen::MatrixXcd result(residual.rows(), residual.cols());
    const Eigen::MatrixXcd scaled_far = far_inverse_.asDiagonal() * residual(far_, Eigen::all);
    Eigen::MatrixXcd near_part;
    if (!near_.empty()) {
      near_part = lu_.solve(residual(near_, Eigen::all) - near_far_ * scaled_far);
      result(near_, Eigen::all) = near_part;
      result(far_, Eigen::all) = scaled_far - far_inverse_.asDiagonal() * (far_near_ * near_part);
    } else {
      result(far_, Eigen::all) = scaled_far;
    }
    return result;
  }

 private:
  std::vector<Eigen::Index> near_, far_;
  Eigen::VectorXcd far_inverse_;
  Eigen::MatrixXcd near_far_, far_near_;
  Eigen::PartialPivLU<Eigen::MatrixXcd> lu_;
};

}  // namespace

ComplexMat ProjectedHarmonicSolver::Solve(double frequency, const ComplexMat& loads, double rotor_speed,
                                          const std::vector<FrequencyTermCoefficients>& terms) const {
  if (terms.size() != terms_.size()) {
    throw LogicError(fmt::format("ProjectedHarmonicSolver::Solve: {} term coefficients for {} terms", terms.size(),
                                 terms_.size()));
  }
  if (!std::isfinite(frequency) || frequency < 0.0 || !std::isfinite(rotor_speed)) {
    throw LogicError(fmt::format("ProjectedHarmonicSolver::Solve: needs a finite ω ≥ 0 and a finite Ω "
                                 "(ω = {} rad/s, Ω = {} rad/s)", frequency, rotor_speed));
  }
  if (loads.rows() != size()) {
    throw LogicError(fmt::format("ProjectedHarmonicSolver::Solve: the loads have {} rows, the system {}",
                                 loads.rows(), size()));
  }
  const Eigen::MatrixXcd reduced = Assemble(frequency, rotor_speed, terms);
  // Vᵀ F over the loaded rows (a load acts at a node or two).
  Eigen::MatrixXcd reduced_loads = Eigen::MatrixXcd::Zero(basis_.cols(), loads.cols());
  for (Eigen::Index i = 0; i < loads.rows(); ++i) {
    if (loads.row(i).squaredNorm() > 0.0) reduced_loads += basis_.row(i).transpose() * loads.row(i);
  }
  std::vector<Eigen::Index> near, far;
  for (Eigen::Index j = 0; j < ritz_eigenvalues_.size(); ++j) {
    const double lambda = ritz_eigenvalues_[j];
    const bool close = lambda > 0.0 && std::abs(std::sqrt(lambda) - frequency) <= options_.near_window * frequency;
    (close ? near : far).push_back(j);
  }
  Eigen::MatrixXcd y;
  bool converged = false;
  if (2 * std::ssize(near) <= reduced.rows()) {
    const NearFarSplit split(reduced, std::move(near), std::move(far));
    if (split.Regular()) {
      y = split.Apply(reduced_loads);
      const double target = 1e-10 * reduced_loads.norm();
      for (int step = 0; step < 30 && !converged; ++step) {
        const Eigen::MatrixXcd residual = reduced_loads - reduced * y;
        converged = residual.norm() <= target;
        if (!converged) y += split.Apply(residual);
      }
    }
  }
  if (!converged) {
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(reduced);
    const double rcond = lu.rcond();
    if (!(rcond > 1e-14)) {
      throw SolverError(fmt::format("reduced harmonic response: the projected matrix is singular at ω = {} rad/s "
                                    "({} Hz): reciprocal condition number {:.3g} (an undamped system driven at a "
                                    "natural frequency has no steady state)",
                                    frequency, frequency / (2.0 * kPi), rcond));
    }
    y = lu.solve(reduced_loads);
  }
  ComplexMat x(basis_.rows(), loads.cols());
  x.real() = basis_ * y.real();
  x.imag() = basis_ * y.imag();
  if (!x.allFinite()) throw SolverError("reduced harmonic response: non-finite solution");
  return x;
}

}  // namespace drillflex::solvers
