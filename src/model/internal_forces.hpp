// Internal forces along the string (stress resultants) from a state q, read from each body's FE
// model: the nodal displacements relative to the floating frame d = U η (cms::ReducedBody::
// mode_shapes, FE DOF order 6 k + d) and the element end forces f_e = (K_e + N K_G,e) d_e, with
// K_e the element stiffness rebuilt from the body's fe::BodySpec and N K_G,e the geometric
// stiffness of the body's mean membrane force N̄ (below): the P-delta part of the shear and end
// moments (in the body frame the shear includes N̄ times the element's slope).
//
// N̄ is the model's BodyAxialForce (model/body_dynamics.hpp), the force the body transmits
// along its axis. The body's rigid-body equations balance the external forces on the deformed
// geometry with it, so the body-end shear includes N̄ × chord slope and agrees with the coupling
// forces (tests/analyses/internal_forces_test.cpp).
//
// Sign convention: the internal force at a section is the force (and moment about the section's
// centre) that the part of the string ABOVE the section (larger s, toward the top) exerts on the
// part below. Components in the body frame (x along the body axis toward the top, y, z lateral;
// for a straight string without a well this is the string frame). So:
//   axial force N = F_x (tension positive), shears F_y, F_z, torque T = M_x, bending M_y, M_z.
// For an element from node a (lower) to node b (upper), f_e = K d_e is the force ON the element
// AT its nodes, so the section at b carries +f_e(b) and the section at a carries −f_e(a).
// At a node shared by two elements of a body the two sides differ by the external (and inertia)
// load applied at that node: the average of the two sides is reported. At a body's end node only
// one element side exists. At a joint between bodies the coupling force (CouplingElement::Force)
// is the exact internal force there (tests/analyses/internal_forces_test.cpp checks that the body
// ends agree with it).
#pragma once

#include <span>
#include <vector>

#include "core/types.hpp"
#include "model/load_parameters.hpp"
#include "model/builder.hpp"

namespace drillflex::model {

// Stress resultants at one section, body frame (see the sign convention above).
struct SectionForces {
  Vec3 force = Vec3::Zero();   // (N, V_y, V_z), N
  Vec3 moment = Vec3::Zero();  // (T, M_y, M_z), N·m

  double axial_force() const { return force.x(); }   // N, tension positive
  double torque() const { return moment.x(); }       // N·m
  double shear_force() const { return force.tail<2>().norm(); }     // N
  double bending_moment() const { return moment.tail<2>().norm(); }  // N·m
};

// Internal forces at every node of every body: result[b][k] for node k of body b. `load` scales
// the dead nodal loads (NodalLoadElement::Scale) used for the axial force inside a body (below).
//
// Axial force inside a body. (1) The mean: N̄ = BodyAxialForce, the membrane force
// rowᵀη + (EA/L) ½ ηᵀ K_G,ff η (elongation of the end nodes plus the foreshortening of bending;
// a bent body without axial load carries none). (2) The distribution: the body's modes rarely
// hold an axial interior mode (the lowest fixed-interface modes of a slender body are bending
// modes), so the FE axial force of U η is the same everywhere. The element axial forces are
// therefore // rebuilt from N̄ and the equilibrium of the dead axial nodal loads a_j (body frame):
// node j joins element j−1 (below) and j (above), so N_j = N_{j−1} − a_j, i.e.
// N_e = N̄ + c_e − mean(c), c_e = −Σ_{j=1..e} a_j: the static FE solution when N̄ is exact (it is
// for a uniform bar: linear elements are nodally exact). Axial loads of other elements (contact
// friction, fluid) and axial inertia inside a body are not resolved this way.
std::vector<std::vector<SectionForces>> ComputeInternalForces(const BuiltModel& built, const VecX& q,
                                                              const LoadParameters& load = 1.0);
// The same for the listed bodies only (result[b] empty for the others): what a transient run reads
// at its output times (the bit, the top, the probes) without the whole string.
std::vector<std::vector<SectionForces>> ComputeInternalForces(const BuiltModel& built, const VecX& q,
                                                              const LoadParameters& load, std::span<const Index> bodies);

// The internal forces of one body from its modal coordinates η (body frame); `axial_loads` are
// the dead axial nodal loads a_j (N, along the body axis), one per node, or empty.
std::vector<SectionForces> BodyInternalForces(const Body& body, const VecX& eta,
                                              const std::vector<double>& axial_loads = {});

// The raw FE end forces of element e (nodes e, e+1) of a body: f_e = (K_e + N̄ K_G,e) d_e,
// without the axial rebuild above; 12 values in the FE order (forces and moments on the element
// at node e, then at node e+1), body frame.
Eigen::Matrix<double, 12, 1> ElementEndForces(const Body& body, const VecX& eta, Index element);

// The internal force at each joint (size bodies − 1; joint j between body j and body j + 1):
// the coupling force f = K e + C ė (CouplingElement::Force) in the lower body's frame, which is
// the force the upper body exerts on the lower one. Throws LogicError if a joint has no coupling.
std::vector<SectionForces> JointInternalForces(const BuiltModel& built, const VecX& q, const VecX& v);
// The same for the listed joints only (the others left zero).
std::vector<SectionForces> JointInternalForces(const BuiltModel& built, const VecX& q, const VecX& v,
                                               std::span<const Index> joints);

}  // namespace drillflex::model
