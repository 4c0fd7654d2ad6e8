#include "solvers/harmonic.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "solvers/block_tridiagonal_lu.hpp"
#include "solvers/linear_solver.hpp"

namespace drillflex::solvers {
namespace {

using Complex = std::complex<double>;
using ComplexSparse = Eigen::SparseMatrix<Complex>;

// SparseLU that can report its smallest pivot: the diagonal of U is kept in the supernodes of
// the L store (the same walk as Eigen's SparseLU::absDeterminant).
template <typename Ordering>
class PivotCheckedLu : public Eigen::SparseLU<ComplexSparse, Ordering> {
 public:
  double SmallestPivot() const {
    double smallest2 = std::numeric_limits<double>::infinity();  // |u_jj|²: no hypot per column
    for (Eigen::Index j = 0; j < this->cols(); ++j) {
      double pivot2 = 0.0;  // a column without a stored diagonal has a zero pivot
      for (typename decltype(this->m_Lstore)::InnerIterator it(this->m_Lstore, j); it; ++it) {
        if (it.index() == j) {
          pivot2 = std::norm(it.value());
          break;
        }
      }
      smallest2 = std::min(smallest2, pivot2);
    }
    return std::sqrt(smallest2);
  }
};

bool AllFinite(const SparseMat& matrix) {
  const double* values = matrix.valuePtr();
  return std::all_of(values, values + matrix.nonZeros(),
                     [](double x) { return std::isfinite(x); });
}

// The values of `matrix` laid onto the (sorted, compressed) pattern `pattern`, which must contain
// every entry of `matrix`.
std::vector<double> ValuesOnPattern(const SparseMat& matrix, const SparseMat& pattern) {
  std::vector<double> values(pattern.nonZeros(), 0.0);
  if (matrix.size() == 0) return values;
  for (Eigen::Index col = 0; col < pattern.outerSize(); ++col) {
    Eigen::Index slot = pattern.outerIndexPtr()[col];
    const Eigen::Index end = pattern.outerIndexPtr()[col + 1];
    for (SparseMat::InnerIterator it(matrix, col); it; ++it) {
      while (slot < end && pattern.innerIndexPtr()[slot] < it.row()) ++slot;
      if (slot == end || pattern.innerIndexPtr()[slot] != it.row()) {
        throw LogicError("HarmonicSolver: an entry lies outside the union pattern");
      }
      values[slot] += it.value();
    }
  }
  return values;
}

}  // namespace

// The real matrices laid onto one storage of the complex matrix: the slots of the union pattern
// (general LU) or the block storage of the block LU.
struct MatricesOnStorage {
  std::vector<double> stiffness, mass, damping, gyroscopic;  // empty D, G: none
  // The frequency terms: those with entries on more than a quarter of the pattern as values on the
  // storage (dense_terms), the others as their nonzeros (place in the storage, value) in `terms`.
  std::vector<std::vector<std::pair<Index, double>>> terms;
  std::vector<std::vector<double>> dense_terms;
};

struct HarmonicSolver::Workspace {
  HarmonicOptions options;
  ComplexSparse matrix;  // the union pattern; values rewritten for the general LU
  MatricesOnStorage on_storage;  // on the block storage when the block LU is in use, else on the pattern
  Eigen::ArrayXd imaginary;      // the imaginary parts being formed
  bool natural_order = false;
  BlockTridiagonalLu blocks;  // in use when analysed
  int block_fallbacks = 0;
  PivotCheckedLu<Eigen::NaturalOrdering<int>> lu_natural;
  PivotCheckedLu<Eigen::COLAMDOrdering<int>> lu_colamd;
};

namespace {

void CheckSystemMatrix(const SparseMat& matrix, Eigen::Index n, const char* name,
                       bool may_be_empty) {
  const bool empty = matrix.rows() == 0 && matrix.cols() == 0;
  if (!(may_be_empty && empty) && (matrix.rows() != n || matrix.cols() != n)) {
    throw LogicError(fmt::format("HarmonicSolver: {} is {}x{}, K is {}x{}", name, matrix.rows(),
                                 matrix.cols(), n, n));
  }
  if (!AllFinite(matrix)) {
    throw LogicError(fmt::format("HarmonicSolver: {} has non-finite entries", name));
  }
}

}  // namespace

HarmonicSolver::HarmonicSolver(LinearSystem system, HarmonicOptions options)
    : HarmonicSolver(std::move(system), {}, options) {}

HarmonicSolver::HarmonicSolver(LinearSystem system, std::vector<SparseMat> terms, HarmonicOptions options)
    : workspace_(std::make_unique<Workspace>()) {
  Workspace& w = *workspace_;
  w.options = options;
  const Eigen::Index n = system.stiffness.rows();
  CheckSystemMatrix(system.stiffness, n, "K", false);
  CheckSystemMatrix(system.mass, n, "M", false);
  CheckSystemMatrix(system.damping, n, "D", true);
  CheckSystemMatrix(system.gyroscopic, n, "G", true);
  for (const SparseMat& term : terms) CheckSystemMatrix(term, n, "a frequency term", false);
  for (SparseMat* matrix : {&system.stiffness, &system.mass, &system.damping,
                            &system.gyroscopic}) {
    matrix->makeCompressed();
  }
  // The union of the four patterns (Eigen keeps structural zeros of a sparse sum), with a
  // full diagonal so that a zero diagonal entry is never structurally missing.
  SparseMat pattern = system.stiffness.cwiseAbs() + system.mass.cwiseAbs();
  if (system.damping.size() > 0) pattern += system.damping.cwiseAbs();
  if (system.gyroscopic.size() > 0) pattern += system.gyroscopic.cwiseAbs();
  for (const SparseMat& term : terms) pattern += term.cwiseAbs();
  SparseMat identity(n, n);
  identity.setIdentity();
  pattern += identity;
  pattern.makeCompressed();
  w.matrix = pattern.cast<Complex>();
  w.matrix.makeCompressed();
  if (!options.block_starts.empty()) w.blocks.Analyze(pattern, options.block_starts);
  // A pattern slot's place in the storage the values are assembled in.
  const std::vector<Index>* offsets = w.blocks.analyzed() ? &w.blocks.slot_offsets() : nullptr;
  const Index storage = offsets ? w.blocks.storage_size() : pattern.nonZeros();
  auto on_storage = [&](const SparseMat& matrix) {
    std::vector<double> values = ValuesOnPattern(matrix, pattern);
    if (!offsets) return values;
    std::vector<double> placed(storage, 0.0);
    for (Index slot = 0; slot < std::ssize(values); ++slot) placed[(*offsets)[slot]] = values[slot];
    return placed;
  };
  MatricesOnStorage& m = w.on_storage;
  m.stiffness = on_storage(system.stiffness);
  m.mass = on_storage(system.mass);
  if (system.damping.size() > 0) m.damping = on_storage(system.damping);
  if (system.gyroscopic.size() > 0) m.gyroscopic = on_storage(system.gyroscopic);
  for (const SparseMat& term : terms) {
    auto& nonzeros = m.terms.emplace_back();
    auto& dense = m.dense_terms.emplace_back();
    if (4 * term.nonZeros() > pattern.nonZeros()) {
      dense = on_storage(term);
      continue;
    }
    const std::vector<double> values = ValuesOnPattern(term, pattern);
    for (Index slot = 0; slot < std::ssize(values); ++slot) {
      if (values[slot] != 0.0) nonzeros.emplace_back(offsets ? (*offsets)[slot] : slot, values[slot]);
    }
  }
  w.natural_order = FactorizeInOwnOrder(pattern);  // narrow bands keep their own order (linear_solver.hpp)
  if (n > 0) {
    if (w.natural_order) {
      w.lu_natural.analyzePattern(w.matrix);
    } else {
      w.lu_colamd.analyzePattern(w.matrix);
    }
  }
}

HarmonicSolver::~HarmonicSolver() = default;
HarmonicSolver::HarmonicSolver(HarmonicSolver&&) noexcept = default;
HarmonicSolver& HarmonicSolver::operator=(HarmonicSolver&&) noexcept = default;

Eigen::Index HarmonicSolver::size() const { return workspace_->matrix.rows(); }
bool HarmonicSolver::block_lu() const { return workspace_->blocks.analyzed(); }
int HarmonicSolver::block_fallbacks() const { return workspace_->block_fallbacks; }

namespace {

// max |Re z_i| + |Im z_i| of a column: the ∞-norm with |z| measured as |Re z| + |Im z| (within √2
// of the modulus, and no hypot per entry).
double MaxAbs(const Eigen::Ref<const Eigen::VectorXcd>& column) {
  return column.size() == 0 ? 0.0 : (column.real().cwiseAbs() + column.imag().cwiseAbs()).maxCoeff();
}

// max_c ‖R_c‖∞ / (‖A‖∞ ‖X_c‖∞ + ‖F_c‖∞) for the residual R = F − A X, every modulus as |Re| + |Im|.
double BackwardError(double matrix_norm, const ComplexMat& loads, const ComplexMat& x, const ComplexMat& residual) {
  double largest = 0.0;
  for (Eigen::Index c = 0; c < x.cols(); ++c) {
    const double scale = matrix_norm * MaxAbs(x.col(c)) + MaxAbs(loads.col(c));
    const double error = MaxAbs(residual.col(c));
    if (error > 0.0) largest = std::max(largest, scale > 0.0 ? error / scale : std::numeric_limits<double>::infinity());
  }
  return std::isfinite(largest) ? largest : std::numeric_limits<double>::infinity();
}

// The values of A(ω) on a storage: one pass over the matrices and the dense terms, then the sparse
// terms' entries (`imaginary` is scratch).
void AssembleOnStorage(const MatricesOnStorage& m, double frequency, double rotor_speed,
                       const std::vector<FrequencyTermCoefficients>& terms, Complex* values, Eigen::ArrayXd& imaginary) {
  const double omega2 = frequency * frequency;
  const Index entries = std::ssize(m.stiffness);
  using Strided = Eigen::Map<Eigen::ArrayXd, 0, Eigen::InnerStride<2>>;  // the real or imaginary parts
  Strided real(reinterpret_cast<double*>(values), entries);
  auto array = [entries](const std::vector<double>& v) { return Eigen::Map<const Eigen::ArrayXd>(v.data(), entries); };
  imaginary.setZero(entries);
  real = array(m.stiffness) - omega2 * array(m.mass);
  if (!m.damping.empty()) imaginary += frequency * array(m.damping);
  if (!m.gyroscopic.empty() && rotor_speed != 0.0) imaginary += frequency * rotor_speed * array(m.gyroscopic);
  for (Index t = 0; t < std::ssize(terms); ++t) {
    if (m.dense_terms[t].empty()) continue;
    if (terms[t].mass != 0.0) real -= omega2 * terms[t].mass * array(m.dense_terms[t]);
    if (terms[t].damping != 0.0) imaginary += frequency * terms[t].damping * array(m.dense_terms[t]);
  }
  Strided(reinterpret_cast<double*>(values) + 1, entries) = imaginary;
  for (Index t = 0; t < std::ssize(terms); ++t) {
    const Complex factor(-omega2 * terms[t].mass, frequency * terms[t].damping);
    if (factor == Complex(0.0, 0.0)) continue;
    for (const auto& [at, value] : m.terms[t]) values[at] += factor * value;
  }
}

}  // namespace

ComplexMat HarmonicSolver::Solve(double frequency, const ComplexMat& loads, double rotor_speed) {
  return Solve(frequency, loads, rotor_speed,
               std::vector<FrequencyTermCoefficients>(workspace_->on_storage.terms.size()));
}

ComplexMat HarmonicSolver::Solve(double frequency, const ComplexMat& loads, double rotor_speed,
                                 const std::vector<FrequencyTermCoefficients>& terms) {
  Workspace& w = *workspace_;
  if (terms.size() != w.on_storage.terms.size()) {
    throw LogicError(fmt::format("HarmonicSolver::Solve: {} term coefficients for {} terms", terms.size(),
                                 w.on_storage.terms.size()));
  }
  if (!std::isfinite(frequency) || frequency < 0.0 || !std::isfinite(rotor_speed)) {
    throw LogicError(fmt::format("HarmonicSolver::Solve: needs a finite ω ≥ 0 and a finite Ω "
                                 "(ω = {} rad/s, Ω = {} rad/s)", frequency, rotor_speed));
  }
  if (loads.rows() != size()) {
    throw LogicError(fmt::format("HarmonicSolver::Solve: the loads have {} rows, the system {}",
                                 loads.rows(), size()));
  }
  if (!loads.allFinite()) throw LogicError("HarmonicSolver::Solve: non-finite loads");
  if (size() == 0) return ComplexMat(0, loads.cols());
  // A = K − ω² M + iω (D + Ω G) + Σ_t (−ω² a_t + iω b_t) T_t on the storage in use.
  const bool blocked = w.blocks.analyzed();
  Complex* values = blocked ? w.blocks.values() : w.matrix.valuePtr();
  AssembleOnStorage(w.on_storage, frequency, rotor_speed, terms, values, w.imaginary);
  if (blocked) {
    w.blocks.Factorize();
    // Not a structured binding: the lambda below captures the norm, which clang before 16 refuses.
    const std::pair<double, double> norms = w.blocks.Norms();
    const double matrix_norm = norms.first, largest = norms.second;
    if (w.blocks.smallest_pivot() > w.options.singular_pivot_tolerance * largest) {
      ComplexMat x = w.blocks.Solve(loads), residual;
      auto backward_error = [&] {
        residual = loads - w.blocks.Multiply(x);
        return BackwardError(matrix_norm, loads, x, residual);
      };
      double error = backward_error();
      for (int step = 0; step < 2 && error > kBlockBackwardErrorTolerance; ++step) {  // iterative refinement
        x += w.blocks.Solve(residual);
        error = backward_error();
      }
      if (error <= kBlockBackwardErrorTolerance) return x;
    }
    ++w.block_fallbacks;  // a small pivot or a missed backward error: the general LU decides
    const std::vector<Index>& offsets = w.blocks.slot_offsets();
    Complex* pattern_values = w.matrix.valuePtr();
    for (Index slot = 0; slot < std::ssize(offsets); ++slot) pattern_values[slot] = values[offsets[slot]];
  }
  double largest2 = 0.0;  // max |a_ij|² (std::norm: no hypot per entry and frequency)
  for (Eigen::Index k = 0; k < w.matrix.nonZeros(); ++k) largest2 = std::max(largest2, std::norm(w.matrix.valuePtr()[k]));
  const double largest = std::sqrt(largest2);
  auto singular = [&](const std::string& why) {
    return SolverError(fmt::format(
        "harmonic response: K − ω²M + iω(D + ΩG) is singular at ω = {} rad/s ({} Hz), Ω = {} "
        "rad/s: {} (an undamped system driven at a natural frequency has no steady state)",
        frequency, frequency / (2.0 * kPi), rotor_speed, why));
  };
  auto factorize_and_solve = [&](auto& lu) -> ComplexMat {
    lu.factorize(w.matrix);
    if (lu.info() != Eigen::Success) throw singular("LU: " + lu.lastErrorMessage());
    const double smallest = lu.SmallestPivot();
    if (!(smallest > w.options.singular_pivot_tolerance * largest)) {
      throw singular(fmt::format("smallest pivot {:.3g} of largest entry {:.3g}", smallest,
                                 largest));
    }
    ComplexMat x = lu.solve(loads);
    if (lu.info() != Eigen::Success || !x.allFinite()) throw singular("non-finite solution");
    return x;
  };
  return w.natural_order ? factorize_and_solve(w.lu_natural)
                         : factorize_and_solve(w.lu_colamd);
}

void SweepHarmonicResponse(const LinearSystem& system, const HarmonicSweep& sweep,
                           const HarmonicLoads& loads, const HarmonicSink& sink,
                           HarmonicOptions options) {
  if (!sweep.rotor_speeds.empty() && sweep.rotor_speeds.size() != sweep.frequencies.size()) {
    throw LogicError(fmt::format("SweepHarmonicResponse: {} rotor speeds for {} frequencies",
                                 sweep.rotor_speeds.size(), sweep.frequencies.size()));
  }
  if (!loads || !sink) throw LogicError("SweepHarmonicResponse: loads and sink must be set");
  HarmonicSolver solver(system, options);
  for (Index j = 0; j < std::ssize(sweep.frequencies); ++j) {
    const Index point = j;
    const double frequency = sweep.frequencies[j];
    const double rotor_speed = sweep.rotor_speeds.empty() ? 0.0 : sweep.rotor_speeds[j];
    const ComplexMat response = solver.Solve(frequency, loads(point, frequency), rotor_speed);
    sink(point, frequency, response);
  }
}

std::vector<ComplexMat> SweepHarmonicResponse(const LinearSystem& system,
                                              const HarmonicSweep& sweep, const ComplexMat& loads,
                                              HarmonicOptions options) {
  std::vector<ComplexMat> responses;
  responses.reserve(sweep.frequencies.size());
  SweepHarmonicResponse(
      system, sweep, [&loads](Eigen::Index, double) { return loads; },
      [&responses](Eigen::Index, double, const ComplexMat& response) {
        responses.push_back(response);
      },
      options);
  return responses;
}

}  // namespace drillflex::solvers
