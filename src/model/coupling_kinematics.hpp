// Kinematics of a 6-component spring between node a of side 1 and node b of side 2 (method.md §5):
// the strain, its Jacobian and the derivative of the Jacobian, exact, for couplings between bodies
// and for supports (side 1 = the ground).
//
// Strain in side 1's frame A1 (for the ground: a fixed frame):
//   e_t = A1ᵀ (r2 + A2 u_b − r1) − u_a                          (relative translation)
//   e_r = vee(skew(R)) + Ψ_b η2 − Ψ_a η1,  R = R0ᵀ A1ᵀ A2        (relative rotation)
// with u the node offsets ρ + Φη, Ψη the small elastic node rotations, R0 a built-in relative
// rotation (a bent housing; I otherwise). vee(skew(R)) = ½ (R − Rᵀ)^∨ is the rotation vector for
// small relative rotations. Columns of the Jacobian B = ∂e/∂v follow the velocities of side 1
// (ṙ1, ω1, η̇1; absent for the ground) then side 2 (ṙ2, ω2, η̇2), with δA = A skew(δθ).
#pragma once

#include "model/body.hpp"

namespace drillflex::model {

using Vec6 = Eigen::Matrix<double, 6, 1>;

struct CouplingEnd {
  const Body* body = nullptr;  // nullptr: the ground
  Index node = 0;
  BodyPose pose;               // of the body, or the ground frame (r = point, A = frame, η empty)
};

struct CouplingKinematics {
  Vec6 strain = Vec6::Zero();
  MatX jacobian;  // 6 × (n1 + n2)
  Index n1 = 0, n2 = 0;
  // Intermediate quantities the Hessian needs.
  Mat3 A1 = Mat3::Identity(), R12 = Mat3::Identity(), R0 = Mat3::Identity(), R = Mat3::Identity();
  Vec3 w = Vec3::Zero(), u_b = Vec3::Zero(), vee_r = Vec3::Zero();
  const Eigen::Matrix<double, 3, Eigen::Dynamic>* phi_b = nullptr;
};

CouplingKinematics ComputeCouplingKinematics(const CouplingEnd& end1, const CouplingEnd& end2,
                                             const Mat3& built_in_rotation = Mat3::Identity());

// H(λ) = ∂(Bᵀλ)/∂v along the increments, (n1 + n2)²: the geometric part of the tangent of the
// generalized force Bᵀλ for a fixed force λ.
MatX CouplingJacobianDerivative(const CouplingKinematics& kinematics, const Vec6& lambda);

}  // namespace drillflex::model
