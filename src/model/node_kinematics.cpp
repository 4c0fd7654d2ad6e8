#include "model/node_kinematics.hpp"

#include "core/so3.hpp"

namespace drillflex::model {

Vec3 NodeReferencePosition(const Body& body, Index node) {
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  return body.reference_position + frame * body.reduced->node_positions[node];
}

NodeMotion ComputeNodeMotion(const Body& body, const BodyPose& pose, Index node,
                             const Eigen::Ref<const VecX>& body_velocity) {
  const auto& phi = body.reduced->node_translation_modes[node];
  const auto& psi = body.reduced->node_rotation_modes[node];
  const auto eta_rate = body_velocity.segment(6, body.flexible_count);
  NodeMotion motion;
  motion.offset = body.reduced->node_positions[node] + phi * pose.eta;
  motion.position = pose.r + pose.A * motion.offset;
  motion.body_rate = body_velocity.segment<3>(3);
  motion.relative_velocity = motion.body_rate.cross(motion.offset) + phi * eta_rate;
  motion.node_rate = motion.body_rate + psi * eta_rate;
  motion.velocity = body_velocity.head<3>() + pose.A * motion.relative_velocity;
  motion.angular_velocity = pose.A * motion.node_rate;
  return motion;
}

NodeRates ComputeBodyFrameNodeRates(const Body& body, const BodyPose& pose, Index node, const VecX& body_velocity) {
  const cms::ReducedBody& reduced = *body.reduced;
  const Vec3 velocity = pose.A.transpose() * body_velocity.head<3>();
  const Vec3 omega = body_velocity.segment<3>(3);
  const auto eta_dot = body_velocity.tail(body.flexible_count);
  NodeRates rates;
  rates.translation = velocity + omega.cross(pose.NodeOffset(body, node)) + reduced.node_translation_modes[node] * eta_dot;
  rates.rotation = omega + reduced.node_rotation_modes[node] * eta_dot;
  return rates;
}

NodeRates ComputeStringFrameNodeRates(const Body& body, const BodyPose& pose, const VecX& v, Index node) {
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  const Mat3 to_string = frame.transpose() * pose.A;
  const Index n_f = body.flexible_count;
  const Vec3 velocity = v.segment<3>(body.v_offset);
  const Vec3 omega = v.segment<3>(body.v_offset + 3);
  const auto eta_dot = v.segment(body.v_offset + 6, n_f);
  const Vec3 offset = pose.NodeOffset(body, node);
  NodeRates rates;
  rates.translation = frame.transpose() * velocity +
                      to_string * (omega.cross(offset) + body.reduced->node_translation_modes[node] * eta_dot);
  rates.rotation = to_string * (omega + body.reduced->node_rotation_modes[node] * eta_dot);
  return rates;
}

NodeDisplacement ComputeNodeDisplacement(const Body& body, const BodyPose& pose, Index node) {
  const Mat3 frame = body.reference_orientation.toRotationMatrix();  // string frame at the body
  const Vec3 reference = NodeReferencePosition(body, node);
  NodeDisplacement motion;
  motion.position = pose.NodePosition(body, node);
  motion.displacement = frame.transpose() * (motion.position - reference);
  // Node orientation A · Exp(θ_k) relative to the reference frame, as a rotation vector in it.
  const Mat3 node_rotation = pose.A * so3::ExpMap(pose.NodeRotation(body, node));
  motion.rotation = so3::LogMap(frame.transpose() * node_rotation);
  return motion;
}

FrameMotion ComputeFrameMotion(const BodyPose& pose, const VecX& body_velocity, const VecX& body_acceleration) {
  return {pose.A.transpose() * body_velocity.head<3>(), pose.A.transpose() * body_acceleration.head<3>(),
          body_velocity.segment<3>(3), body_acceleration.segment<3>(3)};
}

BodyFrameNodeMotion ComputeBodyFrameNodeMotion(const Body& body, const BodyPose& pose, const FrameMotion& frame,
                                               const VecX& body_velocity, const VecX& body_acceleration, Index node) {
  const Index nf = body.flexible_count;
  const auto& phi = body.reduced->node_translation_modes[node];
  BodyFrameNodeMotion motion;
  motion.offset = pose.NodeOffset(body, node);
  motion.modal_velocity = phi * body_velocity.tail(nf);
  motion.velocity = frame.velocity + frame.omega.cross(motion.offset) + motion.modal_velocity;
  // d/dt(Aᵀṙ) = Aᵀr̈ − ω × Aᵀṙ, d/dt(ω × u) = ω̇ × u + ω × Φ η̇.
  motion.rate = frame.acceleration + frame.omega_rate.cross(motion.offset) + phi * body_acceleration.tail(nf) +
                frame.omega.cross(motion.modal_velocity) - frame.omega.cross(frame.velocity);
  return motion;
}

void NodeVelocityJacobian(const Body& body, const BodyPose& pose, Index node, const Vec3& offset,
                          Eigen::Matrix<double, 3, Eigen::Dynamic>& jacobian) {
  jacobian.resize(3, body.velocity_count());
  jacobian.leftCols<3>() = pose.A.transpose();
  jacobian.middleCols<3>(3) = -so3::Skew(offset);  // ω × u = −ũ ω
  jacobian.rightCols(body.flexible_count) = body.reduced->node_translation_modes[node];
}

MatX NodeTranslationJacobian(const Body& body, const BodyPose& pose, Index node) {
  MatX jacobian(3, body.velocity_count());
  jacobian.leftCols<3>() = Mat3::Identity();
  jacobian.middleCols<3>(3) = -pose.A * so3::Skew(pose.NodeOffset(body, node));
  jacobian.rightCols(body.flexible_count) = pose.A * body.reduced->node_translation_modes[node];
  return jacobian;
}

}  // namespace drillflex::model
