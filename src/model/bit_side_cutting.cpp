// The bit's side cutting (formulas in bit_side_cutting.hpp).
#include "model/bit_side_cutting.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "model/node_force.hpp"

namespace drillflex::model {

void CheckBitSideCuttingParameters(const BitSideCuttingParameters& p) {
  if (!(p.resistance > 0.0)) throw LogicError("bit side cutting: the lateral cutting resistance must be positive");
  if (!(p.stick_speed > 0.0)) throw LogicError("bit side cutting: the stick speed must be positive");
}

BitSideCuttingElement::BitSideCuttingElement(const Body* bit, const BitSideCuttingParameters& parameters)
    : ForceElement({bit}), parameters_(parameters), axis_(bit->reference_orientation.toRotationMatrix().col(0)) {
  CheckBitSideCuttingParameters(parameters_);
}

std::string BitSideCuttingElement::Describe() const {
  return fmt::format("side cutting of the bit (k_s = {:.4g} N/m)", parameters_.resistance);
}

void BitSideCuttingElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& bit = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(bit, pose, 0, state.velocity);
  const double spin = -axis_.dot(motion.angular_velocity);
  const double omega_r = std::sqrt(spin * spin + parameters_.stick_speed * parameters_.stick_speed);
  const double coefficient = 2.0 * kPi * parameters_.resistance / omega_r;  // N·s/m
  const Mat3 projector = Mat3::Identity() - axis_ * axis_.transpose();
  const Vec3 lateral = projector * motion.velocity;
  const Vec3 force = -coefficient * lateral;
  if (!with_matrices) {
    AddNodeForce(bit, pose, 0, motion, force, Vec3::Zero(), nullptr, false, out);
    return;
  }
  NodeForceJacobian jacobian;
  jacobian.force_velocity = -coefficient * projector;
  jacobian.force_angular_velocity = -(coefficient * spin / (omega_r * omega_r)) * lateral * axis_.transpose();
  AddNodeForce(bit, pose, 0, motion, force, Vec3::Zero(), &jacobian, true, out);
}

}  // namespace drillflex::model
