#include "model/string_above.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "model/hole_friction.hpp"

namespace drillflex::model {

EndStiffness SemiInfiniteBeamEndStiffness(double bending_rigidity, double foundation, double tension) {
  if (!(bending_rigidity > 0.0)) return {};
  const double p = std::sqrt(std::max(foundation, 0.0) / bending_rigidity);
  const double s_squared = tension / bending_rigidity + 2.0 * p;  // (a + b)² = a² + b² + 2ab
  if (!(s_squared > 0.0)) return {};  // beyond F_sin = 2 √(k EI): the pipe above lies buckled
  const double s = std::sqrt(s_squared);
  return {bending_rigidity * p * s, bending_rigidity * p, bending_rigidity * s};
}

StringAboveElement::StringAboveElement(const Body* body, Index node, const Vec3& position, const Mat3& frame,
                                       const StringAboveParameters& parameters)
    : ForceElement({body}), node_(node), parameters_(parameters) {
  ground_.r = ground_.reference = position;
  ground_.A = frame;  // the body's reference orientation: the rotational strain is measured from it
}

std::string StringAboveElement::Describe() const {
  return fmt::format("the pipe above the top at {:.4g} m from the bit",
                     bodies()[0]->NodeS(node_));
}

double StringAboveElement::Tension(const LoadParameters& load) const {
  if (parameters_.top_tension) return load.load_factor * *parameters_.top_tension;
  const double wob = load.weight_on_bit.value_or(parameters_.weight_on_bit);
  return load.load_factor * (load.weight_factor * parameters_.axial_weight - wob);
}

StringAboveElement::Lying StringAboveElement::LyingOf(const LoadParameters& load) const {
  const double tension = Tension(load);
  const double weight = load.load_factor * load.weight_factor * parameters_.weight_per_length;
  // The load across the hole per length: the weight's part, and the tension's pull toward the arc's
  // centre (a compression pushes outward).
  const Eigen::Vector2d across = weight * parameters_.gravity_across + tension * parameters_.curvature;
  Lying lying;
  const double load_per_length = across.norm();
  if (load_per_length > 0.0) lying.direction = across / load_per_length;
  lying.foundation = parameters_.clearance > 0.0 ? load_per_length / parameters_.clearance : 0.0;
  // The friction's climb around the hole (model/wall_contact.hpp: the friction per newton of normal
  // force is μ_t v_θ / max(|v|, v_ε) around the hole for the contact point's sliding v).
  std::optional<PrescribedSliding> sliding = parameters_.sliding;
  if (load.sliding_mode == SlidingMode::kVelocities) sliding.reset();
  if (load.sliding_mode == SlidingMode::kPrescribed) sliding = load.sliding;
  if (sliding && sliding->rotary_speed != 0.0) {
    const double mu = EffectiveFriction({parameters_.friction, parameters_.cased}, load).tangential;
    const double around = sliding->rotary_speed * parameters_.contact_radius;
    const double speed = std::max(std::hypot(sliding->axial_speed, around), parameters_.regularization_velocity);
    const double climb = std::atan(mu * std::abs(around) / speed);
    // Toward x × d for a clockwise (looking down-hole) turn: x × (0, d_y, d_z) = (0, −d_z, d_y).
    const Eigen::Vector2d sideways(-lying.direction.y(), lying.direction.x());
    const double sense = sliding->rotary_speed > 0.0 ? 1.0 : -1.0;
    lying.direction = std::cos(climb) * lying.direction + sense * std::sin(climb) * sideways;
  }
  return lying;
}

double StringAboveElement::BucklingMargin(const LoadParameters& load) const {
  return Tension(load) + 2.0 * std::sqrt(LyingOf(load).foundation * parameters_.bending_rigidity);
}

Eigen::Matrix<double, 6, 6> StringAboveElement::Stiffness(const LoadParameters& load) const {
  const double tension = Tension(load);
  const Lying lying = LyingOf(load);
  // Around the hole (u along t = x × d, tilt θ = −ψ·d for the rotation vector ψ) on the foundation;
  // up off the wall (u along d, tilt θ = ψ·t) on the tension alone.
  const EndStiffness around = SemiInfiniteBeamEndStiffness(parameters_.bending_rigidity, lying.foundation, tension);
  const EndStiffness off = SemiInfiniteBeamEndStiffness(parameters_.bending_rigidity, 0.0, tension);
  const Vec3 d(0.0, lying.direction.x(), lying.direction.y());
  const Vec3 t = Vec3::UnitX().cross(d);
  auto plane = [](const EndStiffness& end, const Vec6& u, const Vec6& theta) {
    return Eigen::Matrix<double, 6, 6>(end.uu * u * u.transpose() +
                                       end.u_theta * (u * theta.transpose() + theta * u.transpose()) +
                                       end.theta_theta * theta * theta.transpose());
  };
  Vec6 u_around, theta_around, u_off, theta_off;
  u_around << t, Vec3::Zero();
  theta_around << Vec3::Zero(), -d;
  u_off << d, Vec3::Zero();
  theta_off << Vec3::Zero(), t;
  return plane(around, u_around, theta_around) + plane(off, u_off, theta_off);
}

Vec6 StringAboveElement::Reaction(const ElementState& state) const {
  return -(Stiffness(state.parameters) * Kinematics(state).strain);
}

CouplingKinematics StringAboveElement::Kinematics(const ElementState& state) const {
  const CouplingEnd ground{nullptr, 0, ground_};
  const CouplingEnd end{bodies()[0], node_, *state.poses[0]};
  return ComputeCouplingKinematics(ground, end);
}

// f = K e on the strain e; generalized force Bᵀ f, tangent Bᵀ K B + H(f) (model/coupling_kinematics.hpp).
void StringAboveElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Eigen::Matrix<double, 6, 6> stiffness = Stiffness(state.parameters);
  if (stiffness.isZero(0.0)) return;
  const CouplingKinematics k = Kinematics(state);
  const Vec6 force = stiffness * k.strain;
  out.force.noalias() += k.jacobian.transpose() * force;
  if (!with_matrices) return;
  const Eigen::Matrix<double, 6, Eigen::Dynamic> weighted = stiffness * k.jacobian;
  out.stiffness.noalias() += k.jacobian.transpose() * weighted;
  out.stiffness += CouplingJacobianDerivative(k, force);
}

double StringAboveElement::DoPotentialEnergy(const ElementState& state) const {
  const Vec6 strain = Kinematics(state).strain;
  return 0.5 * strain.dot(Stiffness(state.parameters) * strain);
}

}  // namespace drillflex::model
