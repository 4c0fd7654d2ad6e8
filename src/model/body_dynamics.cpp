#include "model/body_dynamics.hpp"

#include "core/so3.hpp"
#include "model/body_inertia_jacobian.hpp"

namespace drillflex::model {

using so3::Skew;

MatX BodyMassMatrix(const Body& body, const BodyPose& pose) {
  const cms::ReducedBody& reduced = *body.reduced;
  const int nf = body.flexible_count;
  const int n = 6 + nf;
  // Accumulate in the body-frame velocities w = (Aᵀṙ, ω, η̇), then rotate the translational rows.
  MatX mass = MatX::Zero(n, n);
  Eigen::Matrix<double, 3, Eigen::Dynamic> rows(3, n), weighted(3, n), rotation_rows(3, nf);
  for (int k = 0; k < reduced.node_count(); ++k) {
    const Mat3 node_mass = reduced.NodeTranslationalMass(k);
    const Mat3 offset_skew = Skew(pose.NodeOffset(body, k));
    const auto& phi = reduced.node_translation_modes[k];
    const auto& psi = reduced.node_rotation_modes[k];
    const Mat3& inertia = reduced.node_rotary_inertia[k];
    // Translation: L = [I, −ũ, Φ] in w; Lᵀ m L. The 3-row products are written as lazy
    // (coefficient-wise) products: as general matrix products they went through Eigen's blocked
    // GEMM and its temporaries, a third of the bundled example's iteration-matrix assembly.
    rows.leftCols<3>().setIdentity();
    rows.middleCols<3>(3) = -offset_skew;
    rows.rightCols(nf) = phi;
    weighted.noalias() = node_mass.lazyProduct(rows);
    mass.noalias() += rows.transpose().lazyProduct(weighted);
    // Rotation: [0, I, Ψ].
    rotation_rows.noalias() = inertia.lazyProduct(psi);
    mass.block<3, 3>(3, 3) += inertia;
    mass.block(3, 6, 3, nf) += rotation_rows;
    mass.block(6, 3, nf, 3) += rotation_rows.transpose();
    mass.block(6, 6, nf, nf).noalias() += psi.transpose().lazyProduct(rotation_rows);
  }
  mass += body.mass_correction;
  // ṙ = A (Aᵀṙ): M_v = Wᵀ M_w W with W = diag(Aᵀ, I, I).
  mass.topRows<3>() = pose.A * mass.topRows<3>();
  mass.leftCols<3>() = mass.leftCols<3>() * pose.A.transpose();
  return mass;
}

VecX BodyVelocityForces(const Body& body, const BodyPose& pose, const VecX& velocity) {
  const cms::ReducedBody& reduced = *body.reduced;
  const int nf = body.flexible_count;
  VecX forces = VecX::Zero(6 + nf);
  const Vec3 omega = velocity.segment<3>(3);
  const VecX eta_rate = velocity.tail(nf);
  Vec3 translational_sum = Vec3::Zero();  // Σ M_k c_k in the body frame
  for (int k = 0; k < reduced.node_count(); ++k) {
    const Vec3 offset = pose.NodeOffset(body, k);
    const auto& phi = reduced.node_translation_modes[k];
    const auto& psi = reduced.node_rotation_modes[k];
    // Body-frame node acceleration terms quadratic in velocity: ω×(ω×u) + 2 ω×(Φ η̇).
    const Vec3 quadratic = omega.cross(omega.cross(offset)) + 2.0 * omega.cross(phi * eta_rate);
    const Vec3 force = reduced.NodeTranslationalMass(k) * quadratic;
    translational_sum += force;
    forces.segment<3>(3) += offset.cross(force);
    forces.tail(nf).noalias() += phi.transpose() * force;
    // Gyroscopic moment of the node's rotary inertia, ω_k × J_k ω_k.
    const Vec3 node_omega = omega + psi * eta_rate;
    const Vec3 moment = node_omega.cross(reduced.node_rotary_inertia[k] * node_omega);
    forces.segment<3>(3) += moment;
    forces.tail(nf).noalias() += psi.transpose() * moment;
  }
  forces.head<3>() = pose.A * translational_sum;
  return forces;
}

namespace {
// EA/L of a body, N/m.
double AxialStiffness(const Body& body) { return body.axial_rigidity / body.length(); }
}  // namespace

double BodyAxialForce(const Body& body, const BodyPose& pose) {
  // N = EA ε with the mean axial strain including the foreshortening of the bending:
  // ε L = Δu + ½ ∫(v′² + w′²) dx = Δu + ½ ηᵀ K_G,ff η (K_G per unit axial force).
  const VecX& eta = pose.eta;
  return body.axial_force_row.dot(eta) +
         0.5 * AxialStiffness(body) * eta.dot(body.reduced->modal_geometric_stiffness * eta);
}

void AddElasticForces(const Body& body, const BodyPose& pose, const VecX& velocity, VecX& residual) {
  const cms::ReducedBody& reduced = *body.reduced;
  const int nf = body.flexible_count;
  const VecX& eta = pose.eta;
  const double axial_force = BodyAxialForce(body, pose);
  const VecX geometric = reduced.modal_geometric_stiffness * eta;
  // V = ½ηᵀK_ffη + ½(EA/L)[(Δu + ½ηᵀGη)² − Δu²] (the axial part of K_ff is ½(EA/L)Δu²), so
  // ∂V/∂η = K_ff η + N G η + ½ (ηᵀ G η) ∂Δu-row, with N the corrected axial force above.
  residual.tail(nf).noalias() += reduced.modal_stiffness * eta + axial_force * geometric +
                                 0.5 * eta.dot(geometric) * body.axial_force_row +
                                 reduced.modal_damping * velocity.tail(nf);
}

void AddElasticMatrices(const Body& body, const BodyPose& pose, double cK, double cD, MatX& matrix) {
  const cms::ReducedBody& reduced = *body.reduced;
  const int nf = body.flexible_count;
  auto block = matrix.bottomRightCorner(nf, nf);
  if (cK != 0.0) {
    const double axial_force = BodyAxialForce(body, pose);
    const VecX geometric = reduced.modal_geometric_stiffness * pose.eta;
    // ∂/∂η of the force above, with ∂N/∂η = row + (EA/L) G η.
    block.noalias() += cK * (reduced.modal_stiffness + axial_force * reduced.modal_geometric_stiffness +
                             geometric * body.axial_force_row.transpose() +
                             AxialStiffness(body) * geometric * geometric.transpose() +
                             body.axial_force_row * geometric.transpose());
  }
  if (cD != 0.0) block.noalias() += cD * reduced.modal_damping;
}

double BodyElasticEnergy(const Body& body, const BodyPose& pose) {
  const cms::ReducedBody& reduced = *body.reduced;
  const VecX& eta = pose.eta;
  const double bending = eta.dot(reduced.modal_geometric_stiffness * eta);  // ηᵀGη = ∫(v′² + w′²)
  return 0.5 * eta.dot(reduced.modal_stiffness * eta) + 0.5 * body.axial_force_row.dot(eta) * bending +
         AxialStiffness(body) * bending * bending / 8.0;
}

double BodyKineticEnergy(const Body& body, const BodyPose& pose, const VecX& velocity) {
  // ½ vᵀ M v with M v from the node sum (BodyInertialForces at zero velocity and acceleration v).
  return 0.5 * velocity.dot(BodyInertialForces(body, pose, VecX::Zero(velocity.size()), velocity));
}

}  // namespace drillflex::model
