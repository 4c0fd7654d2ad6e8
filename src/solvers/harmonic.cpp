#include "solvers/harmonic.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
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
    double smallest = std::numeric_limits<double>::infinity();
    for (Eigen::Index j = 0; j < this->cols(); ++j) {
      double pivot = 0.0;  // a column without a stored diagonal has a zero pivot
      for (typename decltype(this->m_Lstore)::InnerIterator it(this->m_Lstore, j); it; ++it) {
        if (it.index() == j) {
          pivot = std::abs(it.value());
          break;
        }
      }
      smallest = std::min(smallest, pivot);
    }
    return smallest;
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
  std::vector<double> values(static_cast<std::size_t>(pattern.nonZeros()), 0.0);
  if (matrix.size() == 0) return values;
  for (Eigen::Index col = 0; col < pattern.outerSize(); ++col) {
    Eigen::Index slot = pattern.outerIndexPtr()[col];
    const Eigen::Index end = pattern.outerIndexPtr()[col + 1];
    for (SparseMat::InnerIterator it(matrix, col); it; ++it) {
      while (slot < end && pattern.innerIndexPtr()[slot] < it.row()) ++slot;
      if (slot == end || pattern.innerIndexPtr()[slot] != it.row()) {
        throw LogicError("HarmonicSolver: an entry lies outside the union pattern");
      }
      values[static_cast<std::size_t>(slot)] += it.value();
    }
  }
  return values;
}

}  // namespace

struct HarmonicSolver::Workspace {
  HarmonicOptions options;
  ComplexSparse matrix;  // the union pattern; values rewritten at every frequency
  std::vector<double> stiffness, mass, damping, gyroscopic;  // on that pattern
  // The frequency terms' nonzeros: (slot on the pattern, value).
  std::vector<std::vector<std::pair<std::size_t, double>>> terms;
  bool natural_order = false;
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
  w.stiffness = ValuesOnPattern(system.stiffness, pattern);
  w.mass = ValuesOnPattern(system.mass, pattern);
  w.damping = ValuesOnPattern(system.damping, pattern);
  w.gyroscopic = ValuesOnPattern(system.gyroscopic, pattern);
  for (const SparseMat& term : terms) {
    const std::vector<double> values = ValuesOnPattern(term, pattern);
    auto& nonzeros = w.terms.emplace_back();
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (values[k] != 0.0) nonzeros.emplace_back(k, values[k]);
    }
  }
  w.matrix = pattern.cast<Complex>();
  w.matrix.makeCompressed();
  // Band fill n·b against the entries (linear_solver.hpp): narrow bands keep their own order.
  w.natural_order = static_cast<double>(n) * static_cast<double>(HalfBandwidth(pattern)) <=
                    8.0 * static_cast<double>(std::max<Eigen::Index>(pattern.nonZeros(), 1));
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

ComplexMat HarmonicSolver::Solve(double frequency, const ComplexMat& loads, double rotor_speed) {
  return Solve(frequency, loads, rotor_speed,
               std::vector<FrequencyTermCoefficients>(workspace_->terms.size()));
}

ComplexMat HarmonicSolver::Solve(double frequency, const ComplexMat& loads, double rotor_speed,
                                 const std::vector<FrequencyTermCoefficients>& terms) {
  Workspace& w = *workspace_;
  if (terms.size() != w.terms.size()) {
    throw LogicError(fmt::format("HarmonicSolver::Solve: {} term coefficients for {} terms", terms.size(),
                                 w.terms.size()));
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
  // A = K − ω² M + iω (D + Ω G), entry by entry on the shared pattern.
  const double omega2 = frequency * frequency;
  Complex* values = w.matrix.valuePtr();
  double largest2 = 0.0;  // max |a_ij|² (std::norm: no hypot per entry and frequency)
  for (std::size_t k = 0; k < w.stiffness.size(); ++k) {
    values[k] = Complex(w.stiffness[k] - omega2 * w.mass[k],
                        frequency * (w.damping[k] + rotor_speed * w.gyroscopic[k]));
  }
  for (std::size_t t = 0; t < terms.size(); ++t) {
    const Complex factor(-omega2 * terms[t].mass, frequency * terms[t].damping);
    if (factor == Complex(0.0, 0.0)) continue;
    for (const auto& [slot, value] : w.terms[t]) values[slot] += factor * value;
  }
  for (std::size_t k = 0; k < w.stiffness.size(); ++k) largest2 = std::max(largest2, std::norm(values[k]));
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
  for (std::size_t j = 0; j < sweep.frequencies.size(); ++j) {
    const auto point = static_cast<Eigen::Index>(j);
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
