#include "model/bit_rock.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "model/node_force.hpp"

namespace drillflex::model {
namespace {

// Detournay's law, regularized (bit_rock.hpp): d = 2π V⁺/Ω_r with Ω_r = sqrt(Ω² + Ω_ε²),
// WOB = ζ ε a d + W_f c, TOB = (½ ε a² d + ½ μ γ a W_f c) s, c = clamp(V/V_ε, 0, 1) and
// s = clamp(Ω/Ω_ε, −1, 1).
BitRockForces Detournay(const BitRockParameters& p, double v, double omega) {
  const double omega_r = std::sqrt(omega * omega + p.stick_speed * p.stick_speed);
  const double depth = v > 0.0 ? 2.0 * kPi * v / omega_r : 0.0;
  const double depth_v = v > 0.0 ? 2.0 * kPi / omega_r : 0.0;
  const double depth_w = -depth * omega / (omega_r * omega_r);
  const double contact = std::clamp(v / p.contact_speed, 0.0, 1.0);
  const double contact_v = v > 0.0 && v < p.contact_speed ? 1.0 / p.contact_speed : 0.0;
  const double spin = std::clamp(omega / p.stick_speed, -1.0, 1.0);
  const double spin_w = std::abs(omega) < p.stick_speed ? 1.0 / p.stick_speed : 0.0;
  const double a = p.radius, eps = p.specific_energy;
  // The torque before the spin's sign: cutting ½ ε a² d plus the flats' friction ½ μ γ a W_f c.
  const double flats = 0.5 * p.friction * p.geometry * a * p.contact_force;
  const double torque = 0.5 * eps * a * a * depth + flats * contact;
  const double torque_v = 0.5 * eps * a * a * depth_v + flats * contact_v;
  const double torque_w = 0.5 * eps * a * a * depth_w;
  BitRockForces f;
  f.wob = p.cutting_ratio * eps * a * depth + p.contact_force * contact;
  f.wob_by_penetration = p.cutting_ratio * eps * a * depth_v + p.contact_force * contact_v;
  f.wob_by_spin = p.cutting_ratio * eps * a * depth_w;
  f.tob = torque * spin;
  f.tob_by_penetration = torque_v * spin;
  f.tob_by_spin = torque_w * spin + torque * spin_w;
  return f;
}

// Static/kinetic friction torque (bit_rock.hpp): viscous T_s Ω/Ω_ε up to Ω_ε, then the exponential
// drop T_d + (T_s − T_d) exp(−(|Ω| − Ω_ε)/Ω_d), continuous at Ω_ε.
BitRockForces Friction(const BitRockParameters& p, double omega) {
  BitRockForces f;
  const double speed = std::abs(omega);
  if (speed <= p.stick_speed) {
    f.tob = p.static_torque * omega / p.stick_speed;
    f.tob_by_spin = p.static_torque / p.stick_speed;
    return f;
  }
  const double drop = (p.static_torque - p.kinetic_torque) * std::exp(-(speed - p.stick_speed) / p.stribeck_speed);
  const double sign = omega > 0.0 ? 1.0 : -1.0;
  f.tob = sign * (p.kinetic_torque + drop);
  f.tob_by_spin = -drop / p.stribeck_speed;  // d/dΩ of sign·(T_d + drop(|Ω|)) = drop'(|Ω|)
  return f;
}

void Require(bool condition, const char* what) {
  if (!condition) throw LogicError(fmt::format("bit-rock interaction: {}", what));
}

}  // namespace

void CheckBitRockParameters(const BitRockParameters& p) {
  Require(p.stick_speed > 0.0, "the stick speed must be positive");
  if (p.bottom) {
    Require(p.law != BitRockLaw::Detournay,
            "a bottom contact does not go with Detournay's law (its WOB is already the rock's axial reaction)");
    CheckBitBottomParameters(*p.bottom);
  }
  if (p.side_cutting) CheckBitSideCuttingParameters({*p.side_cutting, p.stick_speed});
  if (p.law == BitRockLaw::None) return;
  if (p.law == BitRockLaw::Detournay) {
    Require(p.radius > 0.0, "the bit radius must be positive");
    Require(p.specific_energy > 0.0, "the intrinsic specific energy must be positive");
    Require(p.cutting_ratio > 0.0, "the cutting force ratio zeta must be positive");
    Require(p.contact_force >= 0.0, "the contact force of the wear flats must not be negative");
    Require(p.friction >= 0.0, "the friction coefficient must not be negative");
    Require(p.geometry > 0.0, "the bit geometry factor gamma must be positive");
    Require(p.contact_speed > 0.0, "the contact speed must be positive");
  } else {
    Require(p.kinetic_torque >= 0.0, "the kinetic friction torque must not be negative");
    Require(p.static_torque > p.kinetic_torque, "the static friction torque must exceed the kinetic one");
    Require(p.stribeck_speed > 0.0, "the Stribeck speed must be positive");
  }
}

BitRockForces EvaluateBitRock(const BitRockParameters& parameters, double penetration_rate, double spin_rate) {
  CheckBitRockParameters(parameters);
  if (parameters.law == BitRockLaw::None) return {};
  return parameters.law == BitRockLaw::Detournay ? Detournay(parameters, penetration_rate, spin_rate)
                                                 : Friction(parameters, spin_rate);
}

BitRockElement::BitRockElement(const Body* bit, const BitRockParameters& parameters)
    : ForceElement({bit}), parameters_(parameters),
      axis_(bit->reference_orientation.toRotationMatrix().col(0)) {
  CheckBitRockParameters(parameters_);
  if (parameters_.law == BitRockLaw::None) throw LogicError("BitRockElement: no law to apply");
}

std::string BitRockElement::Describe() const {
  return parameters_.law == BitRockLaw::Detournay ? "bit-rock interaction (Detournay) at the bit"
                                                  : "bit-rock interaction (friction) at the bit";
}

double BitRockElement::PenetrationRate(const ElementState& state) const {
  const Body& bit = *bodies()[0];
  return -axis_.dot(ComputeNodeMotion(bit, *state.poses[0], 0, state.velocity).velocity);
}

double BitRockElement::SpinRate(const ElementState& state) const {
  const Body& bit = *bodies()[0];
  return -axis_.dot(ComputeNodeMotion(bit, *state.poses[0], 0, state.velocity).angular_velocity);
}

void BitRockElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& bit = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(bit, pose, 0, state.velocity);
  const double penetration = -axis_.dot(motion.velocity);
  const double spin = -axis_.dot(motion.angular_velocity);
  const BitRockForces f = EvaluateBitRock(parameters_, penetration, spin);
  // On the bit: F = WOB t (up-hole), M = TOB t (against a spin about −t).
  const Vec3 force = f.wob * axis_, moment = f.tob * axis_;
  if (!with_matrices) {
    AddNodeForce(bit, pose, 0, motion, force, moment, nullptr, false, out);
    return;
  }
  // ∂V/∂ṙ_k = ∂Ω/∂ω_k = −tᵀ, so ∂F/∂ṙ_k = −WOB_V t tᵀ, ∂F/∂ω_k = −WOB_Ω t tᵀ, and M alike.
  const Mat3 tt = axis_ * axis_.transpose();
  NodeForceJacobian jacobian;
  jacobian.force_velocity = -f.wob_by_penetration * tt;
  jacobian.force_angular_velocity = -f.wob_by_spin * tt;
  jacobian.moment_velocity = -f.tob_by_penetration * tt;
  jacobian.moment_angular_velocity = -f.tob_by_spin * tt;
  AddNodeForce(bit, pose, 0, motion, force, moment, &jacobian, true, out);
}

}  // namespace drillflex::model
