#include "analyses/modes_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Cholesky>

#include "core/dense_eigen.hpp"
#include "core/error.hpp"
#include "model/node_kinematics.hpp"
#include "solvers/buckling.hpp"
#include "solvers/eigen.hpp"

namespace drillflex::analyses {
// Kinetic energy ½ vᵀ M v of a mode split by kind with the lumped nodal masses (method.md §4):
// body-frame node velocity t_k = Aᵀṙ + ω × u_k + Φ_k η̇ and rotation w_k = ω + Ψ_k η̇; axial
// ½ m_k t_x², torsional ½ J_x w_x², lateral the rest (t_y, t_z with the fluid mass, and the
// bending rotations w_y, w_z). "Axial" is along the local body axis.
EnergySplit SplitKineticEnergy(const model::SystemModel& model, const std::vector<model::BodyPose>& poses,
                               const VecX& v) {
  EnergySplit split;
  for (Index b = 0; b < std::ssize(model.bodies()); ++b) {
    const model::Body& body = model.bodies()[b];
    const cms::ReducedBody& reduced = *body.reduced;
    const VecX body_velocity = v.segment(body.v_offset, body.velocity_count());
    for (Index k = 0; k < body.node_count(); ++k) {
      const model::NodeRates rates = model::ComputeBodyFrameNodeRates(body, poses[b], k, body_velocity);
      const Vec3& t = rates.translation;
      const Vec3& w = rates.rotation;
      const Mat3 mass = reduced.NodeTranslationalMass(k);
      const Mat3& inertia = reduced.node_rotary_inertia[k];
      split.axial += 0.5 * mass(0, 0) * t.x() * t.x();
      split.lateral += 0.5 * (mass(1, 1) * t.y() * t.y() + mass(2, 2) * t.z() * t.z());
      split.torsional += 0.5 * inertia(0, 0) * w.x() * w.x();
      const Eigen::Vector2d bending = w.tail<2>();
      split.lateral += 0.5 * bending.dot(inertia.bottomRightCorner<2, 2>() * bending);
    }
  }
  return split;
}

// Mode shape per station in the string frame, scaled to max |displacement| = 1 (a torsional
// mode: max |rotation| = 1), with the largest component of the largest entry positive.
void FillShape(const model::SystemModel& model, const std::vector<model::BodyPose>& poses,
               const std::vector<Station>& stations, ModeResult& mode) {
  mode.displacement.clear();
  mode.rotation.clear();
  for (const Station& station : stations) {
    const model::Body& body = model.bodies()[station.body];
    const model::NodeRates node = model::ComputeStringFrameNodeRates(body, poses[station.body], mode.vector, station.node);
    mode.displacement.push_back(node.translation);
    mode.rotation.push_back(node.rotation);
  }
  const std::vector<Vec3>& measure = mode.kind == ModeKind::Torsional ? mode.rotation : mode.displacement;
  std::size_t largest = 0;
  for (Index i = 0; i < std::ssize(measure); ++i) {
    if (measure[i].norm() > measure[largest].norm()) largest = i;
  }
  if (measure.empty() || measure[largest].norm() == 0.0) return;
  Eigen::Index component = 0;
  measure[largest].cwiseAbs().maxCoeff(&component);
  const double scale = (measure[largest][component] < 0.0 ? -1.0 : 1.0) / measure[largest].norm();
  for (Vec3& d : mode.displacement) d *= scale;
  for (Vec3& r : mode.rotation) r *= scale;
}

namespace {

ModeResult DescribeMode(const model::SystemModel& model, const std::vector<model::BodyPose>& poses,
                        const std::vector<Station>& stations, double eigenvalue, const VecX& vector) {
  ModeResult mode;
  mode.eigenvalue = eigenvalue;
  mode.frequency_hz = eigenvalue > 0.0 ? std::sqrt(eigenvalue) / (2.0 * kPi) : 0.0;
  mode.vector = vector;
  const EnergySplit split = SplitKineticEnergy(model, poses, vector);
  const double total = split.axial + split.torsional + split.lateral;
  if (total > 0.0) {
    mode.axial_fraction = split.axial / total;
    mode.torsional_fraction = split.torsional / total;
    mode.lateral_fraction = split.lateral / total;
  }
  mode.kind = ModeKind::Lateral;
  if (mode.axial_fraction > std::max(mode.lateral_fraction, mode.torsional_fraction)) mode.kind = ModeKind::Axial;
  if (mode.torsional_fraction > std::max(mode.lateral_fraction, mode.axial_fraction)) mode.kind = ModeKind::Torsional;
  FillShape(model, poses, stations, mode);
  return mode;
}

// The frequency (corrected for a viscous fluid's C_m(ω)) and damping ratio of an undamped mode:
// the fixed point ω² = φᵀKφ / (φᵀM_sφ + Σ m_k(ω) s_k), s_k = |J_lat,k φ|² (model/lateral_fluid.hpp),
// then ζ = ζ_s + (φᵀDφ + Σ c_k(ω) s_k) / (2 ω (φᵀM_sφ + Σ m_k(ω) s_k)).
void SetFrequencyAndDamping(const model::SystemModel& model, const VecX& q, const LinearizedSystem& system,
                            const model::LateralFluid* fluid, ModeResult& mode) {
  if (mode.rigid_body || mode.eigenvalue <= 0.0) return;
  const VecX& phi = mode.vector;
  const double stiffness = phi.dot(system.stiffness * phi);
  const double steel = phi.dot(system.mass * phi);
  const double structural_damping = phi.dot(system.damping * phi);
  std::vector<double> squares;
  if (fluid && !fluid->empty()) squares = model::LateralNodeSquares(model, *fluid, q, phi);
  auto fluid_terms = [&](double omega) {
    model::NodeFluidTerms sum;
    for (Index k = 0; k < std::ssize(squares); ++k) {
      const model::NodeFluidTerms terms = model::ComputeNodeFluidTerms(*fluid, k, omega);
      sum.mass += terms.mass * squares[k];
      sum.damping += terms.damping * squares[k];
    }
    return sum;
  };
  double omega = std::sqrt(mode.eigenvalue);
  if (fluid && fluid->frequency_dependent()) {
    for (Index iteration = 0; iteration < 100; ++iteration) {
      const double next = std::sqrt(std::max(0.0, stiffness / (steel + fluid_terms(omega).mass)));
      const bool done = std::abs(next - omega) <= 1e-12 * omega;
      omega = next;
      if (done) break;
    }
    mode.eigenvalue = omega * omega;
    mode.frequency_hz = omega / (2.0 * kPi);
  }
  const model::NodeFluidTerms terms = fluid_terms(omega);
  // Plus the structural damping ratio ζ_s as a loss factor 2ζ_s on K (vibration_analysis.hpp).
  const double structural = model.bodies().empty() ? 0.0 : model.bodies().front().reduced->structural_damping;
  if (omega > 0.0) {
    mode.damping_ratio =
        structural + (structural_damping + terms.damping) / (2.0 * omega * (steel + terms.mass));
  }
}

// The rigid motions of the whole string at q as columns (t_x, t_y, t_z, θ_x, θ_y, θ_z): translation t
// and rotation θ about the centroid c, ṙ_b = t + θ × (r_b − c), ω_b = A_bᵀ θ, η̇ = 0.
MatX RigidFields(const model::SystemModel& model, const VecX& q) {
  const auto poses = model.Poses(q);
  Vec3 centroid = Vec3::Zero();
  for (const model::BodyPose& pose : poses) centroid += pose.r;
  if (!poses.empty()) centroid /= static_cast<double>(poses.size());
  MatX fields = MatX::Zero(model.num_velocities(), 6);
  for (Index b = 0; b < std::ssize(poses); ++b) {
    const Index offset = model.bodies()[b].v_offset;
    for (Index axis = 0; axis < 3; ++axis) {
      const Vec3 unit = Vec3::Unit(axis);
      fields.block<3, 1>(offset, axis) = unit;
      fields.block<3, 1>(offset, 3 + axis) = unit.cross(poses[b].r - centroid);
      fields.block<3, 1>(offset + 3, 3 + axis) = poses[b].A.transpose() * unit;
    }
  }
  return fields;
}

// Of the computed modes, the (at most `rigid`) ones that are rigid motions: at least 90 % of the
// mode's M-norm in the span of the rigid fields F, φᵀMF (FᵀMF)⁻¹ FᵀMφ ≥ 0.9 (φ M-normalised). Not
// simply the `rigid` lowest |ω²|: when the free rigid motion is not among the modes computed, that
// flagged an elastic mode (the bundled example's 1.86 Hz mode was reported as a 0 Hz rigid one).
std::vector<bool> RigidFlags(const solvers::ModalResult& modal, const MatX& fields, const SparseMat& mass,
                             Index rigid) {
  std::vector<bool> flags(modal.eigenvalues.size(), false);
  if (rigid == 0) return flags;
  const MatX mass_fields = mass * fields;
  const Eigen::LDLT<MatX> field_mass(fields.transpose() * mass_fields);
  std::vector<std::pair<double, Eigen::Index>> fractions;
  for (Eigen::Index j = 0; j < modal.eigenvalues.size(); ++j) {
    const VecX overlap = mass_fields.transpose() * modal.vectors.col(j);
    const double fraction = overlap.dot(field_mass.solve(overlap));
    if (fraction >= 0.9) fractions.emplace_back(fraction, j);
  }
  std::sort(fractions.rbegin(), fractions.rend());
  for (Index i = 0; i < std::ssize(fractions) && i < rigid; ++i) {
    flags[fractions[i].second] = true;
  }
  return flags;
}

// The `count` lowest modes (kind All) or the lowest of one family, solving more modes progressively
// (from solve_count, doubling, at most bound) until enough of the family are found.
ModesResult SearchModes(const model::SystemModel& model, const VecX& q, const std::vector<model::BodyPose>& poses,
                        const std::vector<Station>& stations, const LinearizedSystem& solved,
                        const ModesSettings& settings, Index solve_count, Index bound) {
  const bool all = settings.kind == ModeKind::All;
  const Index n = model.num_velocities();
  ModesResult result;
  const Index rigid = CountRigidBodyModes(model, q, solved);
  if (all) solve_count = std::min<Index>(n, settings.count + rigid);
  while (true) {
    const solvers::ModalResult modal = LowestModes(solved, solve_count);
    const std::vector<bool> rigid_flags = RigidFlags(modal, RigidFields(model, q), solved.mass, rigid);
    result.modes.clear();
    result.rigid_body_modes = 0;
    for (Eigen::Index j = 0; j < modal.eigenvalues.size(); ++j) {
      ModeResult mode = DescribeMode(model, poses, stations, modal.eigenvalues[j], modal.vectors.col(j));
      mode.rigid_body = rigid_flags[j];
      if (mode.rigid_body) mode.frequency_hz = 0.0;
      if (!all && (mode.rigid_body || mode.kind != settings.kind)) continue;
      if (mode.rigid_body) ++result.rigid_body_modes;
      result.modes.push_back(std::move(mode));
      if (std::ssize(result.modes) == settings.count) break;
    }
    if (std::ssize(result.modes) >= settings.count || solve_count >= bound) break;
    solve_count = std::min(bound, 2 * solve_count);
  }
  return result;
}

// Axial or torsional modes of a string held laterally: stiff springs (the largest diagonal stiffness)
// on every node's lateral translation push the bending modes far up, so the lowest modes of the held
// system are the axial and torsional ones. Exact where the families are uncoupled (a straight string:
// those modes move no node laterally); accepted only if each mode also satisfies the free system,
// ‖Kφ − λMφ‖ ≤ 1e-6 ‖Kφ‖ with λ its Rayleigh quotient. None (the caller searches the full spectrum)
// when the families couple (a curved hole, a loaded contact) or too few are found.
std::optional<ModesResult> FamilyModesWithLateralHeld(const model::SystemModel& model, const VecX& q,
                                                      const std::vector<model::BodyPose>& poses,
                                                      const std::vector<Station>& stations,
                                                      const LinearizedSystem& solved, const ModesSettings& settings,
                                                      Index bound) {
  double hold = 0.0;
  for (Eigen::Index i = 0; i < solved.stiffness.rows(); ++i) hold = std::max(hold, std::abs(solved.stiffness.coeff(i, i)));
  std::vector<Eigen::Triplet<double>> triplets;
  for (Index b = 0; b < std::ssize(model.bodies()); ++b) {
    const model::Body& body = model.bodies()[b];
    for (Index k = 0; k < body.node_count(); ++k) {
      model::LateralFluidNode node;
      node.body = b;
      node.node = k;
      const MatX jacobian = model::LateralNodeJacobian(model, poses, node);
      const MatX product = hold * (jacobian.transpose() * jacobian);
      for (Eigen::Index r = 0; r < product.rows(); ++r) {
        for (Eigen::Index c = 0; c < product.cols(); ++c) {
          if (product(r, c) != 0.0) triplets.emplace_back(body.v_offset + r, body.v_offset + c, product(r, c));
        }
      }
    }
  }
  SparseMat springs(solved.stiffness.rows(), solved.stiffness.cols());
  springs.setFromTriplets(triplets.begin(), triplets.end());
  LinearizedSystem held = solved;
  held.stiffness += springs;
  const Index start = std::min<Index>(bound, std::max(2 * settings.count, 6));
  ModesResult result = SearchModes(model, q, poses, stations, held, settings, start, std::min(bound, 4 * start));
  if (std::ssize(result.modes) < settings.count) return std::nullopt;
  for (ModeResult& mode : result.modes) {
    const VecX& phi = mode.vector;
    const VecX k_phi = solved.stiffness * phi, m_phi = solved.mass * phi;
    const double eigenvalue = phi.dot(k_phi) / phi.dot(m_phi);
    if ((k_phi - eigenvalue * m_phi).norm() > 1e-6 * k_phi.norm()) return std::nullopt;
    mode.eigenvalue = eigenvalue;
    mode.frequency_hz = eigenvalue > 0.0 ? std::sqrt(eigenvalue) / (2.0 * kPi) : 0.0;
  }
  return result;
}

}  // namespace

Index CountRigidBodyModes(const model::SystemModel& model, const VecX& q, const LinearizedSystem& system) {
  const MatX fields = RigidFields(model, q);
  const MatX stiffness = fields.transpose() * (system.stiffness * fields);
  const MatX mass = fields.transpose() * (system.mass * fields);
  const DenseEigenpairs solver = GeneralizedSymmetricEigen(0.5 * (stiffness + stiffness.transpose()),
                                                           0.5 * (mass + mass.transpose()), false);
  double scale = 0.0;
  for (Eigen::Index i = 0; i < system.stiffness.rows(); ++i) {
    const double m = system.mass.coeff(i, i);
    if (m > 0.0) scale = std::max(scale, std::abs(system.stiffness.coeff(i, i)) / m);
  }
  Index rigid = 0;
  for (Eigen::Index i = 0; i < solver.values.size(); ++i) {
    if (std::abs(solver.values[i]) < 1e-9 * scale) ++rigid;
  }
  return rigid;
}

solvers::ModalResult LowestModes(const LinearizedSystem& system, int count) {
  return solvers::SolveModes(system.stiffness, system.mass, count);
}

const char* ModeKindName(ModeKind kind) {
  switch (kind) {
    case ModeKind::All: return "all";
    case ModeKind::Lateral: return "lateral";
    case ModeKind::Axial: return "axial";
    case ModeKind::Torsional: return "torsional";
  }
  return "unknown";
}

const char* WhirlName(Whirl whirl) {
  switch (whirl) {
    case Whirl::None: return "none";
    case Whirl::Forward: return "forward";
    case Whirl::Backward: return "backward";
    case Whirl::Planar: return "planar";
  }
  return "unknown";
}

ModesResult ComputeModes(const model::SystemModel& model, const VecX& q, const ModesSettings& settings,
                         double load_factor, const model::LateralFluid* fluid) {
  if (settings.count < 1) throw LogicError("ComputeModes: count must be at least 1");
  const LinearizedSystem system = Linearize(model, q, load_factor);
  // The eigenproblem's mass: the steel and the fluid at its inviscid (or given) added mass.
  LinearizedSystem solved = system;
  if (fluid && !fluid->empty()) solved.mass += model::ComputeLateralFluidMatrices(model, *fluid, q, 0.0).mass;
  const Index n = model.num_velocities();
  const auto poses = model.Poses(q);
  const std::vector<Station> stations = StringStations(model);
  const bool all = settings.kind == ModeKind::All;
  const Index bound = std::min(n, std::max<Index>(kMaxModesSearched, settings.count));
  Index solve_count =
      all ? std::min<Index>(n, settings.count) : std::min<Index>(bound, std::max(3 * settings.count, 12));
  ModesResult result;
  for (const Station& station : stations) result.s.push_back(station.s);
  if (settings.kind == ModeKind::Axial || settings.kind == ModeKind::Torsional) {
    if (auto held = FamilyModesWithLateralHeld(model, q, poses, stations, solved, settings, bound)) {
      result.modes = std::move(held->modes);
    }
  }
  if (result.modes.empty()) {
    const ModesResult found = SearchModes(model, q, poses, stations, solved, settings, solve_count, bound);
    result.modes = found.modes;
    result.rigid_body_modes = found.rigid_body_modes;
  }
  for (ModeResult& mode : result.modes) SetFrequencyAndDamping(model, q, system, fluid, mode);
  std::stable_sort(result.modes.begin(), result.modes.end(),
                   [](const ModeResult& a, const ModeResult& b) { return a.eigenvalue < b.eigenvalue; });
  result.near_zero_modes = result.negative_stiffness_modes = 0;
  for (ModeResult& mode : result.modes) {
    mode.negative_stiffness = !mode.rigid_body && mode.eigenvalue < 0.0;
    mode.near_zero = mode.rigid_body || (!mode.negative_stiffness && mode.frequency_hz < kNearZeroFrequencyHz);
    if (mode.near_zero) ++result.near_zero_modes;
    if (mode.negative_stiffness) ++result.negative_stiffness_modes;
  }
  return result;
}

const ModeResult* FirstLateralMode(const ModesResult& result) {
  for (const ModeResult& mode : result.modes) {
    if (!mode.near_zero && !mode.negative_stiffness && mode.kind == ModeKind::Lateral) return &mode;
  }
  return nullptr;
}

ModesResult RunModes(const model::BuiltModel& built, const VecX& q, const ModesSettings& settings,
                     const model::LateralFluid* fluid) {
  return ComputeModes(built.system, q, settings, 1.0, fluid);
}

}  // namespace drillflex::analyses
