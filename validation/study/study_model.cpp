#include "study_model.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "cms/reduced_body.hpp"
#include "core/error.hpp"
#include "fe/material.hpp"
#include "model/builder.hpp"
#include "model/static_problem.hpp"
#include "solvers/eigen.hpp"
#include "solvers/newton.hpp"

namespace drillflex::study {
namespace {

const double kSecondMoment = kPi * std::pow(kDiameter, 4) / 64.0;
const double kArea = kPi * kDiameter * kDiameter / 4.0;
const double kBendingRigidity = kYoungsModulus * kSecondMoment;
// Tip deflection of the linear load cases. The exact (elastica) response is linear to 1e-7 already
// at L/1000, but the model is not: a spurious axial compression grows as (deflection/body
// length)² (docs/model-study.md (d)) and at L/1000 would hide the coupling compliance at c ≥ 1e4.
constexpr double kTipDeflection = kStaticDeflectionRatio * kLength;
// Two frequencies are one bending pair (y and z planes of the round rod) when this close
// (measured round-off splits: below 1e-6).
constexpr double kPairTolerance = 1e-5;

// The clamped V1 rod: one component, cut into `bodies` equal bodies, clamp at s = 0.
model::ModelInput CantileverInput(const ModelConfig& config) {
  model::ModelInput input;
  model::Component rod;
  rod.type = model::ComponentType::Collar;
  rod.outer_diameter = kDiameter;
  rod.inner_diameter = 0.0;
  rod.length = kLength;
  rod.material = "rod";
  input.string.components.push_back(rod);
  input.materials["rod"] = fe::Material{"rod", kYoungsModulus, kPoissonRatio, kDensity};
  model::ModelSettings& settings = input.settings;
  settings.body_length = kLength / config.bodies + 1e-9;
  settings.elements_per_body = config.elements_per_body;
  settings.modes_per_body = config.modes_per_body;
  settings.coupling_factor = config.coupling_factor;
  settings.mass = config.mass;
  settings.rotary_inertia = config.rotary_inertia;
  model::Support clamp;
  clamp.at = 0.0;
  clamp.fixed.fill(true);
  input.supports = {clamp};
  return input;
}

// Loads giving a tip deflection δ in +y: P = 3EIδ/L³, q = 8EIδ/L⁴, M = 2EIδ/L²
// (Euler–Bernoulli cantilever, e.g. Roark's Formulas for Stress and Strain, Table 8.1).
model::Load StaticLoad(StaticCase which, double deflection) {
  model::Load load;
  const double scale = kBendingRigidity * deflection;
  switch (which) {
    case kTipForce:
      load.at = kLength;
      load.force = Vec3(0.0, 3.0 * scale / std::pow(kLength, 3), 0.0);
      break;
    case kUniformLoad:
      load.distributed = true;
      load.from = 0.0;
      load.to = kLength;
      load.force_per_length = Vec3(0.0, 8.0 * scale / std::pow(kLength, 4), 0.0);
      break;
    case kTipMoment:
      load.at = kLength;
      load.moment = Vec3(0.0, 0.0, 2.0 * scale / (kLength * kLength));  // +M_z bends toward +y
      break;
  }
  return load;
}

// Static tip deflection (y of the last node) under one load, m.
double TipDeflection(const ModelConfig& config, const model::Load& load, cms::ReductionCache& cache) {
  model::ModelInput input = CantileverInput(config);
  input.loads = {load};
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  model::StaticModelProblem problem(built.system);
  solvers::NewtonOptions options;  // as recommended for this model (model-orientation notes)
  options.increment_tolerance = 1e-10;
  options.line_search.enabled = false;
  const solvers::NewtonResult result = solvers::SolveStatic(problem, built.system.ReferencePositions(), options);
  const model::Body& tip_body = built.system.bodies().back();
  return built.system.Poses(result.q).back().NodePosition(tip_body, tip_body.node_count() - 1).y();
}

// Squared nodal motions of a mode (velocities δv = (δr, δθ, δη) of every body), linearized at the
// straight reference state where every body frame is the global frame: node k moves by
// δr + δθ × ρ_k + Φ_k δη and twists by δθ_x + (Ψ_k δη)_x (method.md §4).
struct ModeContent {
  double axial = 0.0, lateral_y = 0.0, lateral_z = 0.0, torsion = 0.0;  // m² (torsion: twist × radius)
  bool IsBending() const { return lateral_y + lateral_z > axial + torsion; }
};

ModeContent ContentOf(const model::SystemModel& system, const VecX& mode) {
  ModeContent content;
  const double radius = 0.5 * kDiameter;
  for (const model::Body& body : system.bodies()) {
    const cms::ReducedBody& reduced = *body.reduced;
    const Vec3 dr = mode.segment<3>(body.v_offset);
    const Vec3 dtheta = mode.segment<3>(body.v_offset + 3);
    const VecX deta = mode.segment(body.v_offset + 6, body.flexible_count);
    for (int k = 0; k < body.node_count(); ++k) {
      const Vec3 d = dr + dtheta.cross(reduced.node_positions[k]) + reduced.node_translation_modes[k] * deta;
      const double twist = radius * (dtheta.x() + reduced.node_rotation_modes[k].row(0).dot(deta));
      content.axial += d.x() * d.x();
      content.lateral_y += d.y() * d.y();
      content.lateral_z += d.z() * d.z();
      content.torsion += twist * twist;
    }
  }
  return content;
}

// Bending frequencies (Hz, ascending) in the x-y and x-z planes. A degenerate pair (equal y and z
// frequencies, its modes any mix of the two planes) counts once in each plane; a single bending
// mode goes to the plane it moves in. The planes differ only when modes_per_body cuts a y/z pair
// of fixed-interface modes (the reduction keeps one of the two).
struct PlaneFrequencies {
  std::vector<double> y, z;
};

PlaneFrequencies BendingFrequencies(const model::SystemModel& system, const VecX& hz, const MatX& modes) {
  std::vector<Eigen::Index> bending;
  for (Eigen::Index j = 0; j < hz.size(); ++j) {
    if (ContentOf(system, modes.col(j)).IsBending()) bending.push_back(j);
  }
  PlaneFrequencies planes;
  for (std::size_t i = 0; i < bending.size(); ++i) {
    const double f = hz[bending[i]];
    if (i + 1 < bending.size() && std::abs(hz[bending[i + 1]] - f) <= kPairTolerance * f) {
      const double mean = 0.5 * (f + hz[bending[i + 1]]);
      planes.y.push_back(mean);
      planes.z.push_back(mean);
      ++i;
    } else {
      const ModeContent content = ContentOf(system, modes.col(bending[i]));
      (content.lateral_y > content.lateral_z ? planes.y : planes.z).push_back(f);
    }
  }
  return planes;
}

// Natural frequencies (Hz, ascending) and modes of K x = ω² M x from the inverse problem
// M x = μ K x, μ = 1/ω² (K is positive definite: the rod is clamped). The stiff couplings spread
// K's eigenvalues over ~1e13; the direct problem resolves every ω² only to round-off × ω_max²
// (measured: the two frequencies of a y/z pair 1e-5 apart with 16 bodies), the inverse one the
// low modes to round-off × their own size.
void ModesFromInverse(const SparseMat& stiffness, const SparseMat& mass, VecX& hz, MatX& modes) {
  const solvers::ModalResult inverse = solvers::SolveModes(mass, stiffness, static_cast<int>(mass.rows()));
  hz = inverse.eigenvalues.reverse().unaryExpr([](double mu) { return 1.0 / (2.0 * kPi * std::sqrt(mu)); });
  modes = inverse.vectors.rowwise().reverse();
}

// Stiffness (cK = 1) and mass matrices of a model at its reference state (v = a = 0, no load).
struct ReferenceMatrices {
  SparseMat stiffness, mass;
  explicit ReferenceMatrices(const model::SystemModel& system) {
    const VecX q = system.ReferencePositions();
    const VecX zero = VecX::Zero(system.num_velocities());
    stiffness = system.IterationMatrix(0.0, q, zero, zero, 1.0, 1.0, 0.0, 0.0);
    mass = system.MassMatrix(q);
  }
  // The highest natural frequency (rad/s) from the direct problem, accurate at the top of the spectrum.
  double HighestFrequency() const {
    return std::sqrt(solvers::SolveModes(stiffness, mass, static_cast<int>(mass.rows())).eigenvalues.maxCoeff());
  }
};

// All modes of the clamped model (dense: at most a few hundred coordinates): the bending
// frequency errors (the larger |error| of the two planes) and the highest frequency; then the highest
// frequency without the clamp (couplings only).
void MeasureModes(const ModelConfig& config, cms::ReductionCache& cache, Measurement& out) {
  model::ModelInput input = CantileverInput(config);
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const ReferenceMatrices clamped(built.system);
  VecX hz;
  MatX modes;
  ModesFromInverse(clamped.stiffness, clamped.mass, hz, modes);
  const PlaneFrequencies planes = BendingFrequencies(built.system, hz, modes);
  if (static_cast<int>(std::min(planes.y.size(), planes.z.size())) < kFrequencyCount) {
    throw SolverError(fmt::format("model study ({} bodies, {} elements, {} modes, c = {}): fewer than four bending "
                                  "modes in each plane", config.bodies, config.elements_per_body,
                                  config.modes_per_body, config.coupling_factor));
  }
  for (int n = 0; n < kFrequencyCount; ++n) {
    const double exact = ExactFrequencyHz(n);
    const double error_y = planes.y[n] / exact - 1.0, error_z = planes.z[n] / exact - 1.0;
    out.frequency_error[n] = std::abs(error_y) > std::abs(error_z) ? error_y : error_z;
    out.plane_split = std::max(out.plane_split, std::abs(error_y - error_z));
  }
  out.coordinates = built.system.num_velocities();
  out.omega_max = clamped.HighestFrequency();
  out.body_omega_max = built.system.bodies().front().reduced->natural_frequencies.maxCoeff();
  input.supports.clear();
  out.omega_max_free = ReferenceMatrices(model::BuildSystemModel(input, cache).system).HighestFrequency();
}

double MaxAbs(const auto& values) {
  double largest = 0.0;
  for (double value : values) largest = std::max(largest, std::abs(value));
  return largest;
}

}  // namespace

double Measurement::MaxFrequencyError() const { return MaxAbs(frequency_error); }
double Measurement::MaxStaticError() const { return MaxAbs(static_error); }

double ExactFrequencyHz(int n) {
  static constexpr double kBetaL[kFrequencyCount] = {1.8751041, 4.6940911, 7.8547574, 10.995541};
  return kBetaL[n] * kBetaL[n] / (2.0 * kPi * kLength * kLength) *
         std::sqrt(kBendingRigidity / (kDensity * kArea));
}

Measurement Measure(const ModelConfig& config, cms::ReductionCache& cache) {
  Measurement out;
  MeasureModes(config, cache, out);
  for (int c = 0; c < kStaticCaseCount; ++c) {
    const auto which = static_cast<StaticCase>(c);
    out.static_error[c] = TipDeflection(config, StaticLoad(which, kTipDeflection), cache) / kTipDeflection - 1.0;
  }
  return out;
}

double RotaryInertiaShift(int n) {
  // Rayleigh quotient with the Euler–Bernoulli shape φ(x): ω² = EI∫φ''² / (ρA∫φ² + ρI∫φ'²), so
  // ω_Rayleigh/ω_EB = (1 + (I/A) ∫φ'²/∫φ²)^(-1/2) to first order in I/A (Rayleigh's beam; e.g.
  // Géradin & Rixen, "Mechanical Vibrations", §5). Cantilever shape (Blevins, Table 8-1):
  // φ = cosh βx − cos βx − σ (sinh βx − sin βx), σ = (cosh βL + cos βL)/(sinh βL + sin βL).
  static constexpr double kBetaL[kFrequencyCount] = {1.8751041, 4.6940911, 7.8547574, 10.995541};
  const double beta = kBetaL[n] / kLength;
  const double sigma = (std::cosh(kBetaL[n]) + std::cos(kBetaL[n])) / (std::sinh(kBetaL[n]) + std::sin(kBetaL[n]));
  constexpr int kIntervals = 4000;  // Simpson's rule, even count
  double shape = 0.0, slope = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double bx = beta * kLength * i / kIntervals;
    const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const double phi = std::cosh(bx) - std::cos(bx) - sigma * (std::sinh(bx) - std::sin(bx));
    const double dphi = beta * (std::sinh(bx) + std::sin(bx) - sigma * (std::cosh(bx) - std::cos(bx)));
    shape += weight * phi * phi;
    slope += weight * dphi * dphi;
  }
  return 1.0 / std::sqrt(1.0 + kSecondMoment / kArea * slope / shape) - 1.0;
}

MomentArcErrors MomentArcError(const ModelConfig& config, double tip_rotation, cms::ReductionCache& cache) {
  // M = EI φ/L; linear theory δ = M L²/(2EI) = φL/2; the exact elastica under an end moment is a
  // circular arc of radius R = EI/M = L/φ: δ = R (1 − cos φ) (planar bending: the dead moment
  // about z stays the bending moment).
  const double linear = 0.5 * tip_rotation * kLength;
  const double arc = kLength / tip_rotation * (1.0 - std::cos(tip_rotation));
  const double deflection = TipDeflection(config, StaticLoad(kTipMoment, linear), cache);
  return {deflection / linear - 1.0, deflection / arc - 1.0};
}

}  // namespace drillflex::study
