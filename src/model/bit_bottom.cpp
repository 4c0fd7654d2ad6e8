// The bottom contact of the bit (formulas in bit_bottom.hpp).
#include "model/bit_bottom.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "model/node_force.hpp"

namespace drillflex::model {
namespace {

void Require(bool condition, const char* what) {
  if (!condition) throw LogicError(fmt::format("bit bottom contact: {}", what));
}

// The bottom's motion at t: its envelope A(t) = a ½(1 − cos(π t/T_r)) (a after T_r) times
// sin(2π f t), and the rate of that product.
struct BottomMotion {
  double place = 0.0, rate = 0.0;
};

BottomMotion Motion(const BitBottomParameters& p, double t) {
  BottomMotion m{p.level, 0.0};
  if (p.amplitude == 0.0 || t <= 0.0) return m;
  double envelope = p.amplitude, envelope_rate = 0.0;
  if (t < p.ramp_time) {
    const double phase = kPi * t / p.ramp_time;
    envelope = 0.5 * p.amplitude * (1.0 - std::cos(phase));
    envelope_rate = 0.5 * p.amplitude * std::sin(phase) * kPi / p.ramp_time;
  }
  const double omega = 2.0 * kPi * p.frequency;
  m.place += envelope * std::sin(omega * t);
  m.rate = envelope_rate * std::sin(omega * t) + envelope * omega * std::cos(omega * t);
  return m;
}

// N = k δ + c δ̇ while δ > 0 and N > 0, else 0 (header: the damper never pulls).
double NormalForce(double stiffness, double damping, double penetration, double penetration_rate) {
  if (!(penetration > 0.0)) return 0.0;
  const double force = stiffness * penetration + damping * penetration_rate;
  return force > 0.0 ? force : 0.0;
}

}  // namespace

void CheckBitBottomParameters(const BitBottomParameters& p) {
  Require(p.stiffness >= 0.0, "the stiffness must not be negative");
  Require(p.damping_ratio >= 0.0, "the damping ratio must not be negative");
  Require(std::isfinite(p.level), "the bottom's level must be finite");
  Require(p.amplitude >= 0.0, "the amplitude of the bottom's motion must not be negative");
  Require(p.amplitude == 0.0 || p.frequency > 0.0, "a bottom motion needs a positive frequency");
  Require(p.ramp_time >= 0.0, "the ramp time must not be negative");
}

BitBottomElement::BitBottomElement(const Body* bit, Index node, const Vec3& position, const Vec3& axis,
                                   const BitBottomParameters& parameters, double stiffness, double damping)
    : ForceElement({bit}), node_(node), position_(position), axis_(axis.normalized()), parameters_(parameters),
      stiffness_(stiffness), damping_(damping) {
  CheckBitBottomParameters(parameters_);
  if (node < 0 || node >= bit->node_count()) throw LogicError("BitBottomElement: the node is not on the body");
  if (!(stiffness > 0.0 && damping >= 0.0)) {
    throw LogicError("BitBottomElement: the contact needs a positive stiffness and a damping ≥ 0");
  }
}

std::string BitBottomElement::Describe() const {
  return fmt::format("bottom contact of the bit (k = {:.4g} N/m)", stiffness_);
}

double BitBottomElement::BottomPlace(double time) const { return Motion(parameters_, time).place; }
double BitBottomElement::BottomRate(double time) const { return Motion(parameters_, time).rate; }

double BitBottomElement::Penetration(const ElementState& state) const {
  const Vec3 r = state.poses[0]->NodePosition(*bodies()[0], node_);
  return BottomPlace(state.time) - axis_.dot(r - position_);
}

double BitBottomElement::ContactForce(const ElementState& state) const {
  const NodeMotion motion = ComputeNodeMotion(*bodies()[0], *state.poses[0], node_, state.velocity);
  const BottomMotion bottom = Motion(parameters_, state.time);
  return NormalForce(stiffness_, damping_, bottom.place - axis_.dot(motion.position - position_),
                     bottom.rate - axis_.dot(motion.velocity));
}

void BitBottomElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& bit = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(bit, pose, node_, state.velocity);
  const BottomMotion bottom = Motion(parameters_, state.time);
  const double force = NormalForce(stiffness_, damping_, bottom.place - axis_.dot(motion.position - position_),
                                   bottom.rate - axis_.dot(motion.velocity));
  if (!(force > 0.0)) return;  // lifted off (or the damper would pull): nothing, no derivatives
  const Mat3 tt = axis_ * axis_.transpose();
  NodeForceJacobian jacobian;
  jacobian.force_position = -stiffness_ * tt;
  jacobian.force_velocity = -damping_ * tt;
  AddNodeForce(bit, pose, node_, motion, force * axis_, Vec3::Zero(), &jacobian, with_matrices, out);
}

double BitBottomElement::DoPotentialEnergy(const ElementState& state) const {
  const double penetration = Penetration(state);
  return penetration > 0.0 ? 0.5 * stiffness_ * penetration * penetration : 0.0;
}

bool BitBottomElement::DoPenalty(const ElementState& state, double& value, double& stiffness, VecX& gradient) const {
  const Body& bit = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(bit, pose, node_, VecX::Zero(local_size()));
  value = BottomPlace(state.time) - axis_.dot(motion.position - position_);
  stiffness = stiffness_;
  // ∂δ/∂r = −t: the residual carries −Lᵀ F for a force F on the node, so F = −∇δ = t gives Lᵀ ∇δ.
  ElementContribution mapped;
  mapped.force = VecX::Zero(local_size());
  AddNodeForce(bit, pose, node_, motion, axis_, Vec3::Zero(), nullptr, false, mapped);
  gradient = std::move(mapped.force);
  return true;
}

}  // namespace drillflex::model
