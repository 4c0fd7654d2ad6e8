// A flexible body after Craig–Bampton reduction (method.md §3 step 7): plain data for the
// floating-frame equations of method.md §4. Body frame: x along the axis, origin at node 0.
//
// Mass representation — a design note.
// The floating-frame equations sum over nodes: M = Σ_k L_kᵀ diag(M_k, J_k) L_k with
// L_k = [I, −A ũ_k, A Φ_k; 0, I, Ψ_k]. That node sum is exact only for a lumped FE mass. With a
// consistent FE mass (which converges O(h⁴) instead of O(h²): tests/fe/body_fe_model_test.cpp),
// the modes U come from UᵀMU = I with the consistent M, and the node sum of the same modes gives a
// slightly different (lumped) flexible mass and a non-zero rigid–flexible coupling.
// This struct therefore carries BOTH:
//  * the lumped nodal data (M_k, J_k) together with Φ_k, Ψ_k: what the node sum needs for the
//    velocity-dependent (centrifugal, Coriolis, gyroscopic) terms and for mapping nodal forces;
//  * the exact small-deformation inertia from the very FE mass M that produced U:
//    rigid_mass = Rᵀ M R, rigid_flexible_mass = Rᵀ M U (zero to round-off: U is M-orthogonal to
//    the rigid fields R, the Tisserand frame of method.md §3.6), modal_mass = Uᵀ M U (= I).
//    ReferenceMassMatrix() assembles them into the (6 + n_f)² mass at η = 0, A = I.
// A downstream that wants the consistent accuracy with the node-sum machinery adds the constant
// correction ReferenceMassMatrix() − NodalReferenceMassMatrix() (body-frame velocities; the
// translational rows/columns rotate with A). For a lumped FE mass the correction is zero.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "fe/body_fe_model.hpp"

namespace drillflex::cms {

using Matrix3X = Eigen::Matrix<double, 3, Eigen::Dynamic>;
using Matrix6X = Eigen::Matrix<double, 6, Eigen::Dynamic>;

struct ReducedBody {
  fe::BodySpec spec;                   // what was reduced (element matrices can be rebuilt from it)
  double length = 0.0;                 // m
  Index fixed_interface_mode_count = 0;  // H (modes_per_body, one more to complete a cut pair)
  Index flexible_count = 0;              // n_f = 6 n_interface − 6 + H (6 + H for two end nodes)
  std::vector<Index> interface_nodes;    // node indices used as the Craig–Bampton interface
  double structural_damping = 0.0;     // ζ_s

  // Per node k (body frame):
  std::vector<Vec3> node_positions;              // ρ_k = (x_k, 0, 0), m
  std::vector<double> node_mass;                 // structural lumped mass m_k (isotropic), kg
  std::vector<double> node_lateral_mass;         // fluid lumped mass, moves in y and z only, kg (the FE route;
                                                 // a string's model carries its fluid as Body::fluid_lateral_mass)
  std::vector<Mat3> node_rotary_inertia;         // J_k about the node, kg·m²
  std::vector<Matrix3X> node_translation_modes;  // Φ_k: rows (u, v, w) of U, m per unit η
  std::vector<Matrix3X> node_rotation_modes;     // Ψ_k: rows (θx, θy, θz) of U, rad per unit η

  MatX mode_shapes;                // U, N × n_f (FE DOF order 6 k + d)
  VecX natural_frequencies;        // ω_j of the free-free reduced body, ascending, rad/s
  MatX modal_stiffness;            // K_ff = diag(ω_j²) (Uᵀ K U to round-off), N·m / (kg·m²)
  MatX modal_damping;              // D_ff = diag(2 ζ_s ω_j)
  MatX modal_mass;                 // M_ff = Uᵀ M U with the reduction's own M (identity)
  MatX modal_geometric_stiffness;  // K_G,ff = Uᵀ K_G U per unit axial force (tension +), 1/m
  MatX modal_torque_geometric_stiffness;  // K_T,ff = Uᵀ K_T U per unit torque (fe/beam_element.hpp)
  // U_eᵀ K_G,e U_e of each element e (U_e the rows of its two nodes): Σ_e = K_G,ff. An axial force
  // that varies along the body weights them one by one (model/nodal_loads.hpp).
  std::vector<MatX> element_modal_geometric_stiffness;
  // The body's shape turned about its x axis, in modal coordinates: a nodal field turned by φ,
  // R_x(φ) = E_x + cos φ E_⊥ + sin φ S (S u = e_x × u on each node's translation and rotation, E_⊥
  // the projection across x), is η ↦ G(φ) η = η − (1 − cos φ) P_⊥ η + sin φ J η, with
  // J = Uᵀ M S U and P_⊥ = Uᵀ M E_⊥ U (the mass-weighted projections; Uᵀ M U = I). Exact when the
  // modes span a subspace closed under the turn (an axisymmetric body with both modes of each
  // bending pair kept).
  MatX twist_generator;        // J, n_f × n_f
  MatX transverse_projection;  // P_⊥, n_f × n_f

  // Consistent inertia at η = 0 from the reduction's mass M. Rigid coordinates (t, θ): node k
  // moves by t + θ × ρ_k and rotates by θ (fe::RigidBodyFields), about the body origin.
  Eigen::Matrix<double, 6, 6> rigid_mass = Eigen::Matrix<double, 6, 6>::Zero();  // Rᵀ M R
  Matrix6X rigid_flexible_mass;                                                  // Rᵀ M U ≈ 0

  // The undeformed structural body (continuum values, fluid excluded): mass ρAL, centre (L/2,0,0),
  // inertia about the centre diag(ρJL, ρIL + mL²/12, ρIL + mL²/12).
  double total_mass = 0.0;                   // kg
  Vec3 center_of_mass = Vec3::Zero();        // m
  Mat3 inertia_about_center = Mat3::Zero();  // kg·m²

  Index node_count() const { return std::ssize(node_positions); }
  // diag(m_k, m_k + m_lat,k, m_k + m_lat,k): node k's translational mass in the body frame.
  Mat3 NodeTranslationalMass(Index node) const;
};

// Σ_k L_kᵀ diag(M_k, J_k) L_k at η = 0 and A = I in the velocities (ṙ, ω, η̇): the node-sum mass
// of method.md §4 evaluated on the nodal data. (6 + n_f)².
MatX NodalReferenceMassMatrix(const ReducedBody& body);

// [R U]ᵀ M [R U] from rigid_mass, rigid_flexible_mass and modal_mass: the exact mass at η = 0.
MatX ReferenceMassMatrix(const ReducedBody& body);

}  // namespace drillflex::cms
