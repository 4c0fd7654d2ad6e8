// Modes of the spinning string on a projected quadratic eigenproblem (gyroscopic_modes.hpp).
#include "analyses/gyroscopic_modes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include <fmt/format.h>

#include "analyses/response_solver.hpp"
#include "analyses/string_stations.hpp"
#include "core/error.hpp"
#include "model/gyroscopic_element.hpp"
#include "model/node_kinematics.hpp"
#include "solvers/eigen.hpp"

namespace drillflex::analyses {
namespace {

using Complex = std::complex<double>;

// Below this the projected eigenvalues are near zero or real (2π × 0.01 Hz, rad/s).
constexpr double kLeastFrequency = 2.0 * kPi * kNearZeroFrequencyHz;

// The basis: the lowest 2·count + 10 undamped modes, plus as many as are near zero or of negative
// stiffness among them (they hold no whirl of interest but take places in the basis).
solvers::ModalResult UndampedBasis(const SparseMat& stiffness, const SparseMat& mass, int count) {
  const Index n = stiffness.rows();
  const Index wanted = std::min<Index>(n, 2 * count + 10);
  solvers::ModalResult modal = solvers::SolveModes(stiffness, mass, wanted);
  const Index excluded = (modal.eigenvalues.array() < kLeastFrequency * kLeastFrequency).count();
  if (excluded > 0 && wanted < n) modal = solvers::SolveModes(stiffness, mass, std::min(n, wanted + excluded));
  return modal;
}

MatX Project(const SparseMat& matrix, const MatX& basis) {
  const MatX product = matrix * basis;
  return basis.transpose() * product;
}

}  // namespace

struct GyroscopicModeSolver::Data {
  const model::SystemModel* model = nullptr;
  int count = 0;
  model::LateralFluid fluid;  // the case's, or empty
  SweepSystem sweep;          // K, M (steel, bore fluid), D and the annulus groups' terms
  MatX basis;                 // Φ, n × r
  MatX stiffness, mass, damping, gyroscopic;  // projected, r × r
  std::vector<MatX> annulus;                  // Φᵀ U_g Φ of each annulus group
  double structural = 0.0;                    // ζ_s
  std::vector<model::BodyPose> poses;
  std::vector<Station> stations;

  // M(ω) and D(ω) + Ω G of the projected problem (the annulus terms at ω).
  void MatricesAt(double frequency, double spin, MatX& m, MatX& d) const {
    m = mass;
    d = damping + spin * gyroscopic;
    const std::vector<solvers::FrequencyTermCoefficients> c = SweepTermCoefficients(sweep, frequency);
    for (Index g = 0; g < std::ssize(annulus); ++g) {
      m += c[g].mass * annulus[g];
      d += c[g].damping * annulus[g];
    }
  }

  // The fixed point of a mode's frequency with the fluid at that frequency: re-solve at Im s and
  // keep the mode most like the previous one (the largest |x_oldᴴ x|² / (|x_old|² |x|²) in the
  // basis coordinates, M_ref-orthonormal: the nearest eigenvalue is not enough, as the heavier
  // viscous added mass moves the next mode of a close pair onto the old frequency), until the
  // eigenvalue moves by less than 1e-9 |s|.
  void Refine(double spin, Complex& s, Eigen::VectorXcd& x) const {
    MatX m, d;
    for (int iteration = 0; iteration < 30; ++iteration) {
      MatricesAt(s.imag(), spin, m, d);
      const solvers::ComplexModes modes = solvers::SolveDampedModes(stiffness, d, m, stiffness.rows());
      Eigen::Index best = 0;
      double likeness = -1.0;
      for (Eigen::Index j = 0; j < modes.eigenvalues.size(); ++j) {
        if (!(modes.eigenvalues[j].imag() > 0.0)) continue;
        const double overlap = std::norm(x.dot(modes.vectors.col(j))) / (x.squaredNorm() * modes.vectors.col(j).squaredNorm());
        if (overlap > likeness) likeness = overlap, best = j;
      }
      const bool done = std::abs(modes.eigenvalues[best] - s) <= 1e-9 * std::abs(s);
      s = modes.eigenvalues[best];
      x = modes.vectors.col(best);
      if (done) break;
    }
  }

