#include "model/body_inertia_jacobian.hpp"

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/body_dynamics.hpp"

namespace drillflex::model {

using so3::Skew;

namespace {

using Matrix3X = Eigen::Matrix<double, 3, Eigen::Dynamic>;

// The body-frame pieces of the derivatives of G = (M̂ + C) α + Q̂ (header), before the rotation Wᵀ.
struct BodyFrameDerivatives {
  Vec3 translational_residual = Vec3::Zero();  // G_t
  MatX translation_columns;  // (M̂ + C)[:, t], n × 3 (stiffness only)
  MatX modal_stiffness;      // ∂G/∂η, n × n_f (stiffness only)
  MatX velocity_damping;     // ∂G/∂(ω, η̇), n × (3 + n_f) (damping only)
};

// Adds L̂_kᵀ x = [x; ũ_k x; Φ_kᵀ x] of a body-frame nodal force (rows) into `target` (n rows).
// Lazy (coefficient-wise) products: as general products the n_f × 3 by 3 × n_f ones went through
// Eigen's blocked GEMM, its packing and temporaries (a tenth of the bundled example's transient).
template <typename Rows>
void AddTranslationalMap(const Mat3& skew_offset, const Matrix3X& phi, const Rows& rows, MatX& target) {
  target.topRows<3>() += rows;
  target.middleRows<3>(3).noalias() += skew_offset.lazyProduct(rows);
  target.bottomRows(phi.cols()).noalias() += phi.transpose().lazyProduct(rows);
}

BodyFrameDerivatives ComputeBodyFrameDerivatives(const Body& body, const BodyPose& pose, const VecX& velocity,
                                                 const VecX& acceleration, bool stiffness, bool damping) {
  const cms::ReducedBody& reduced = *body.reduced;
  const Index nf = body.flexible_count;
  const Index n = 6 + nf;
  const Vec3 omega = velocity.segment<3>(3);
  const auto eta_rate = velocity.tail(nf);
  VecX alpha = acceleration;  // α = W a
  alpha.head<3>() = pose.A.transpose() * acceleration.head<3>();
  const Vec3 alpha_t = alpha.head<3>();
  const Vec3 alpha_omega = alpha.segment<3>(3);
  const auto alpha_eta = alpha.tail(nf);
  const Mat3 skew_omega = Skew(omega);
  // ∂(a_k + c_k)/∂u_k: α_ω × δu + ω × (ω × δu).
  const Mat3 offset_rate = Skew(alpha_omega) + skew_omega * skew_omega;

  BodyFrameDerivatives out;
  if (stiffness) {
    out.translational_residual = body.mass_correction.topRows<3>() * alpha;
    out.translation_columns = body.mass_correction.leftCols<3>();
    out.modal_stiffness = MatX::Zero(n, nf);
  }
  if (damping) out.velocity_damping = MatX::Zero(n, 3 + nf);
  Matrix3X force_rate(3, nf), velocity_rate(3, 3 + nf), gyroscopic_rate(3, 3 + nf);
  for (Index k = 0; k < reduced.node_count(); ++k) {
    const Mat3 mass = reduced.NodeTranslationalMass(k);
    const Matrix3X& phi = reduced.node_translation_modes[k];
    const Matrix3X& psi = reduced.node_rotation_modes[k];
    const Vec3 offset = pose.NodeOffset(body, k);
    const Mat3 skew_offset = Skew(offset);
    const Vec3 modal_velocity = phi * eta_rate;
    if (stiffness) {
      const Vec3 node_acceleration = alpha_t + alpha_omega.cross(offset) + phi * alpha_eta +
                                     omega.cross(omega.cross(offset)) + 2.0 * omega.cross(modal_velocity);
      const Vec3 force = mass * node_acceleration;  // f_k
      out.translational_residual += force;
      AddTranslationalMap(skew_offset, phi, mass, out.translation_columns);
      force_rate.noalias() = (mass * offset_rate).lazyProduct(phi);  // δf_k / δη
      AddTranslationalMap(skew_offset, phi, force_rate, out.modal_stiffness);
      out.modal_stiffness.middleRows<3>(3).noalias() -= Skew(force).lazyProduct(phi);  // δu_k × f_k
    }
    if (damping) {
      // ∂c_k/∂ω and ∂c_k/∂η̇, times M_k.
      velocity_rate.leftCols<3>() =
          mass * (-Skew(omega.cross(offset)) - skew_omega * skew_offset - 2.0 * Skew(modal_velocity));
      velocity_rate.rightCols(nf).noalias() = (2.0 * mass * skew_omega).lazyProduct(phi);
      AddTranslationalMap(skew_offset, phi, velocity_rate, out.velocity_damping);
      // ∂g_k/∂Ω_k [I, Ψ_k], mapped by [0; I; Ψ_kᵀ].
      const Mat3& inertia = reduced.node_rotary_inertia[k];
      const Vec3 node_omega = omega + psi * eta_rate;
      const Mat3 gyroscopic = Skew(node_omega) * inertia - Skew(inertia * node_omega);
      gyroscopic_rate.leftCols<3>() = gyroscopic;
      gyroscopic_rate.rightCols(nf).noalias() = gyroscopic.lazyProduct(psi);
      out.velocity_damping.middleRows<3>(3) += gyroscopic_rate;
      out.velocity_damping.bottomRows(nf).noalias() += psi.transpose().lazyProduct(gyroscopic_rate);
    }
  }
  return out;
}

// Wᵀ X: the translational rows rotate to the global frame.
void RotateTranslationalRows(const Mat3& A, MatX& rows) { rows.topRows<3>() = A * rows.topRows<3>(); }

}  // namespace

VecX BodyInertialForces(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& acceleration) {
  // The node sum of the header without forming M: with the body-frame accelerations
  // α = (Aᵀ r̈, ω̇, η̈), per node f_k = M_k (α_t + α_ω × u_k + Φ_k α_η + c_k) mapped by [I; ũ_k; Φ_kᵀ],
  // and m_k = J_k (α_ω + Ψ_k α_η) + Ω_k × J_k Ω_k mapped by [0; I; Ψ_kᵀ]; then C α and the
  // translational rows rotated by A (R_in = Wᵀ G). The nodes' Φ_k and Ψ_k are the rows of the mode
  // shapes U (6 per node), so the modal parts of all nodes are three products U x and one Uᵀ g:
  // O(nodes · n_f) instead of the O(nodes · n²) of forming M.
  const cms::ReducedBody& reduced = *body.reduced;
  const Index nf = body.flexible_count;
  const Index nodes = reduced.node_count();
  const MatX& shapes = reduced.mode_shapes;
  if (shapes.rows() != 6 * nodes || shapes.cols() != nf) {
    throw LogicError("BodyInertialForces: the mode shapes do not have 6 rows a node and n_f columns");
  }
  const Vec3 alpha_t = pose.A.transpose() * acceleration.head<3>();
  const Vec3 alpha_w = acceleration.segment<3>(3);
  const Vec3 omega = velocity.segment<3>(3);
  // Per-thread work vectors (the residual of a long string calls this for every body and Newton
  // iteration; their allocations were a tenth of the V1 cantilever's transient run).
  thread_local VecX displacement, rate, elastic_acceleration, nodal;
  displacement.noalias() = shapes * pose.eta;
  rate.noalias() = shapes * velocity.tail(nf);
  elastic_acceleration.noalias() = shapes * acceleration.tail(nf);
  nodal.setZero(6 * nodes);  // (f_k, m_k) per node, body frame
  Vec3 translational_sum = Vec3::Zero(), rotational_sum = Vec3::Zero();
  for (Index k = 0; k < nodes; ++k) {
    const Vec3 offset = reduced.node_positions[k] + displacement.segment<3>(6 * k);
    const Vec3 node_acceleration = alpha_t + alpha_w.cross(offset) + elastic_acceleration.segment<3>(6 * k) +
                                   omega.cross(omega.cross(offset)) + 2.0 * omega.cross(rate.segment<3>(6 * k));
    const Vec3 force = reduced.NodeTranslationalMass(k) * node_acceleration;
    const Mat3& inertia = reduced.node_rotary_inertia[k];
    const Vec3 node_omega = omega + rate.segment<3>(6 * k + 3);
    const Vec3 moment =
        inertia * (alpha_w + elastic_acceleration.segment<3>(6 * k + 3)) + node_omega.cross(inertia * node_omega);
    translational_sum += force;
    rotational_sum += offset.cross(force) + moment;
    nodal.segment<3>(6 * k) = force;
    nodal.segment<3>(6 * k + 3) = moment;
  }
  VecX forces(6 + nf);
  forces << translational_sum, rotational_sum, shapes.transpose() * nodal;
  VecX body_frame_acceleration(6 + nf);
  body_frame_acceleration << alpha_t, alpha_w, acceleration.tail(nf);
  forces.noalias() += body.mass_correction * body_frame_acceleration;
  forces.head<3>() = pose.A * Vec3(forces.head<3>());
  return forces;
}

InertiaJacobians BodyInertiaJacobians(const Body& body, const BodyPose& pose, const VecX& velocity,
                                      const VecX& acceleration) {
  const Index n = body.velocity_count();
  InertiaJacobians jacobians{MatX::Zero(n, n), MatX::Zero(n, n)};
  AddInertiaMatrices(body, pose, velocity, acceleration, 1.0, 0.0, 0.0, jacobians.stiffness);
  AddInertiaMatrices(body, pose, velocity, acceleration, 0.0, 1.0, 0.0, jacobians.damping);
  return jacobians;
}

void AddInertiaMatrices(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& acceleration,
                        double cK, double cD, double cM, MatX& matrix) {
  if (cM != 0.0) matrix.noalias() += cM * BodyMassMatrix(body, pose);
  const bool moving = !velocity.isZero(0.0);
  const bool stiffness = cK != 0.0 && (moving || !acceleration.isZero(0.0));
  const bool damping = cD != 0.0 && moving;
  if (!stiffness && !damping) return;
  const Index nf = body.flexible_count;
  BodyFrameDerivatives d = ComputeBodyFrameDerivatives(body, pose, velocity, acceleration, stiffness, damping);
  if (stiffness) {
    // δθ columns: Wᵀ (M̂ + C)[:, t] skew(α_t) − [A skew(G_t); 0; 0].
    const Vec3 alpha_t = pose.A.transpose() * acceleration.head<3>();
    MatX rotation_columns = d.translation_columns * Skew(alpha_t);
    rotation_columns.topRows<3>() -= Skew(d.translational_residual);
    RotateTranslationalRows(pose.A, rotation_columns);
    matrix.middleCols<3>(3) += cK * rotation_columns;
    RotateTranslationalRows(pose.A, d.modal_stiffness);
    matrix.rightCols(nf) += cK * d.modal_stiffness;
  }
  if (damping) {
    RotateTranslationalRows(pose.A, d.velocity_damping);
    matrix.rightCols(3 + nf) += cD * d.velocity_damping;
  }
}

}  // namespace drillflex::model
