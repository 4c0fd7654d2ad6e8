#include "analyses/string_stations.hpp"

#include <cmath>

#include "core/so3.hpp"

namespace drillflex::analyses {

std::vector<Station> StringStations(const model::SystemModel& model) {
  std::vector<Station> stations;
  const auto& bodies = model.bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const model::Body& body = bodies[b];
    for (int k = 0; k < body.node_count(); ++k) {
      Station station;
      station.s = body.NodeS(k);
      station.body = static_cast<int>(b);
      station.node = k;
      if (k == 0 && b > 0) {
        const model::Body& below = bodies[b - 1];
        const double below_end = below.s_start + below.length();
        // A joint: the lower body's end node is this station too (read from the upper body).
        if (std::abs(below_end - station.s) <= 1e-9 * std::max(1.0, std::abs(station.s))) {
          station.lower_body = static_cast<int>(b - 1);
          stations.back() = station;  // replaces the lower body's end node
          continue;
        }
      }
      stations.push_back(station);
    }
  }
  return stations;
}

NodeMotion ComputeNodeMotion(const model::Body& body, const model::BodyPose& pose, int node) {
  const Mat3 frame = body.reference_orientation.toRotationMatrix();  // string frame at the body
  const Vec3 reference = body.reference_position + frame * body.reduced->node_positions[node];
  NodeMotion motion;
  motion.position = pose.NodePosition(body, node);
  motion.displacement = frame.transpose() * (motion.position - reference);
  // Node orientation A · Exp(θ_k) relative to the reference frame, as a rotation vector in it.
  const Mat3 node_rotation = pose.A * so3::ExpMap(pose.NodeRotation(body, node));
  motion.rotation = so3::LogMap(frame.transpose() * node_rotation);
  return motion;
}

NodeVelocity MapToNode(const model::Body& body, const model::BodyPose& pose, const VecX& v, int node) {
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  const Mat3 to_string = frame.transpose() * pose.A;
  const int n_f = body.flexible_count;
  const Vec3 velocity = v.segment<3>(body.v_offset);
  const Vec3 omega = v.segment<3>(body.v_offset + 3);
  const auto eta_dot = v.segment(body.v_offset + 6, n_f);
  const Vec3 offset = pose.NodeOffset(body, node);
  NodeVelocity result;
  // ṙ_k = ṙ + A(ω × u_k + Φ_k η̇), ω_k = ω + Ψ_k η̇ (method.md §4).
  result.translation = frame.transpose() * velocity +
                       to_string * (omega.cross(offset) + body.reduced->node_translation_modes[node] * eta_dot);
  result.rotation = to_string * (omega + body.reduced->node_rotation_modes[node] * eta_dot);
  return result;
}

}  // namespace drillflex::analyses
