// Top drive and block elements (formulas in drive_elements.hpp).
#include "model/drive_elements.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/node_force.hpp"

namespace drillflex::model {

using so3::Skew;

namespace {

void CheckNode(const Body* body, Index node, const char* what) {
  if (body == nullptr || node < 0 || node >= body->node_count()) {
    throw LogicError(fmt::format("{}: node {} is not on the body", what, node));
  }
}

}  // namespace

// What the speed drive's spring needs at a state (drive_elements.hpp).
struct TopDriveElement::Twist {
  Mat3 R = Mat3::Identity();   // Gᵀ A
  Vec3 vee_r = Vec3::Zero();   // vee(skew(R))
  VecX b;                      // ∂ė/∂v over the body's velocities
  double strain = 0.0;         // e, rad
  double rate = 0.0;           // ė, rad/s
  double drive_rate = 0.0;     // ψ̇ = −speed(t), rad/s about +x
};

TopDriveElement::TopDriveElement(const Body* body, Index node, const Mat3& frame, const TopDrive& drive,
                                 double stiffness, double damping)
    : ForceElement({body}), node_(node), frame_(frame), drive_(drive), stiffness_(stiffness), damping_(damping) {
  CheckNode(body, node, "TopDriveElement");
  if (drive.mode == TopDriveMode::Speed && !(stiffness > 0.0 && damping >= 0.0)) {
    throw LogicError("TopDriveElement: a speed drive needs a positive stiffness and a damping ≥ 0");
  }
  if (!(drive.setting.ramp_time >= 0.0)) throw LogicError("TopDriveElement: the ramp time must be ≥ 0");
}

std::string TopDriveElement::Describe() const {
  return fmt::format("top drive ({}) at {:.4g} m from the bit", drive_.mode == TopDriveMode::Speed ? "speed" : "torque",
                     bodies()[0]->NodeS(node_));
}

double TopDriveElement::DriveAngle(double t) const {
  return drive_.mode == TopDriveMode::Speed ? drive_.setting.Integral(t) : 0.0;
}

TopDriveElement::Twist TopDriveElement::Kinematics(const ElementState& state) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const Index nf = body.flexible_count;
  const auto& psi = body.reduced->node_rotation_modes[node_];
  Twist k;
  // G = F Rx(ψ), ψ = −angle: from cos and sin of the total angle, so any number of turns is exact
  // to the rounding of the angle itself.
  const double psi_angle = -DriveAngle(state.time);
  k.drive_rate = -drive_.setting.Value(state.time);
  const Mat3 turn = Eigen::AngleAxisd(psi_angle, Vec3::UnitX()).toRotationMatrix();
  k.R = (frame_ * turn).transpose() * pose.A;
  k.vee_r = so3::Vee(k.R);
  const double trace = k.R.trace();
  k.b = VecX::Zero(body.velocity_count());
  k.b.segment<3>(3) = 0.5 * (trace * Vec3::UnitX() - k.R.col(0));  // g2ᵀ e_x
  k.b.tail(nf) = psi.row(0).transpose();                            // Ψ_kᵀ e_x
  k.strain = k.vee_r.x() + psi.row(0).dot(pose.eta);
  const double g1_xx = -0.5 * (trace - k.R(0, 0));
  k.rate = k.b.dot(state.velocity) + k.drive_rate * g1_xx;
  return k;
}

void TopDriveElement::EvaluateSpeed(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Twist k = Kinematics(state);
  const double torque = stiffness_ * k.strain + damping_ * k.rate;
  out.force += torque * k.b;
  if (!with_matrices) return;
  const Vec3 ex = Vec3::UnitX();
  const Vec3 omega = state.velocity.segment<3>(3);
  // s_θ = ∂ė/∂θ (header).
  const Vec3 rate_theta = -omega.x() * k.vee_r + 0.5 * (k.R.transpose() * omega).cross(ex) +
                          k.drive_rate * (k.vee_r + 0.5 * ex.cross(k.R.transpose() * ex));
  out.stiffness.noalias() += stiffness_ * k.b * k.b.transpose();
  out.stiffness.middleCols<3>(3).noalias() += damping_ * k.b * rate_theta.transpose();
  out.stiffness.block<3, 3>(3, 3) += torque * (-ex * k.vee_r.transpose() + 0.5 * k.R * Skew(ex));
  out.damping.noalias() += damping_ * k.b * k.b.transpose();
}

void TopDriveElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  if (drive_.mode == TopDriveMode::Speed) {
    EvaluateSpeed(state, with_matrices, out);
    return;
  }
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(body, pose, node_, state.velocity);
  // Clockwise looking down-hole: about −x of the string frame.
  const Vec3 moment = -state.parameters.load_factor * drive_.setting.Value(state.time) * (frame_ * Vec3::UnitX());
  AddNodeForce(body, pose, node_, motion, Vec3::Zero(), moment, nullptr, with_matrices, out);
}

double TopDriveElement::Torque(const ElementState& state) const {
  if (drive_.mode == TopDriveMode::Torque) return state.parameters.load_factor * drive_.setting.Value(state.time);
  const Twist k = Kinematics(state);
  return stiffness_ * k.strain + damping_ * k.rate;
}

double TopDriveElement::Lag(const ElementState& state) const {
  return drive_.mode == TopDriveMode::Speed ? Kinematics(state).strain : 0.0;
}

double TopDriveElement::DoPotentialEnergy(const ElementState& state) const {
  if (drive_.mode == TopDriveMode::Torque) return 0.0;  // a moment on a turning node has no potential
  const double e = Kinematics(state).strain;
  return 0.5 * stiffness_ * e * e;
}

BlockElement::BlockElement(const Body* body, Index node, const Vec3& position, const Mat3& frame,
                           const BlockDrive& drive, double stiffness, double damping, double preload)
    : ForceElement({body}), node_(node), position_(position), axis_(frame.col(0)), drive_(drive),
      stiffness_(stiffness), damping_(damping), preload_(preload) {
  CheckNode(body, node, "BlockElement");
  if (drive.mode == BlockMode::Velocity && !(stiffness > 0.0 && damping >= 0.0)) {
    throw LogicError("BlockElement: a block velocity needs a positive stiffness and a damping ≥ 0");
  }
  if (!(drive.setting.ramp_time >= 0.0)) throw LogicError("BlockElement: the ramp time must be ≥ 0");
}

std::string BlockElement::Describe() const {
  return fmt::format("block ({}) at {:.4g} m from the bit",
                     drive_.mode == BlockMode::Velocity ? "velocity" : "hook load", bodies()[0]->NodeS(node_));
}

void BlockElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(body, pose, node_, state.velocity);
  if (drive_.mode == BlockMode::HookLoad) {
    const Vec3 force = state.parameters.load_factor * drive_.setting.Value(state.time) * axis_;
    AddNodeForce(body, pose, node_, motion, force, Vec3::Zero(), nullptr, with_matrices, out);
    return;
  }
  const Vec3 force = -SpringForce(motion, state.time) * axis_;
  NodeForceJacobian jacobian;
  const Mat3 projector = axis_ * axis_.transpose();
  jacobian.force_position = -stiffness_ * projector;
  jacobian.force_velocity = -damping_ * projector;
  AddNodeForce(body, pose, node_, motion, force, Vec3::Zero(), &jacobian, with_matrices, out);
}

double BlockElement::HookLoad(const ElementState& state) const {
  if (drive_.mode == BlockMode::HookLoad) return state.parameters.load_factor * drive_.setting.Value(state.time);
  return -SpringForce(ComputeNodeMotion(*bodies()[0], *state.poses[0], node_, state.velocity), state.time);
}

double BlockElement::SpringForce(const NodeMotion& motion, double t) const {
  const double strain = axis_.dot(motion.position - position_) - drive_.setting.Integral(t);
  const double rate = axis_.dot(motion.velocity) - drive_.setting.Value(t);
  return stiffness_ * strain + damping_ * rate + preload_;
}

double BlockElement::DoPotentialEnergy(const ElementState& state) const {
  const Body& body = *bodies()[0];
  const Vec3 position = state.poses[0]->NodePosition(body, node_);
  if (drive_.mode == BlockMode::HookLoad) {
    return -state.parameters.load_factor * drive_.setting.Value(state.time) * axis_.dot(position - position_);
  }
  const double strain = axis_.dot(position - position_) - drive_.setting.Integral(state.time);
  return 0.5 * stiffness_ * strain * strain + preload_ * strain;
}

}  // namespace drillflex::model
