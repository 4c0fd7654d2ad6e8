// Applied dead loads on one body: a force and a moment at each node, fixed in the global frame and
// scaled by the load factor. Gravity (buoyed weight), distributed loads (as work-equivalent nodal
// forces and moments) and point loads of a body are all gathered into one element per body.
// Generalized force of a nodal force F and moment M (method.md §4, Q_e = Σ L_kᵀ (F_k, M_k)):
//   [F;  u_k × AᵀF + AᵀM;  Φ_kᵀ AᵀF + Ψ_kᵀ AᵀM].
//
// The axial force's gradient inside the body. The body's own geometric stiffness carries its mean
// axial force N̄ (model/body_dynamics.hpp); the axial components a_k = F_k · A e_x of the loads at
// its interior nodes make the force vary from element to element, N_e = N̄ + d_e with
// d_e = A_e − mean(A), A_e = Σ_{k>e} a_k (the loads above element e; elements are equal). Their
// geometric stiffness is the work of those loads through the nodes' axial shortening by the
// bending that the linear modes leave out: node k sits δ_k = −½∫₀^{x_k}(v′² + w′²) + (x_k/L)·½∫₀^L(…)
// lower than they place it (the end nodes are where they are), and −Σ a_k δ_k = ½ Σ_e d_e ηᵀ G_e η,
// G_e = U_eᵀ K_G,e U_e (cms::ReducedBody::element_modal_geometric_stiffness). So the element adds
//   V_g = ½ λ ηᵀ G_d(A) η,   G_d(A) = Σ_i (A e_x)_i Ĝ_i,   Ĝ_i = Σ_e d_e(F(i)) G_e,
// with its exact derivatives in η and in the frame's turn (a_k follows the body's axis). A column
// under its own weight then buckles at Greenhill's w L³/EI = 7.837 with few bodies (validation V2).
#pragma once

#include <vector>

#include "model/force_element.hpp"

namespace drillflex::model {

// The load group an element's loads belong to (LoadParameters): what scales them.
enum class LoadGroup {
  kWeight,       // the buoyed weight: load_factor × weight_factor
  kCaseLoads,    // the case's point and distributed loads: load_factor × case_load_factor
  kInitialLoads, // a transient's initial loads: load_factor × initial_load_factor
  kWeightOnBit,  // per newton of WOB: load_factor × (weight_on_bit, or the element's value)
  kTorqueOnBit,  // per N·m of torque on bit: load_factor × (torque_on_bit, or the element's value)
};

class NodalLoadElement : public ForceElement {
 public:
  // `value`: the WOB (N) or torque on bit (N·m) the case gives, for the groups whose loads are per
  // unit of it (kWeightOnBit, kTorqueOnBit); ignored by the others.
  NodalLoadElement(const Body* body, std::vector<Vec3> forces, std::vector<Vec3> moments,
                   LoadGroup group = LoadGroup::kCaseLoads, double value = 1.0);
  std::string Describe() const override;
  const std::vector<Vec3>& forces() const { return forces_; }
  LoadGroup group() const { return group_; }
  // What the element's forces and moments are multiplied by under `load`.
  double Scale(const LoadParameters& load) const;

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  // −λ Σ F_k · (r_k − r_k,ref) is path-dependent for the moments; only the forces' part is reported.
  double DoPotentialEnergy(const ElementState& state) const override;
  // −λ Σ (F_k · Δx_k + M_k · Δψ_k): the dead loads' work over a step, Δx_k and Δψ_k the node's move
  // and turn (model::NodeMoveBetween; the turn exact about a fixed axis, as a twist under the torque
  // on bit): its derivative along an increment is the residual's virtual work.
  double DoPotentialEnergyChange(const ElementState& from, const ElementState& to) const override;

 private:
  std::vector<Vec3> forces_;   // N, global, per node
  std::vector<Vec3> moments_;  // N·m, global, per node
  LoadGroup group_;
  double value_;  // kWeightOnBit, kTorqueOnBit: the case's value
  // The residual without the node loop (a string's residual evaluates every body's loads each
  // Newton iteration): the loads are fixed in the global frame, so with a = A's nine entries and
  // u_k = x_k + Φ_k η every sum is linear in a or bilinear in a and η:
  //   Σ F_k;   Σ u_k × AᵀF_k + AᵀM_k = H a + Σ_i (Σ_j A(j, i) p_j) × e_i + Aᵀ Σ M_k;   Σ Φ_kᵀ AᵀF_k + Ψ_kᵀ AᵀM_k = G a,
  // p_j = P_j η with P_j = Σ_k F_k(j) Φ_k; G, H and P_j summed over the nodes once, here.
  Vec3 force_sum_, moment_sum_;                          // Σ F_k, Σ M_k
  Eigen::Matrix<double, Eigen::Dynamic, 9> modal_by_rotation_;  // G, n_f × 9
  Eigen::Matrix<double, 3, 9> moment_by_rotation_;       // H: column j + 3i = Σ_k F_k(j) x_k × e_i
  Eigen::Matrix<double, 9, Eigen::Dynamic> offset_load_modes_;  // P_0; P_1; P_2 stacked, 9 × n_f
  // Ĝ_0, Ĝ_1, Ĝ_2 of the axial force's gradient (above), n_f × n_f each; empty without one.
  std::vector<MatX> gradient_by_axis_;
  double GradientEnergy(const BodyPose& pose, double load_factor) const;
};

// Work-equivalent nodal forces and moments of a uniform line load q (N/m, global) on a straight
// element from `start` to `end` (global positions): q h/2 at each end and ±(h²/12) t × q
// (t the unit axis): the fixed-end actions of a uniformly loaded beam.
void AddUniformLineLoad(const Vec3& start, const Vec3& end, const Vec3& load_per_length, Vec3& force_start,
                        Vec3& moment_start, Vec3& force_end, Vec3& moment_end);

}  // namespace drillflex::model
