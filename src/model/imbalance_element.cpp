// The imbalance's centripetal d'Alembert force (formulas in imbalance_element.hpp).
#include "model/imbalance_element.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/node_force.hpp"

namespace drillflex::model {

using so3::Skew;

ImbalanceElement::ImbalanceElement(const Body* body, Index node, double imbalance, const Vec3& direction)
    : ForceElement({body}), node_(node), imbalance_(imbalance) {
  if (body == nullptr || node < 0 || node >= body->node_count()) {
    throw LogicError(fmt::format("ImbalanceElement: node {} is not on the body", node));
  }
  if (!(imbalance > 0.0)) throw LogicError("ImbalanceElement: the imbalance m·e must be positive");
  if (!(direction.norm() > 0.0) || std::abs(direction.x()) > 1e-12 * direction.norm()) {
    throw LogicError("ImbalanceElement: the offset must lie across the string axis");
  }
  direction_ = direction.normalized();
}

std::string ImbalanceElement::Describe() const {
  const Body& body = *bodies()[0];
  return fmt::format("imbalance {:.4g} kg·m at {:.4g} m from the bit", imbalance_,
                     body.NodeS(node_));
}

Vec3 ImbalanceElement::Force(const ElementState& state) const {
  const NodeMotion motion = ComputeNodeMotion(*bodies()[0], *state.poses[0], node_, state.velocity);
  const Vec3 e = state.poses[0]->A * direction_;
  const Vec3& w = motion.angular_velocity;
  return -imbalance_ * w.cross(w.cross(e));
}

void ImbalanceElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(body, pose, node_, state.velocity);
  const Vec3 e = pose.A * direction_;
  const Vec3& w = motion.angular_velocity;
  const Vec3 force = -imbalance_ * w.cross(w.cross(e));
  if (!with_matrices) {
    AddNodeForce(body, pose, node_, motion, force, Vec3::Zero(), nullptr, false, out);
    return;
  }
  NodeForceJacobian jacobian;
  jacobian.force_angular_velocity = -imbalance_ * (w * e.transpose() + w.dot(e) * Mat3::Identity() - 2.0 * e * w.transpose());
  AddNodeForce(body, pose, node_, motion, force, Vec3::Zero(), &jacobian, true, out);
  // The turn of ê with the body frame at a fixed ω_k: −L_kᵀ X on the δθ columns.
  const Mat3 skew_w = Skew(w);
  const Mat3 X = imbalance_ * skew_w * skew_w * pose.A * Skew(direction_);
  const Mat3 AtX = pose.A.transpose() * X;
  const auto& phi = body.reduced->node_translation_modes[node_];
  out.stiffness.block<3, 3>(0, 3) -= X;
  out.stiffness.block<3, 3>(3, 3) -= Skew(motion.offset) * AtX;
  out.stiffness.block(6, 3, body.flexible_count, 3).noalias() -= phi.transpose() * AtX;
}

}  // namespace drillflex::model
