#include "model/coupling_kinematics.hpp"

#include "core/so3.hpp"

namespace drillflex::model {

using so3::Skew;

namespace {

// vee(skew(X)) = ½ (X − Xᵀ)^∨.
Vec3 VeeSkew(const Mat3& x) { return so3::Vee(x); }

}  // namespace

CouplingKinematics ComputeCouplingKinematics(const CouplingEnd& end1, const CouplingEnd& end2,
                                             const Mat3& built_in_rotation) {
  CouplingKinematics k;
  const bool grounded = end1.body == nullptr;
  const Body& body2 = *end2.body;
  k.n1 = grounded ? 0 : end1.body->velocity_count();
  k.n2 = body2.velocity_count();
  k.A1 = end1.pose.A;
  const Mat3& A2 = end2.pose.A;
  k.R12 = k.A1.transpose() * A2;
  k.R0 = built_in_rotation;
  k.R = k.R0.transpose() * k.R12;
  k.u_b = end2.pose.NodeOffset(body2, end2.node);
  k.phi_b = &body2.reduced->node_translation_modes[end2.node];
  const Vec3 u_a = grounded ? Vec3::Zero() : end1.pose.NodeOffset(*end1.body, end1.node);
  // r2 − r1 from the references (metres apart: nearly exact) and the displacements q holds
  // (BodyPose), never from the absolute origins: a frame kilometres from the well head is rounded
  // at the ulp of its origin (4.5e-13 m at 3.5 km, ~1 N in a coupling of 2e12 N/m), a floor of
  // noise under which Newton could not drive the residual. tests/model/far_origin_test.cpp.
  const Vec3 d = ((end2.pose.reference - end1.pose.reference) + (end2.pose.displacement - end1.pose.displacement)) +
                 A2 * k.u_b;
  k.w = k.A1.transpose() * d;
  k.vee_r = VeeSkew(k.R);
  const auto& psi_b = body2.reduced->node_rotation_modes[end2.node];
  k.strain.head<3>() = k.w - u_a;
  k.strain.tail<3>() = k.vee_r + psi_b * end2.pose.eta;

  const double trace = k.R.trace();
  const Mat3 g1 = -0.5 * (trace * Mat3::Identity() - k.R);            // ∂vee/∂δθ1' (δθ1' = R0ᵀδθ1)
  const Mat3 g2 = 0.5 * (trace * Mat3::Identity() - k.R.transpose());  // ∂vee/∂δθ2
  k.jacobian = MatX::Zero(6, k.n1 + k.n2);
  if (!grounded) {
    const Body& body1 = *end1.body;
    const auto& phi_a = body1.reduced->node_translation_modes[end1.node];
    const auto& psi_a = body1.reduced->node_rotation_modes[end1.node];
    k.strain.tail<3>() -= psi_a * end1.pose.eta;
    k.jacobian.block<3, 3>(0, 0) = -k.A1.transpose();
    k.jacobian.block<3, 3>(0, 3) = Skew(k.w);
    k.jacobian.block(0, 6, 3, body1.flexible_count) = -phi_a;
    k.jacobian.block<3, 3>(3, 3) = g1 * k.R0.transpose();
    k.jacobian.block(3, 6, 3, body1.flexible_count) = -psi_a;
  }
  const Index o = k.n1;
  k.jacobian.block<3, 3>(0, o) = k.A1.transpose();
  k.jacobian.block<3, 3>(0, o + 3) = -k.R12 * Skew(k.u_b);
  k.jacobian.block(0, o + 6, 3, body2.flexible_count) = k.R12 * (*k.phi_b);
  k.jacobian.block<3, 3>(3, o + 3) = g2;
  k.jacobian.block(3, o + 6, 3, body2.flexible_count) = psi_b;
  return k;
}

MatX CouplingJacobianDerivative(const CouplingKinematics& k, const Vec6& lambda) {
  const Index n = k.n1 + k.n2;
  MatX h = MatX::Zero(n, n);
  const Vec3 lt = lambda.head<3>();
  const Vec3 lr = lambda.tail<3>();
  const Mat3 skew_lt = Skew(lt);
  const Vec3 r12t_lt = k.R12.transpose() * lt;
  const Eigen::Matrix<double, 3, Eigen::Dynamic>& phi_b = *k.phi_b;
  const Index nf2 = phi_b.cols();
  const Index o = k.n1;  // first column of side 2
  // Rotational part: derivatives of G1ᵀλ and G2ᵀλ (see the header), δθ1' = R0ᵀ δθ1.
  const Mat3 lv = lr * k.vee_r.transpose();
  const Mat3 g1_d1 = -0.5 * (2.0 * lv + k.R.transpose() * Skew(lr));
  const Mat3 g1_d2 = -0.5 * (-2.0 * lv - Skew(k.R.transpose() * lr));
  const Mat3 g2_d1 = 0.5 * (2.0 * lv - Skew(k.R * lr));
  const Mat3 g2_d2 = 0.5 * (-2.0 * lv + k.R * Skew(lr));

  if (k.n1 > 0) {
    // Translational strain, side-1 rows.
    h.block<3, 3>(0, 3) += k.A1 * skew_lt;                         // [r1, θ1]
    h.block<3, 3>(3, 3) += skew_lt * Skew(k.w);                    // [θ1, θ1]
    h.block<3, 3>(3, 0) += -skew_lt * k.A1.transpose();            // [θ1, r1]
    h.block<3, 3>(3, o) += skew_lt * k.A1.transpose();             // [θ1, r2]
    h.block<3, 3>(3, o + 3) += -skew_lt * k.R12 * Skew(k.u_b);     // [θ1, θ2]
    h.block(3, o + 6, 3, nf2) += skew_lt * k.R12 * phi_b;          // [θ1, η2]
    h.block<3, 3>(o, 3) += -k.A1 * skew_lt;                        // [r2, θ1]
    h.block<3, 3>(o + 3, 3) += -Skew(k.u_b) * k.R12.transpose() * skew_lt;  // [θ2, θ1]
    h.block(o + 6, 3, nf2, 3) += -phi_b.transpose() * k.R12.transpose() * skew_lt;  // [η2, θ1]
    // Rotational strain.
    h.block<3, 3>(3, 3) += k.R0 * g1_d1 * k.R0.transpose();
    h.block<3, 3>(3, o + 3) += k.R0 * g1_d2;
    h.block<3, 3>(o + 3, 3) += g2_d1 * k.R0.transpose();
  }
  h.block<3, 3>(o + 3, o + 3) += Skew(k.u_b) * Skew(r12t_lt);    // [θ2, θ2]
  h.block(o + 3, o + 6, 3, nf2) += -Skew(r12t_lt) * phi_b;         // [θ2, η2]
  h.block(o + 6, o + 3, nf2, 3) += phi_b.transpose() * Skew(r12t_lt);  // [η2, θ2]
  h.block<3, 3>(o + 3, o + 3) += g2_d2;
  return h;
}

}  // namespace drillflex::model
