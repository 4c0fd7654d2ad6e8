#include "model/fluid_inertia.hpp"

#include "core/so3.hpp"
#include "model/node_kinematics.hpp"

namespace drillflex::model {
namespace {

using so3::Skew;
using Rows3 = Eigen::Matrix<double, 3, Eigen::Dynamic>;

// Π v: the part of a body-frame vector across the body's x axis.
Vec3 Lateral(const Vec3& v) { return Vec3(0.0, v.y(), v.z()); }

// F_k = m (Π ṫ + ω × Π t) + c Π t, body frame.
Vec3 NodeForce(double mass, double damping, const Vec3& omega, const BodyFrameNodeMotion& node) {
  const Vec3 lateral = Lateral(node.velocity);
  return mass * (Lateral(node.rate) + omega.cross(lateral)) + damping * lateral;
}

}  // namespace

VecX BodyFluidForces(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& acceleration) {
  const Index nf = body.flexible_count;
  VecX forces = VecX::Zero(body.velocity_count());
  const FrameMotion frame = ComputeFrameMotion(pose, velocity, acceleration);
  Vec3 translational_sum = Vec3::Zero();
  for (Index k = 0; k < body.node_count(); ++k) {
    const double mass = body.fluid_lateral_mass[k], damping = body.fluid_lateral_damping[k];
    if (mass == 0.0 && damping == 0.0) continue;
    const BodyFrameNodeMotion node = ComputeBodyFrameNodeMotion(body, pose, frame, velocity, acceleration, k);
    const Vec3 force = NodeForce(mass, damping, frame.omega, node);
    // J_kᵀ F = [A F; u × F; Φᵀ F], plus the moment m t × Π t of the turning lateral plane.
    translational_sum += force;
    forces.segment<3>(3) += node.offset.cross(force) + mass * node.velocity.cross(Lateral(node.velocity));
    forces.tail(nf).noalias() += body.reduced->node_translation_modes[k].transpose() * force;
  }
  forces.head<3>() = pose.A * translational_sum;
  return forces;
}

// Derivation (per node; p = Aᵀṙ, α_r = Aᵀr̈, w = Φ η̇, s = Π t; columns (δr, δθ, δη) and (ṙ, ω, η̇)):
//   ∂t/∂v = J,                          ∂t/∂q = [0, p̃, ω̃Φ]            (δAᵀ ṙ = −δθ̃ p = p̃ δθ; δu = Φ δη)
//   ∂ṫ/∂v = [−ω̃Aᵀ, p̃ − w̃, ω̃Φ],        ∂ṫ/∂q = [0, α̃_r − ω̃p̃, (ω̇)~Φ],   ∂ṫ/∂a = J
//   ∂F/∂• = m (Π ∂ṫ/∂• + ω̃ Π ∂t/∂•) + c Π ∂t/∂•, and ∂F/∂ω gains −m s̃ (from ω × s)
//   ∂(t × s)/∂• = t̃ Π ∂t/∂• − s̃ ∂t/∂•
// and the pull-back Jᵀ F itself depends on q: δ(A F) ∋ −A F̃ δθ, δ(u × F) ∋ −F̃ Φ δη.
void AddFluidMatrices(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& acceleration,
                      double cK, double cD, double cM, MatX& matrix) {
  const Index nf = body.flexible_count;
  const FrameMotion frame = ComputeFrameMotion(pose, velocity, acceleration);
  const Mat3 projection = Vec3(0.0, 1.0, 1.0).asDiagonal();
  const Mat3 omega_skew = Skew(frame.omega);
  const Mat3 velocity_skew = Skew(frame.velocity);
  thread_local Rows3 jacobian, velocity_part, rate_part, force_part, moment_part, lateral_velocity_part;
  for (Index k = 0; k < body.node_count(); ++k) {
    const double mass = body.fluid_lateral_mass[k], damping = body.fluid_lateral_damping[k];
    if (mass == 0.0 && damping == 0.0) continue;
    const auto& phi = body.reduced->node_translation_modes[k];
    const BodyFrameNodeMotion node = ComputeBodyFrameNodeMotion(body, pose, frame, velocity, acceleration, k);
    const Vec3 lateral = Lateral(node.velocity);
    NodeVelocityJacobian(body, pose, k, node.offset, jacobian);
    // cK ∂t/∂q + cD ∂t/∂v and cK ∂ṫ/∂q + cD ∂ṫ/∂v + cM ∂ṫ/∂a.
    velocity_part.noalias() = cD * jacobian;
    rate_part.noalias() = cM * jacobian;
    if (cD != 0.0) {
      rate_part.leftCols<3>().noalias() -= cD * omega_skew * pose.A.transpose();
      rate_part.middleCols<3>(3) += cD * (velocity_skew - Skew(node.modal_velocity));
      rate_part.rightCols(nf).noalias() += cD * omega_skew * phi;
    }
    if (cK != 0.0) {
      velocity_part.middleCols<3>(3) += cK * velocity_skew;
      velocity_part.rightCols(nf).noalias() += cK * omega_skew * phi;
      rate_part.middleCols<3>(3) += cK * (Skew(frame.acceleration) - omega_skew * velocity_skew);
      rate_part.rightCols(nf).noalias() += cK * Skew(frame.omega_rate) * phi;
    }
    lateral_velocity_part = velocity_part;  // Π (∂t): the row across x zeroed
    lateral_velocity_part.row(0).setZero();
    force_part.noalias() = mass * (projection * rate_part + omega_skew * lateral_velocity_part);
    force_part.noalias() += damping * lateral_velocity_part;
    if (cD != 0.0) force_part.middleCols<3>(3) -= (cD * mass) * Skew(lateral);
    moment_part.noalias() = mass * (Skew(node.velocity) * lateral_velocity_part - Skew(lateral) * velocity_part);
    matrix.noalias() += jacobian.transpose().lazyProduct(force_part);
    matrix.middleRows<3>(3) += moment_part;
    if (cK != 0.0) {
      const Vec3 force = NodeForce(mass, damping, frame.omega, node);
      const Mat3 force_skew = Skew(force);
      matrix.block<3, 3>(0, 3).noalias() -= cK * pose.A * force_skew;
      matrix.block(3, 6, 3, nf).noalias() -= cK * force_skew * phi;
    }
  }
}

MatX BodyFluidMassMatrix(const Body& body, const BodyPose& pose) {
  const Index n = body.velocity_count();
  MatX mass = MatX::Zero(n, n);
  Rows3 jacobian;
  for (Index k = 0; k < body.node_count(); ++k) {
    if (body.fluid_lateral_mass[k] == 0.0) continue;
    NodeVelocityJacobian(body, pose, k, pose.NodeOffset(body, k), jacobian);
    mass.noalias() += body.fluid_lateral_mass[k] * jacobian.bottomRows<2>().transpose() * jacobian.bottomRows<2>();
  }
  return mass;
}

namespace {
// Σ weight_k |Π t_k|² over the nodes.
double SumOfLateralSquares(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& weights) {
  double sum = 0.0;
  for (Index k = 0; k < body.node_count(); ++k) {
    if (weights[k] == 0.0) continue;
    const Vec3 t = ComputeBodyFrameNodeRates(body, pose, k, velocity).translation;
    sum += weights[k] * Lateral(t).squaredNorm();
  }
  return sum;
}
}  // namespace

double BodyFluidKineticEnergy(const Body& body, const BodyPose& pose, const VecX& velocity) {
  return 0.5 * SumOfLateralSquares(body, pose, velocity, body.fluid_lateral_mass);
}

double BodyFluidDampingPower(const Body& body, const BodyPose& pose, const VecX& velocity) {
  return SumOfLateralSquares(body, pose, velocity, body.fluid_lateral_damping);
}

}  // namespace drillflex::model