  ModeResult Describe(Complex s, const Eigen::VectorXcd& reduced, bool shapes) const;
};

ModeResult GyroscopicModeSolver::Data::Describe(Complex s, const Eigen::VectorXcd& reduced, bool shapes) const {
  Eigen::VectorXcd x(basis.rows());
  x.real() = basis * reduced.real();
  x.imag() = basis * reduced.imag();
  ModeResult mode;
  mode.frequency_hz = s.imag() / (2.0 * kPi);
  mode.eigenvalue = s.imag() * s.imag();
  mode.damping_ratio = structural - s.real() / std::abs(s);
  const VecX re = x.real(), im = x.imag();
  const EnergySplit a = SplitKineticEnergy(*model, poses, re), b = SplitKineticEnergy(*model, poses, im);
  const double total = a.axial + b.axial + a.torsional + b.torsional + a.lateral + b.lateral;
  if (total > 0.0) {
    mode.axial_fraction = (a.axial + b.axial) / total;
    mode.torsional_fraction = (a.torsional + b.torsional) / total;
    mode.lateral_fraction = (a.lateral + b.lateral) / total;
  }
  if (mode.axial_fraction > std::max(mode.lateral_fraction, mode.torsional_fraction)) mode.kind = ModeKind::Axial;
  if (mode.torsional_fraction > std::max(mode.lateral_fraction, mode.axial_fraction)) mode.kind = ModeKind::Torsional;
  // The orbits' sense: Re(Y e^{iωt}), Re(Z e^{iωt}) turn about +x at the mean rate ∝ Im(Y Z̄).
  double turn = 0.0, size = 0.0;
  for (const Station& station : stations) {
    const model::Body& body = model->bodies()[station.body];
    const Vec3 real = model::ComputeStringFrameNodeRates(body, poses[station.body], re, station.node).translation;
    const Vec3 imaginary =
        model::ComputeStringFrameNodeRates(body, poses[station.body], im, station.node).translation;
    const Complex y(real.y(), imaginary.y()), z(real.z(), imaginary.z());
    turn += 2.0 * (y * std::conj(z)).imag();
    size += std::norm(y) + std::norm(z);
  }
  mode.whirl_index = size > 0.0 ? -turn / size : 0.0;
  mode.whirl = mode.kind != ModeKind::Lateral                     ? Whirl::None
               : std::abs(mode.whirl_index) <= kPlanarWhirlIndex ? Whirl::Planar
               : mode.whirl_index > 0.0                           ? Whirl::Forward
                                                                  : Whirl::Backward;
  if (shapes) {
    Eigen::Index largest = 0;
    x.cwiseAbs().maxCoeff(&largest);
    const Eigen::VectorXcd turned = x * (std::conj(x[largest]) / std::abs(x[largest]));
    mode.vector = turned.real();
    FillShape(*model, poses, stations, mode);
  }
  return mode;
}

GyroscopicModeSolver::GyroscopicModeSolver(const model::SystemModel& model, const VecX& q, int count,
                                           const model::LateralFluid* fluid)
    : data_(std::make_unique<Data>()) {
  if (count < 1) throw LogicError("GyroscopicModeSolver: count must be at least 1");
  Data& d = *data_;
  d.model = &model;
  d.count = count;
  if (fluid) d.fluid = *fluid;
  d.sweep = AssembleSweepSystem(model, d.fluid, q);
  d.structural = 0.5 * d.sweep.loss_factor;
  const solvers::ModalResult modal = UndampedBasis(d.sweep.system.stiffness, ReferenceMass(d.sweep, 0.0), count);
  d.basis = modal.vectors;
  d.stiffness = Project(d.sweep.system.stiffness, d.basis);
  d.stiffness = 0.5 * (d.stiffness + d.stiffness.transpose()).eval();
  d.mass = Project(d.sweep.system.mass, d.basis);
  d.mass = 0.5 * (d.mass + d.mass.transpose()).eval();
  d.damping = Project(d.sweep.system.damping, d.basis);
  d.gyroscopic = Project(model::ComputeGyroscopicMatrix(model, q), d.basis);
  for (Index g = 0; g < std::ssize(d.sweep.annulus_radii); ++g) d.annulus.push_back(Project(d.sweep.terms[g], d.basis));
  d.poses = model.Poses(q);
  d.stations = StringStations(model);
}

GyroscopicModeSolver::~GyroscopicModeSolver() = default;
GyroscopicModeSolver::GyroscopicModeSolver(GyroscopicModeSolver&&) noexcept = default;
GyroscopicModeSolver& GyroscopicModeSolver::operator=(GyroscopicModeSolver&&) noexcept = default;

Index GyroscopicModeSolver::basis_size() const { return data_->basis.cols(); }

ModesResult GyroscopicModeSolver::Solve(double spin, ModeKind kind, bool shapes) const {
  const Data& d = *data_;
  const bool viscous = d.sweep.fluid != nullptr && d.fluid.frequency_dependent();
  MatX m, damping;
  d.MatricesAt(0.0, spin, m, damping);
  const Index r = d.stiffness.rows();
  const solvers::ComplexModes base = solvers::SolveDampedModes(d.stiffness, damping, m, r);
  std::vector<Eigen::Index> order;
  for (Eigen::Index j = 0; j < base.eigenvalues.size(); ++j) {
    if (base.eigenvalues[j].imag() > kLeastFrequency) order.push_back(j);
  }
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return base.eigenvalues[a].imag() < base.eigenvalues[b].imag();
  });
  ModesResult result;
  for (const Station& station : d.stations) result.s.push_back(station.s);
  for (const Eigen::Index j : order) {
    Complex s = base.eigenvalues[j];
    Eigen::VectorXcd x = base.vectors.col(j);
    if (viscous) d.Refine(spin, s, x);
    ModeResult mode = d.Describe(s, x, shapes);
    if (kind == ModeKind::Lateral && mode.kind != ModeKind::Lateral) continue;
    result.modes.push_back(std::move(mode));
    if (std::ssize(result.modes) == d.count) break;
  }
  std::stable_sort(result.modes.begin(), result.modes.end(),
                   [](const ModeResult& a, const ModeResult& b) { return a.frequency_hz < b.frequency_hz; });
  return result;
}

