// A flexible body of the system: its reduced model (shared between identical bodies), where it
// sits in the string and in the coordinate vectors, and the section data its force elements need.
//
// Coordinates of a body (method.md §4): positions q_b = [r − reference_position (3, global: the
// frame's displacement, so that a 2e12 N/m coupling 3 km from the origin is not rounded to ~1 N), unit quaternion (4:
// w, x, y, z) of the frame orientation A, modal coordinates η (n_f)]; velocities and position
// increments v_b = [ṙ (3, global), ω (3, body frame), η̇ (n_f)]. The increment of the rotation is
// q ⊕ Δθ = q · exp(Δθ/2) with Δθ in the body frame, so δA = A skew(δθ).
#pragma once

#include <memory>

#include "cms/reduced_body.hpp"
#include "core/types.hpp"

namespace drillflex::model {

struct Body {
  std::shared_ptr<const cms::ReducedBody> reduced;
  Index component = 0;          // index of the string component it was cut from
  double s_start = 0.0;       // distance of node 0 from the bit end, m
  Vec3 reference_position = Vec3::Zero();   // r of the undeformed placement, m
  Quat reference_orientation = Quat::Identity();
  Index q_offset = 0;           // first position coordinate in the system's q
  Index v_offset = 0;           // first velocity coordinate in the system's v
  Index flexible_count = 0;     // n_f

  // Section data (SI) for couplings, contact and internal forces.
  double axial_rigidity = 0.0;    // EA, N
  double bending_rigidity = 0.0;  // EI, N·m²
  double torsional_rigidity = 0.0;  // GJ, N·m²
  double element_length = 0.0;    // ℓ of the body's FE mesh, m
  double outer_diameter = 0.0;    // m
  double contact_diameter = 0.0;  // m: blade, joint or body OD

  // The body's mean axial force is N = axial_force_rowᵀ η (tension positive): EA/L times the
  // elongation between the end nodes, u_x(L) − u_x(0), read from the translational mode rows.
  VecX axial_force_row;
  // Likewise its torque T = torque_rowᵀ η (the linear part): GJ/L times the twist between the end
  // nodes, θx(L) − θx(0), read from the rotational mode rows (model/body_dynamics.hpp adds the
  // twist of bending).
  VecX torque_row;
  // ReferenceMassMatrix − NodalReferenceMassMatrix (cms/reduced_body.hpp): the constant
  // correction that makes the node-sum mass exact for a consistent FE mass at η = 0.
  MatX mass_correction;
  // The mass in the body-frame velocities (Aᵀṙ, ω, η̇) at η = 0: the node sum there
  // (cms::NodalReferenceMassMatrix) plus mass_correction, i.e. cms::ReferenceMassMatrix.
  // (6 + n_f)², kg, kg·m, kg·m². Whoever changes the node masses recomputes it.
  MatX reference_mass;
  // The drilling fluid that moves with the body sideways in a transient (model/fluid_inertia.hpp):
  // per node, the lateral mass (bore fluid plus the annulus's added mass), kg, and the annulus's
  // damping, N·s/m. Empty: none (the static and linear analyses add the fluid themselves).
  VecX fluid_lateral_mass, fluid_lateral_damping;

  double length() const { return reduced->length; }
  Index velocity_count() const { return 6 + flexible_count; }
  Index position_count() const { return 7 + flexible_count; }
  Index node_count() const { return reduced->node_count(); }
  // Node k's distance from the bit end along the undeformed string, m.
  double NodeS(Index k) const { return s_start + reduced->node_positions[k].x(); }
};

// The pose of a body read from the system's positions.
struct BodyPose {
  Vec3 r = Vec3::Zero();  // the frame's origin, m: reference + displacement
  // r split as q stores it: the body's reference position and the frame's displacement from it
  // (q holds the displacement). Differences of two frames' r are formed from these parts, so that
  // frames kilometres from the origin do not round a coupling's gap to 4.5e-13 m (~1 N at 2e12 N/m).
  Vec3 reference = Vec3::Zero();
  Vec3 displacement = Vec3::Zero();
  Quat rotation = Quat::Identity();
  Mat3 A = Mat3::Identity();  // body frame -> global
  VecX eta;

  // u_k = ρ_k + Φ_k η: node k's position in the body frame, m.
  Vec3 NodeOffset(const Body& body, Index node) const;
  // r_k = r + A u_k, m.
  Vec3 NodePosition(const Body& body, Index node) const;
  // θ_k = Ψ_k η: node k's small elastic rotation in the body frame, rad.
  Vec3 NodeRotation(const Body& body, Index node) const;
};

BodyPose PoseOf(const Body& body, const VecX& q);

// How node k moved between two poses of its body, global: `translation` from the frames'
// displacements (not their absolute origins, kilometres away: a move of 1e-7 m would keep six
// digits), m; `rotation` the frame's turn log(A_to A_fromᵀ) plus the node's small elastic turn
// Ψ_k Δη taken to global by the mean of the two frames, rad. Along an increment, the virtual
// displacement and rotation the residual maps a nodal force and moment through.
struct NodeMove {
  Vec3 translation = Vec3::Zero();
  Vec3 rotation = Vec3::Zero();
};
NodeMove NodeMoveBetween(const Body& body, const BodyPose& from, const BodyPose& to, Index node);

// Writes the undeformed placement of the body into q (η = 0).
void SetReferencePose(const Body& body, VecX& q);

// Turns the body's frame about its own x axis (the string axis) by `angle` (rad) and re-expresses
// its elastic coordinates so that the deformed shape stays where it is in space: A ← A Rx(angle),
// η ← the least-squares fit of [Φ_k; Ψ_k] η' = Rx(−angle) [Φ_k; Ψ_k] η over all nodes (exact when the
// modes span bending in both planes alike, as for a round section). Nodes on the x axis do not
// move, so the rest of the string is unaffected except through the twist itself.
// `twist_rate` (rad/m) adds an elastic twist that grows along the body from its middle node
// position: θ_x,k += twist_rate (x_k − x_mid), the torsion a body carrying a torque T has inside
// it (twist_rate = ±T/GJ), so that the couplings at its ends are not left to carry the whole turn
// between neighbouring bodies.
void TwistKeepingShape(const Body& body, double angle, VecX& q, double twist_rate = 0.0);

}  // namespace drillflex::model
