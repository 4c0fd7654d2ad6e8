#include "model/body.hpp"

namespace drillflex::model {

Vec3 BodyPose::NodeOffset(const Body& body, int node) const {
  return body.reduced->node_positions[node] + body.reduced->node_translation_modes[node] * eta;
}

Vec3 BodyPose::NodePosition(const Body& body, int node) const {
  return r + A * NodeOffset(body, node);
}

Vec3 BodyPose::NodeRotation(const Body& body, int node) const {
  return body.reduced->node_rotation_modes[node] * eta;
}

BodyPose PoseOf(const Body& body, const VecX& q) {
  BodyPose pose;
  pose.r = q.segment<3>(body.q_offset);
  pose.rotation = Quat(q[body.q_offset + 3], q[body.q_offset + 4], q[body.q_offset + 5],
                       q[body.q_offset + 6]);
  pose.A = pose.rotation.toRotationMatrix();
  pose.eta = q.segment(body.q_offset + 7, body.flexible_count);
  return pose;
}

void SetReferencePose(const Body& body, VecX& q) {
  q.segment<3>(body.q_offset) = body.reference_position;
  const Quat& rotation = body.reference_orientation;
  q.segment<4>(body.q_offset + 3) << rotation.w(), rotation.x(), rotation.y(), rotation.z();
  q.segment(body.q_offset + 7, body.flexible_count).setZero();
}

}  // namespace drillflex::model