ModesResult ComputeGyroscopicModes(const model::SystemModel& model, const VecX& q, const ModesSettings& settings,
                                   const model::LateralFluid* fluid) {
  if (settings.kind != ModeKind::All && settings.kind != ModeKind::Lateral) {
    throw InputError({}, "analyses.modes.kind", "the gyroscopic modes are of kind all or lateral");
  }
  const GyroscopicModeSolver solver(model, q, settings.count, fluid);
  ModesResult result = solver.Solve(settings.rotary_speed, settings.kind, true);
  result.gyroscopic = true;
  result.rotary_speed = settings.rotary_speed;
  result.basis_size = solver.basis_size();
  return result;
}

CampbellResult ComputeCampbell(const model::SystemModel& model, const VecX& q, const ModesSettings& settings,
                               const model::LateralFluid* fluid) {
  if (!settings.campbell) throw LogicError("ComputeCampbell: no speed range");
  if (settings.kind != ModeKind::All && settings.kind != ModeKind::Lateral) {
    throw InputError({}, "analyses.modes.kind", "the gyroscopic modes are of kind all or lateral");
  }
  const SpeedRange& range = *settings.campbell;
  const GyroscopicModeSolver solver(model, q, settings.count, fluid);
  CampbellResult result;
  result.basis_size = solver.basis_size();
  const Index points = std::lround(std::floor((range.to - range.from) / range.step + 1e-9)) + 1;
  for (Index i = 0; i < points; ++i) {
    CampbellPoint point;
    point.rotary_speed = range.from + i * range.step;
    point.modes = solver.Solve(point.rotary_speed, settings.kind, false).modes;
    for (ModeResult& mode : point.modes) mode.vector.resize(0);
    result.points.push_back(std::move(point));
  }
  result.synchronous = FindSynchronousCrossings(result.points);
  return result;
}

std::vector<CampbellCrossing> FindSynchronousCrossings(const std::vector<CampbellPoint>& points) {
  std::vector<CampbellCrossing> crossings;
  for (Index i = 0; i + 1 < std::ssize(points); ++i) {
    const CampbellPoint &a = points[i], &b = points[i + 1];
    const Index branches = std::min(std::ssize(a.modes), std::ssize(b.modes));
    for (Index j = 0; j < branches; ++j) {
      // g = ω_j − Ω (rad/s) changes sign across the crossing; the j-th lowest frequency is continuous.
      const double ga = 2.0 * kPi * a.modes[j].frequency_hz - a.rotary_speed;
      const double gb = 2.0 * kPi * b.modes[j].frequency_hz - b.rotary_speed;
      if (!(ga > 0.0 && gb <= 0.0) && !(ga < 0.0 && gb >= 0.0)) continue;
      const double t = ga / (ga - gb);
      CampbellCrossing crossing;
      crossing.rotary_speed = a.rotary_speed + t * (b.rotary_speed - a.rotary_speed);
      crossing.frequency_hz = a.modes[j].frequency_hz + t * (b.modes[j].frequency_hz - a.modes[j].frequency_hz);
      crossing.branch = j;
      crossing.whirl = (t < 0.5 ? a : b).modes[j].whirl;
      crossings.push_back(crossing);
    }
  }
  std::stable_sort(crossings.begin(), crossings.end(),
                   [](const CampbellCrossing& x, const CampbellCrossing& y) { return x.rotary_speed < y.rotary_speed; });
  return crossings;
}

}  // namespace drillflex::analyses
