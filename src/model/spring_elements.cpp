#include "model/spring_elements.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/so3.hpp"

namespace drillflex::model {

namespace {

// Bᵀf, and the tangent Bᵀ K B + H(f) and damping Bᵀ C B of a spring on coupling kinematics.
// The derivative of ė = B v with respect to the positions (a term ∝ C v) is left out of the
// tangent: it vanishes at rest (statics, modes about equilibrium) and only slows Newton slightly
// in transients.
void SpringContribution(const CouplingKinematics& k, const Vec6& stiffness, const Vec6& damping,
                        const VecX& velocity, bool with_matrices, ElementContribution& out) {
  if (stiffness.isZero(0.0) && damping.isZero(0.0)) return;
  const Vec6 rate = k.jacobian * velocity;
  const Vec6 force = stiffness.cwiseProduct(k.strain) + damping.cwiseProduct(rate);
  out.force.noalias() += k.jacobian.transpose() * force;
  if (!with_matrices) return;
  // Jᵀ diag(k) J as a lazy product of J and the weighted J: Eigen's GEMM for the 36 × 6 × 36 product
  // packed and allocated more than it computed (a twentieth of the bundled example's transient).
  thread_local Eigen::Matrix<double, 6, Eigen::Dynamic> weighted;
  weighted.noalias() = stiffness.asDiagonal() * k.jacobian;
  out.stiffness.noalias() += k.jacobian.transpose().lazyProduct(weighted);
  out.stiffness += CouplingJacobianDerivative(k, force);
  if (!out.damping_needed) return;  // half the products of a coupling's matrices (statics)
  weighted.noalias() = damping.asDiagonal() * k.jacobian;
  out.damping.noalias() += k.jacobian.transpose().lazyProduct(weighted);
}

// A stiffness scaled by `factor` and its damping by √factor (the same damping ratio).
struct ScaledSpring {
  Vec6 stiffness, damping;
};
ScaledSpring Scaled(const Vec6& stiffness, const Vec6& damping, double factor) {
  if (factor == 1.0) return {stiffness, damping};
  return {factor * stiffness, std::sqrt(std::max(factor, 0.0)) * damping};
}

}  // namespace

CouplingElement::CouplingElement(const Body* lower, Index lower_node, const Body* upper, Index upper_node,
                                 const Vec6& stiffness, const Vec6& damping, const Mat3& built_in_rotation,
                                 const Vec3& placement_kink)
    : ForceElement({lower, upper}), lower_node_(lower_node), upper_node_(upper_node), stiffness_(stiffness),
      damping_(damping), built_in_rotation_(built_in_rotation), placement_kink_(placement_kink) {}

std::string CouplingElement::Describe() const {
  return fmt::format("coupling at {:.4g} m from the bit", bodies()[1]->s_start);
}

CouplingKinematics CouplingElement::Kinematics(const ElementState& state) const {
  const CouplingEnd lower{bodies()[0], lower_node_, *state.poses[0]};
  const CouplingEnd upper{bodies()[1], upper_node_, *state.poses[1]};
  const Mat3 rest = placement_kink_.isZero(0.0)
                        ? built_in_rotation_
                        : Mat3(built_in_rotation_ * so3::ExpMap((1.0 - state.parameters.load_factor) * placement_kink_));
  return ComputeCouplingKinematics(lower, upper, rest);
}

void CouplingElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const ScaledSpring spring = Scaled(stiffness_, damping_, state.parameters.coupling_factor);
  SpringContribution(Kinematics(state), spring.stiffness, spring.damping, state.velocity, with_matrices, out);
}

Vec6 CouplingElement::Force(const ElementState& state) const {
  const CouplingKinematics k = Kinematics(state);
  const ScaledSpring spring = Scaled(stiffness_, damping_, state.parameters.coupling_factor);
  return spring.stiffness.cwiseProduct(k.strain) + spring.damping.cwiseProduct(k.jacobian * state.velocity);
}

double CouplingElement::DoPotentialEnergy(const ElementState& state) const {
  const Vec6 strain = Kinematics(state).strain;
  return 0.5 * state.parameters.coupling_factor * strain.dot(stiffness_.cwiseProduct(strain));
}

SupportElement::SupportElement(const Body* body, Index node, const Vec3& position, const Mat3& frame,
                               const Vec6& stiffness, const Vec6& damping, bool holds_bit)
    : ForceElement({body}), node_(node), stiffness_(stiffness), damping_(damping), holds_bit_(holds_bit) {
  ground_.r = ground_.reference = position;
  ground_.A = frame;
  // The body's node frame at rest is the body's reference frame; the support's rotational strain
  // vee(skew(frameᵀ A)) is measured from it, so the frame must be that reference orientation.
}

std::string SupportElement::Describe() const {
  return fmt::format("support at {:.4g} m from the bit",
                     bodies()[0]->NodeS(node_));
}

CouplingKinematics SupportElement::Kinematics(const ElementState& state) const {
  const CouplingEnd ground{nullptr, 0, ground_};
  const CouplingEnd end{bodies()[0], node_, *state.poses[0]};
  return ComputeCouplingKinematics(ground, end);
}

void SupportElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const ScaledSpring spring = Scaled(stiffness_, damping_, Factor(state));
  SpringContribution(Kinematics(state), spring.stiffness, spring.damping, state.velocity, with_matrices, out);
}

Vec6 SupportElement::Reaction(const ElementState& state) const {
  const CouplingKinematics k = Kinematics(state);
  const ScaledSpring spring = Scaled(stiffness_, damping_, Factor(state));
  return -(spring.stiffness.cwiseProduct(k.strain) + spring.damping.cwiseProduct(k.jacobian * state.velocity));
}

double SupportElement::DoPotentialEnergy(const ElementState& state) const {
  const Vec6 strain = Kinematics(state).strain;
  return 0.5 * Factor(state) * strain.dot(stiffness_.cwiseProduct(strain));
}

}  // namespace drillflex::model
