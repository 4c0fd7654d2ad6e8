#include "model/body.hpp"

#include "core/so3.hpp"

namespace drillflex::model {

Vec3 BodyPose::NodeOffset(const Body& body, Index node) const {
  return body.reduced->node_positions[node] + body.reduced->node_translation_modes[node] * eta;
}

Vec3 BodyPose::NodePosition(const Body& body, Index node) const {
  return r + A * NodeOffset(body, node);
}

Vec3 BodyPose::NodeRotation(const Body& body, Index node) const {
  return body.reduced->node_rotation_modes[node] * eta;
}

BodyPose PoseOf(const Body& body, const VecX& q) {
  BodyPose pose;
  pose.reference = body.reference_position;
  pose.displacement = q.segment<3>(body.q_offset);
  pose.r = pose.reference + pose.displacement;
  pose.rotation = Quat(q[body.q_offset + 3], q[body.q_offset + 4], q[body.q_offset + 5],
                       q[body.q_offset + 6]);
  pose.A = pose.rotation.toRotationMatrix();
  pose.eta = q.segment(body.q_offset + 7, body.flexible_count);
  return pose;
}

NodeMove NodeMoveBetween(const Body& body, const BodyPose& from, const BodyPose& to, Index node) {
  NodeMove move;
  move.translation = (to.displacement - from.displacement) + to.A * to.NodeOffset(body, node) -
                     from.A * from.NodeOffset(body, node);
  move.rotation = so3::LogMap(to.A * from.A.transpose()) +
                  0.5 * (to.A + from.A) * (to.NodeRotation(body, node) - from.NodeRotation(body, node));
  return move;
}

void SetReferencePose(const Body& body, VecX& q) {
  q.segment<3>(body.q_offset).setZero();  // q holds the displacement from reference_position
  const Quat& rotation = body.reference_orientation;
  q.segment<4>(body.q_offset + 3) << rotation.w(), rotation.x(), rotation.y(), rotation.z();
  q.segment(body.q_offset + 7, body.flexible_count).setZero();
}

void TwistKeepingShape(const Body& body, double angle, VecX& q, double twist_rate) {
  Quat rotation(q[body.q_offset + 3], q[body.q_offset + 4], q[body.q_offset + 5], q[body.q_offset + 6]);
  rotation = rotation * Quat(Eigen::AngleAxisd(angle, Vec3::UnitX()));
  rotation.normalize();
  q.segment<4>(body.q_offset + 3) << rotation.w(), rotation.x(), rotation.y(), rotation.z();
  const Index modes = body.flexible_count;
  if (modes == 0) return;
  const Index nodes = body.node_count();
  const Mat3 back = Eigen::AngleAxisd(-angle, Vec3::UnitX()).toRotationMatrix();
  const VecX eta = q.segment(body.q_offset + 7, modes);
  MatX basis(6 * nodes, modes);
  VecX target(6 * nodes);
  const double middle = 0.5 * (body.reduced->node_positions.front().x() + body.reduced->node_positions.back().x());
  for (Index k = 0; k < nodes; ++k) {
    basis.middleRows(6 * k, 3) = body.reduced->node_translation_modes[k];
    basis.middleRows(6 * k + 3, 3) = body.reduced->node_rotation_modes[k];
    target.segment<3>(6 * k) = back * (body.reduced->node_translation_modes[k] * eta);
    target.segment<3>(6 * k + 3) = back * (body.reduced->node_rotation_modes[k] * eta);
    target[6 * k + 3] += twist_rate * (body.reduced->node_positions[k].x() - middle);
  }
  q.segment(body.q_offset + 7, modes) = basis.colPivHouseholderQr().solve(target);
}

}  // namespace drillflex::model
