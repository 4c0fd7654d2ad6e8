// The stationary-frame gyroscopic moments of a spinning body (formulas in gyroscopic_element.hpp).
#include "model/gyroscopic_element.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/so3.hpp"

namespace drillflex::model {

using so3::Skew;

GyroscopicElement::GyroscopicElement(const Body* body, double spin) : ForceElement({body}), spin_(spin) {
  if (body == nullptr) throw LogicError("GyroscopicElement: no body");
  if (!std::isfinite(spin)) throw LogicError("GyroscopicElement: the spin rate must be finite");
}

std::string GyroscopicElement::Describe() const {
  return fmt::format("gyroscopic moments of the body at {:.4g} m spinning at {:.4g} rad/s", bodies()[0]->s_start, spin_);
}

void GyroscopicElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& body = *bodies()[0];
  const cms::ReducedBody& reduced = *body.reduced;
  const BodyPose& pose = *state.poses[0];
  const Index nf = body.flexible_count;
  const Vec3 axis = Vec3::UnitX();
  const Vec3 omega = state.velocity.segment<3>(3);
  const auto eta_rate = state.velocity.tail(nf);
  for (Index k = 0; k < reduced.node_count(); ++k) {
    const Eigen::Matrix<double, 3, Eigen::Dynamic>& psi = reduced.node_rotation_modes[k];
    const double polar = spin_ * reduced.node_rotary_inertia[k](0, 0);  // Ω J_p,k
    if (polar == 0.0) continue;
    const Vec3 e = axis + (psi * pose.eta).cross(axis);  // e_k = e_x + θ_k × e_x
    const Vec3 w = omega + psi * eta_rate;                // w_k = ω + Ψ_k η̇
    const Vec3 moment = polar * e.cross(w);               // m_k = Ω J_p (e_k × w_k)
    out.force.segment<3>(3) += moment;
    out.force.tail(nf).noalias() += psi.transpose() * moment;
    if (!with_matrices) continue;
    // ∂m/∂w = Ω J_p skew(e_k) on [0, I, Ψ_k]; ∂m/∂η = Ω J_p skew(w_k) skew(e_x) Ψ_k (through e_k).
    const Mat3 rate = polar * Skew(e);
    const Eigen::Matrix<double, 3, Eigen::Dynamic> rate_psi = rate * psi;
    out.damping.block<3, 3>(3, 3) += rate;
    out.damping.block(3, 6, 3, nf) += rate_psi;
    out.damping.block(6, 3, nf, 3).noalias() += psi.transpose() * rate;
    out.damping.block(6, 6, nf, nf).noalias() += psi.transpose() * rate_psi;
    const Eigen::Matrix<double, 3, Eigen::Dynamic> tilt = (polar * Skew(w) * Skew(axis)) * psi;
    out.stiffness.block(3, 6, 3, nf) += tilt;
    out.stiffness.block(6, 6, nf, nf).noalias() += psi.transpose() * tilt;
  }
}

SparseMat ComputeGyroscopicMatrix(const SystemModel& model, const VecX& q) {
  const std::vector<BodyPose> poses = model.Poses(q);
  std::vector<Eigen::Triplet<double>> triplets;
  for (Index b = 0; b < std::ssize(model.bodies()); ++b) {
    const Body& body = model.bodies()[b];
    const GyroscopicElement element(&body, 1.0);
    ElementState state;
    state.poses = {&poses[b]};
    state.velocity = VecX::Zero(body.velocity_count());
    ElementContribution contribution;
    element.Evaluate(state, true, contribution);
    const MatX& block = contribution.damping;
    for (Eigen::Index c = 0; c < block.cols(); ++c) {
      for (Eigen::Index r = 0; r < block.rows(); ++r) {
        if (block(r, c) != 0.0) triplets.emplace_back(body.v_offset + r, body.v_offset + c, block(r, c));
      }
    }
  }
  SparseMat gyroscopic(model.num_velocities(), model.num_velocities());
  gyroscopic.setFromTriplets(triplets.begin(), triplets.end());
  return gyroscopic;
}

}  // namespace drillflex::model
