#include "model/nodal_loads.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/so3.hpp"

namespace drillflex::model {

using so3::Skew;

NodalLoadElement::NodalLoadElement(const Body* body, std::vector<Vec3> forces, std::vector<Vec3> moments)
    : ForceElement({body}), forces_(std::move(forces)), moments_(std::move(moments)) {
  if (static_cast<int>(forces_.size()) != body->node_count() ||
      static_cast<int>(moments_.size()) != body->node_count()) {
    throw LogicError("NodalLoadElement: one force and one moment per node expected");
  }
}

std::string NodalLoadElement::Describe() const {
  return fmt::format("loads on the body at {:.4g} m from the bit", bodies()[0]->s_start);
}

void NodalLoadElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const int nf = body.flexible_count;
  const double lambda = state.load_factor;
  for (int k = 0; k < body.node_count(); ++k) {
    if (forces_[k].isZero(0.0) && moments_[k].isZero(0.0)) continue;
    const Vec3 offset = pose.NodeOffset(body, k);
    const Vec3 force_body = pose.A.transpose() * forces_[k];
    const Vec3 moment_body = pose.A.transpose() * moments_[k];
    const auto& phi = body.reduced->node_translation_modes[k];
    const auto& psi = body.reduced->node_rotation_modes[k];
    // Residual carries −f_ext.
    out.force.head<3>() -= lambda * forces_[k];
    out.force.segment<3>(3) -= lambda * (offset.cross(force_body) + moment_body);
    out.force.tail(nf).noalias() -= lambda * (phi.transpose() * force_body + psi.transpose() * moment_body);
    if (!with_matrices) continue;
    // δ(AᵀF) = skew(AᵀF) δθ; δu = Φ δη.
    const Mat3 skew_f = Skew(force_body);
    const Mat3 skew_m = Skew(moment_body);
    out.stiffness.block<3, 3>(3, 3) -= lambda * (Skew(offset) * skew_f + skew_m);
    out.stiffness.block(3, 6, 3, nf) -= lambda * (-skew_f * phi);
    out.stiffness.block(6, 3, nf, 3) -= lambda * (phi.transpose() * skew_f + psi.transpose() * skew_m);
  }
}

double NodalLoadElement::DoPotentialEnergy(const ElementState& state) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const Mat3 reference = body.reference_orientation.toRotationMatrix();
  double energy = 0.0;
  for (int k = 0; k < body.node_count(); ++k) {
    const Vec3 rest = body.reference_position + reference * body.reduced->node_positions[k];
    energy -= state.load_factor * forces_[k].dot(pose.NodePosition(body, k) - rest);
  }
  return energy;
}

void AddUniformLineLoad(const Vec3& start, const Vec3& end, const Vec3& load_per_length, Vec3& force_start,
                        Vec3& moment_start, Vec3& force_end, Vec3& moment_end) {
  const Vec3 axis = end - start;
  const double length = axis.norm();
  const Vec3 tangent = axis / length;
  force_start += 0.5 * length * load_per_length;
  force_end += 0.5 * length * load_per_length;
  const Vec3 fixed_end_moment = (length * length / 12.0) * tangent.cross(load_per_length);
  moment_start += fixed_end_moment;
  moment_end -= fixed_end_moment;
}

}  // namespace drillflex::model
