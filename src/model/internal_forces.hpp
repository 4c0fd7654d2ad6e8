// Internal forces along the string (stress resultants) from a state q, read from each body's FE
// model: the nodal displacements relative to the floating frame d = U η (cms::ReducedBody::
// mode_shapes, FE DOF order 6 k + d) and the element end forces f_e = (K_e + N K_G,e) d_e, with
// K_e the element stiffness rebuilt from the body's fe::BodySpec and N K_G,e the geometric
// stiffness of the body's mean axial force N = axial_force_rowᵀ η (the same term the model's
// modal geometric stiffness K_G,ff carries: the P-delta part of the shear and end moments).
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

#include <vector>

#include "core/types.hpp"
#include "model/system_model.hpp"

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

// Internal forces at every node of every body: result[b][k] for node k of body b.
std::vector<std::vector<SectionForces>> ComputeInternalForces(const SystemModel& model, const VecX& q);

// The internal forces of one body from its modal coordinates η (body frame).
std::vector<SectionForces> BodyInternalForces(const Body& body, const VecX& eta);

// The end forces of element e (nodes e, e+1) of a body: f_e = (K_e + N K_G,e) d_e, 12 values in
// the FE order (forces and moments on the element at node e, then at node e+1), body frame.
Eigen::Matrix<double, 12, 1> ElementEndForces(const Body& body, const VecX& eta, int element);

}  // namespace drillflex::model
