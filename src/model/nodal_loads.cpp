#include "model/nodal_loads.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/node_kinematics.hpp"

namespace drillflex::model {

using so3::Skew;

NodalLoadElement::NodalLoadElement(const Body* body, std::vector<Vec3> forces, std::vector<Vec3> moments,
                                   LoadGroup group, double value)
    : ForceElement({body}), forces_(std::move(forces)), moments_(std::move(moments)), group_(group), value_(value) {
  if (std::ssize(forces_) != body->node_count() || std::ssize(moments_) != body->node_count()) {
    throw LogicError("NodalLoadElement: one force and one moment per node expected");
  }
  // The residual's node sums as products with A's entries (ResidualSums in the header), a = the
  // entries column by column: (AᵀF)_i = Σ_j A(j, i) F(j) = Σ_j a_{j+3i} F(j).
  const cms::ReducedBody& reduced = *body->reduced;
  const Index nf = body->flexible_count;
  force_sum_.setZero();
  moment_sum_.setZero();
  modal_by_rotation_.setZero(nf, 9);
  moment_by_rotation_.setZero();
  offset_load_modes_.setZero(9, nf);
  for (Index k = 0; k < body->node_count(); ++k) {
    const Vec3& force = forces_[k];
    const Vec3& moment = moments_[k];
    force_sum_ += force;
    moment_sum_ += moment;
    const auto& phi = reduced.node_translation_modes[k];
    const auto& psi = reduced.node_rotation_modes[k];
    const Vec3& position = reduced.node_positions[k];
    for (Index i = 0; i < 3; ++i) {
      for (Index j = 0; j < 3; ++j) {
        const Index c = j + 3 * i;
        modal_by_rotation_.col(c) += force(j) * phi.row(i).transpose() + moment(j) * psi.row(i).transpose();
        moment_by_rotation_.col(c) += force(j) * position.cross(Vec3::Unit(i));
      }
    }
    for (Index j = 0; j < 3; ++j) offset_load_modes_.middleRows<3>(3 * j) += force(j) * phi;
  }
  // Ĝ_i = Σ_e (A_e − mean A) G_e with A_e = Σ_{k>e} F_k(i) (header).
  const std::vector<MatX>& elements = reduced.element_modal_geometric_stiffness;
  const Index element_count = std::ssize(elements);
  if (element_count == body->node_count() - 1 && element_count > 1) {
    gradient_by_axis_.assign(3, MatX::Zero(nf, nf));
    for (Index i = 0; i < 3; ++i) {
      std::vector<double> above(element_count, 0.0);
      double sum = 0.0;
      for (Index e = element_count - 1; e >= 0; --e) {
        sum += forces_[e + 1](i);
        above[e] = sum;
      }
      double mean = 0.0;
      for (double value : above) mean += value / element_count;
      for (Index e = 0; e < element_count; ++e) gradient_by_axis_[i] += (above[e] - mean) * elements[e];
    }
    bool any = false;
    for (const MatX& g : gradient_by_axis_) any = any || !g.isZero(0.0);
    if (!any) gradient_by_axis_.clear();
  }
}

double NodalLoadElement::Scale(const LoadParameters& load) const {
  switch (group_) {
    case LoadGroup::kWeight: return load.load_factor * load.weight_factor;
    case LoadGroup::kCaseLoads: return load.load_factor * load.case_load_factor;
    case LoadGroup::kInitialLoads: return load.load_factor * load.initial_load_factor;
    case LoadGroup::kWeightOnBit: return load.load_factor * load.weight_on_bit.value_or(value_);
    case LoadGroup::kTorqueOnBit: return load.load_factor * load.torque_on_bit.value_or(value_);
  }
  return 0.0;
}

double NodalLoadElement::GradientEnergy(const BodyPose& pose, double load_factor) const {
  if (gradient_by_axis_.empty()) return 0.0;
  const Vec3 axis = pose.A.col(0);
  double energy = 0.0;
  for (Index i = 0; i < 3; ++i) energy += axis(i) * pose.eta.dot(gradient_by_axis_[i] * pose.eta);
  return 0.5 * load_factor * energy;
}

namespace {

// The gradient's part of the residual and its stiffness (NodalLoadElement header), c = A e_x:
//   η:  λ G_d η,   θ: ½ λ e_x × (Aᵀ g),  g_i = ηᵀ Ĝ_i η,  with δc = −A ẽ_x δθ, δ(Aᵀg) = skew(Aᵀg) δθ:
//   ηη: λ G_d,  ηθ: −λ P A ẽ_x,  θη: λ ẽ_x Aᵀ Pᵀ,  θθ: ½ λ ẽ_x skew(Aᵀ g),  P = [Ĝ_0η Ĝ_1η Ĝ_2η].
void AddAxialGradient(const std::vector<MatX>& by_axis, const BodyPose& pose, double lambda, bool with_matrices,
                      ElementContribution& out) {
  if (by_axis.empty()) return;
  const Index nf = pose.eta.size();
  const Vec3 axis = pose.A.col(0);
  Eigen::Matrix<double, Eigen::Dynamic, 3> products(nf, 3);  // P
  Vec3 squares;
  for (Index i = 0; i < 3; ++i) {
    products.col(i) = by_axis[i] * pose.eta;
    squares(i) = pose.eta.dot(products.col(i));
  }
  const Mat3 skew_x = Skew(Vec3::UnitX());
  const Vec3 body_squares = pose.A.transpose() * squares;
  out.force.tail(nf).noalias() += lambda * (products * axis);  // G_d η = P c
  out.force.segment<3>(3) += 0.5 * lambda * Vec3::UnitX().cross(body_squares);
  if (!with_matrices) return;
  auto eta_eta = out.stiffness.bottomRightCorner(nf, nf);
  for (Index i = 0; i < 3; ++i) eta_eta += (lambda * axis(i)) * by_axis[i];
  const MatX eta_theta = -lambda * products * pose.A * skew_x;
  out.stiffness.block(6, 3, nf, 3) += eta_theta;
  out.stiffness.block(3, 6, 3, nf) += eta_theta.transpose();
  out.stiffness.block<3, 3>(3, 3) += 0.5 * lambda * skew_x * Skew(body_squares);
}

}  // namespace

std::string NodalLoadElement::Describe() const {
  return fmt::format("loads on the body at {:.4g} m from the bit", bodies()[0]->s_start);
}

void NodalLoadElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const cms::ReducedBody& reduced = *body.reduced;
  const Index nf = body.flexible_count;
  const Index nodes = body.node_count();
  const double lambda = Scale(state.parameters);
  // Per node, in the body frame, F̂_k = AᵀF_k and M̂_k = AᵀM_k. The residual carries −f_ext:
  //   −λ (Σ F_k;  Σ u_k × F̂_k + M̂_k;  Σ Φ_kᵀ F̂_k + Ψ_kᵀ M̂_k),
  // the modal sum one product Uᵀ (F̂_k, M̂_k)_k with the mode shapes (6 rows a node). With
  // δ(AᵀF) = F̂̃ δθ and δu_k = Φ_k δη, the stiffness rows are
  //   θθ: −λ Σ (ũ_k F̂̃_k + M̂̃_k),  θη: λ Σ F̂̃_k Φ_k,  ηθ: −λ Σ (Φ_kᵀ F̂̃_k + Ψ_kᵀ M̂̃_k),
  // the last two products of the stacked skew matrices with U.
  if (!with_matrices) {
    // The node sums of the comment below by the products set up in the constructor: with
    // p_j = Σ_k F_k(j) Φ_k η, Σ_k (Φ_k η) × AᵀF_k = Σ_i (Σ_j A(j, i) p_j) × e_i.
    const Eigen::Map<const Eigen::Matrix<double, 9, 1>> a(pose.A.data());
    const Eigen::Matrix<double, 9, 1> p = offset_load_modes_ * pose.eta;
    const Mat3 elastic = Eigen::Map<const Mat3>(p.data()) * pose.A;  // column i: Σ_j A(j, i) p_j
    Vec3 moment = moment_by_rotation_ * a + pose.A.transpose() * moment_sum_;
    for (Index i = 0; i < 3; ++i) moment += elastic.col(i).cross(Vec3::Unit(i));
    out.force.head<3>() -= lambda * force_sum_;
    out.force.segment<3>(3) -= lambda * moment;
    out.force.tail(nf).noalias() -= lambda * (modal_by_rotation_ * a);
    AddAxialGradient(gradient_by_axis_, pose, lambda, false, out);
    return;
  }
  thread_local VecX nodal;
  thread_local Eigen::Matrix<double, Eigen::Dynamic, 3> skews;  // (F̂̃_k; M̂̃_k) per node
  nodal.setZero(6 * nodes);
  if (with_matrices) skews.setZero(6 * nodes, 3);
  Vec3 force_sum = Vec3::Zero(), moment_sum = Vec3::Zero();
  Mat3 rotation_rotation = Mat3::Zero();
  for (Index k = 0; k < nodes; ++k) {
    if (forces_[k].isZero(0.0) && moments_[k].isZero(0.0)) continue;
    const Vec3 offset = pose.NodeOffset(body, k);
    const Vec3 force_body = pose.A.transpose() * forces_[k];
    const Vec3 moment_body = pose.A.transpose() * moments_[k];
    nodal.segment<3>(6 * k) = force_body;
    nodal.segment<3>(6 * k + 3) = moment_body;
    force_sum += forces_[k];
    moment_sum += offset.cross(force_body) + moment_body;
    if (!with_matrices) continue;
    const Mat3 skew_f = Skew(force_body);
    const Mat3 skew_m = Skew(moment_body);
    rotation_rotation += Skew(offset) * skew_f + skew_m;
    skews.middleRows<3>(6 * k) = skew_f;
    skews.middleRows<3>(6 * k + 3) = skew_m;
  }
  out.force.head<3>() -= lambda * force_sum;
  out.force.segment<3>(3) -= lambda * moment_sum;
  out.force.tail(nf).noalias() -= lambda * (reduced.mode_shapes.transpose() * nodal);
  if (!with_matrices) return;
  out.stiffness.block<3, 3>(3, 3) -= lambda * rotation_rotation;
  out.stiffness.block(6, 3, nf, 3).noalias() -= lambda * reduced.mode_shapes.transpose().lazyProduct(skews);
  // θη: only the force rows (F̂̃_k, the translations Φ_k); F̂̃ᵀ = −F̂̃.
  for (Index k = 0; k < nodes; ++k) skews.middleRows<3>(6 * k + 3).setZero();
  out.stiffness.block(3, 6, 3, nf).noalias() -= lambda * skews.transpose().lazyProduct(reduced.mode_shapes);
  AddAxialGradient(gradient_by_axis_, pose, lambda, true, out);
}

double NodalLoadElement::DoPotentialEnergy(const ElementState& state) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  double energy = 0.0;
  for (Index k = 0; k < body.node_count(); ++k) {
    const Vec3 rest = NodeReferencePosition(body, k);
    energy -= Scale(state.parameters) * forces_[k].dot(pose.NodePosition(body, k) - rest);
  }
  return energy + GradientEnergy(pose, Scale(state.parameters));
}

double NodalLoadElement::DoPotentialEnergyChange(const ElementState& from, const ElementState& to) const {
  const Body& body = *bodies()[0];
  double change = 0.0;
  for (Index k = 0; k < body.node_count(); ++k) {
    if (forces_[k].isZero(0.0) && moments_[k].isZero(0.0)) continue;
    const NodeMove move = NodeMoveBetween(body, *from.poses[0], *to.poses[0], k);
    change -= forces_[k].dot(move.translation) + moments_[k].dot(move.rotation);
  }
  const double scale = Scale(to.parameters);
  return scale * change + GradientEnergy(*to.poses[0], scale) - GradientEnergy(*from.poses[0], scale);
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
