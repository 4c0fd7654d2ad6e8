#include "model/body_dynamics.hpp"

#include <array>

#include "core/so3.hpp"
#include "model/body_inertia_jacobian.hpp"

namespace drillflex::model {

using so3::Skew;

MatX BodyMassMatrix(const Body& body, const BodyPose& pose) {
  const cms::ReducedBody& reduced = *body.reduced;
  const Index nf = body.flexible_count;
  const Index nodes = reduced.node_count();
  // In the body-frame velocities w = (Aᵀṙ, ω, η̇) the node sum Σ L_kᵀ diag(M_k, J_k) L_k, with
  // L_k = [I, −ũ_k, Φ_k] for translation and [0, I, Ψ_k] for rotation, depends on η only through
  // the offsets u_k = ρ_k + d_k, d_k = Φ_k η, in the ω rows and columns. So M_w = M_w(0) + ΔM with
  // M_w(0) the exact reference mass (node sum at η = 0 plus mass_correction) and
  //   ΔM_tω = −Σ M_k d̃_k,  ΔM_ωω = Σ (ũ_kᵀ M_k ũ_k − ρ̃_kᵀ M_k ρ̃_k),  ΔM_ωη = −Σ d̃_kᵀ M_k Φ_k,
  // the last one product of a 3 × 6N row block with the mode shapes U (6 rows a node).
  MatX mass = body.reference_mass;
  if (nf > 0 && !pose.eta.isZero(0.0)) {
    thread_local VecX displacement;
    thread_local Eigen::Matrix<double, 3, Eigen::Dynamic> weighted;  // −d̃_kᵀ M_k per node, 0 for rotations
    displacement.noalias() = reduced.mode_shapes * pose.eta;
    weighted.setZero(3, 6 * nodes);
    Mat3 translation_rotation = Mat3::Zero(), rotation_rotation = Mat3::Zero();
    for (Index k = 0; k < nodes; ++k) {
      const Mat3 node_mass = reduced.NodeTranslationalMass(k);
      const Mat3 reference_skew = Skew(reduced.node_positions[k]);
      const Mat3 displacement_skew = Skew(displacement.segment<3>(6 * k));
      const Mat3 weighted_displacement = displacement_skew.transpose() * node_mass;  // d̃ᵀ M
      translation_rotation.noalias() -= node_mass * displacement_skew;
      // (ρ̃ + d̃)ᵀ M (ρ̃ + d̃) − ρ̃ᵀ M ρ̃ = ρ̃ᵀ M d̃ + d̃ᵀ M ρ̃ + d̃ᵀ M d̃.
      const Mat3 cross = reference_skew.transpose() * node_mass * displacement_skew;
      rotation_rotation.noalias() += cross + cross.transpose() + weighted_displacement * displacement_skew;
      weighted.middleCols<3>(6 * k) = -weighted_displacement;
    }
    mass.block<3, 3>(0, 3) += translation_rotation;
    mass.block<3, 3>(3, 0) += translation_rotation.transpose();
    mass.block<3, 3>(3, 3) += rotation_rotation;
    Eigen::Matrix<double, 3, Eigen::Dynamic> rotation_modal(3, nf);
    rotation_modal.noalias() = weighted.lazyProduct(reduced.mode_shapes);
    mass.block(3, 6, 3, nf) += rotation_modal;
    mass.block(6, 3, nf, 3) += rotation_modal.transpose();
  }
  // ṙ = A (Aᵀṙ): M_v = Wᵀ M_w W with W = diag(Aᵀ, I, I).
  mass.topRows<3>() = pose.A * mass.topRows<3>();
  mass.leftCols<3>() = mass.leftCols<3>() * pose.A.transpose();
  return mass;
}

VecX BodyVelocityForces(const Body& body, const BodyPose& pose, const VecX& velocity) {
  const cms::ReducedBody& reduced = *body.reduced;
  const Index nf = body.flexible_count;
  VecX forces = VecX::Zero(6 + nf);
  const Vec3 omega = velocity.segment<3>(3);
  const VecX eta_rate = velocity.tail(nf);
  Vec3 translational_sum = Vec3::Zero();  // Σ M_k c_k in the body frame
  for (Index k = 0; k < reduced.node_count(); ++k) {
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

// The body's two membrane strains, each the linear end-node part plus a quadratic part of the
// bending (method.md §3; fe/beam_element.hpp):
//   axial:   ε L = Δu + ½ ηᵀ K_G,ff η      (the foreshortening, ½ ∫ (v′² + w′²)),   force N = (EA/L) ε L;
//   torsion: φ   = Δθx + ½ ηᵀ K_T,ff η     (the twist of bending, −½ ∫ (v′w″ − w′v″)), torque T = (GJ/L) φ.
// Each stores energy (k/2) s², s = rowᵀη/k + ½ ηᵀGη, of which the K_ff part holds (k/2)(rowᵀη/k)²:
//   V_c = ½ (rowᵀη) ηᵀGη + (k/8) (ηᵀGη)²,   ∂V_c/∂η = F G η + ½ (ηᵀGη) row,  F = rowᵀη + (k/2) ηᵀGη,
//   ∂²V_c/∂η² = F G + Gη rowᵀ + row (Gη)ᵀ + k Gη (Gη)ᵀ.
struct MembraneStrain {
  const VecX& row;   // rowᵀη: the linear force (N) or torque (N·m)
  const MatX& geometric;  // G per unit force or torque
  double stiffness;  // k = EA/L (N) or GJ/L (N·m)
  bool present() const { return row.size() > 0 && geometric.size() > 0; }  // a body built without it: none
};

std::array<MembraneStrain, 2> MembraneStrains(const Body& body) {
  return {MembraneStrain{body.axial_force_row, body.reduced->modal_geometric_stiffness,
                         body.axial_rigidity / body.length()},
          MembraneStrain{body.torque_row, body.reduced->modal_torque_geometric_stiffness,
                         body.torsional_rigidity / body.length()}};
}

// One strain at η: Gη, ηᵀGη and the force F = rowᵀη + (k/2) ηᵀGη.
struct MembraneState {
  VecX geometric;      // G η
  double bending = 0;  // ηᵀ G η
  double force = 0;    // F
};
MembraneState EvaluateMembrane(const MembraneStrain& strain, const VecX& eta) {
  MembraneState state;
  state.geometric = strain.geometric * eta;
  state.bending = eta.dot(state.geometric);
  state.force = strain.row.dot(eta) + 0.5 * strain.stiffness * state.bending;
  return state;
}

}  // namespace

double BodyAxialForce(const Body& body, const BodyPose& pose) {
  // N = EA ε with the mean axial strain including the foreshortening of the bending:
  // ε L = Δu + ½ ∫(v′² + w′²) = Δu + ½ ηᵀ K_G,ff η (K_G per unit axial force).
  const MembraneStrain axial = MembraneStrains(body)[0];
  return axial.present() ? EvaluateMembrane(axial, pose.eta).force : 0.0;
}

double BodyTorque(const Body& body, const BodyPose& pose) {
  const MembraneStrain torsion = MembraneStrains(body)[1];
  return torsion.present() ? EvaluateMembrane(torsion, pose.eta).force : 0.0;
}

void AddElasticForces(const Body& body, const BodyPose& pose, const VecX& velocity, VecX& residual) {
  const cms::ReducedBody& reduced = *body.reduced;
  const Index nf = body.flexible_count;
  const VecX& eta = pose.eta;
  auto modal = residual.tail(nf);
  modal.noalias() += reduced.modal_stiffness * eta + reduced.modal_damping * velocity.tail(nf);
  for (const MembraneStrain& strain : MembraneStrains(body)) {
    if (!strain.present()) continue;
    const MembraneState state = EvaluateMembrane(strain, eta);
    modal.noalias() += state.force * state.geometric + 0.5 * state.bending * strain.row;
  }
}

void AddElasticMatrices(const Body& body, const BodyPose& pose, double cK, double cD, MatX& matrix) {
  const cms::ReducedBody& reduced = *body.reduced;
  const Index nf = body.flexible_count;
  auto block = matrix.bottomRightCorner(nf, nf);
  if (cK != 0.0) {
    block.noalias() += cK * reduced.modal_stiffness;
    for (const MembraneStrain& strain : MembraneStrains(body)) {
      if (!strain.present()) continue;
      const MembraneState state = EvaluateMembrane(strain, pose.eta);
      const VecX& g = state.geometric;
      block.noalias() += cK * (state.force * strain.geometric + g * strain.row.transpose() +
                               strain.row * g.transpose() + strain.stiffness * g * g.transpose());
    }
  }
  if (cD != 0.0) block.noalias() += cD * reduced.modal_damping;
}

double BodyElasticEnergy(const Body& body, const BodyPose& pose) {
  const cms::ReducedBody& reduced = *body.reduced;
  const VecX& eta = pose.eta;
  double energy = 0.5 * eta.dot(reduced.modal_stiffness * eta);
  for (const MembraneStrain& strain : MembraneStrains(body)) {
    if (!strain.present()) continue;
    const double bending = EvaluateMembrane(strain, eta).bending;
    energy += 0.5 * strain.row.dot(eta) * bending + strain.stiffness * bending * bending / 8.0;
  }
  return energy;
}

double BodyKineticEnergy(const Body& body, const BodyPose& pose, const VecX& velocity) {
  // ½ vᵀ M v with M v from the node sum (BodyInertialForces at zero velocity and acceleration v).
  return 0.5 * velocity.dot(BodyInertialForces(body, pose, VecX::Zero(velocity.size()), velocity));
}

}  // namespace drillflex::model
