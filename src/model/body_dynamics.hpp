// The floating-frame equations of one flexible body (method.md §4), in the body's velocity
// coordinates v_b = (ṙ global, ω body frame, η̇):
//   M(q) v̇ + Q_v(q, v) + [0, 0, K_ff η + D_ff η̇ + geometric stiffening] = Q_e.
// Inertia is the node sum of method.md §4 with the body-frame node velocity
//   v_k = Aᵀṙ + ω × u_k + Φ_k η̇ (translation), ω_k = ω + Ψ_k η̇ (rotation),
// plus the constant correction that makes the mass exact for a consistent FE mass at η = 0
// (cms/reduced_body.hpp). External forces are added by force elements.
#pragma once

#include "model/body.hpp"

namespace drillflex::model {

// M(q), (6 + n_f)², symmetric positive definite.
MatX BodyMassMatrix(const Body& body, const BodyPose& pose);

// Q_v(q, v): the velocity-quadratic (centrifugal, Coriolis, gyroscopic) inertia forces,
// Σ_k L_kᵀ M_k (ω×(ω×u_k) + 2 ω×Φ_k η̇) + Ψ_kᵀ-mapped (ω_k × J_k ω_k).
VecX BodyVelocityForces(const Body& body, const BodyPose& pose, const VecX& velocity);

// The body's mean axial force N = axial_force_rowᵀ η + ½ (EA/L) ηᵀ K_G,ff η, N (tension positive):
// the elongation of the end nodes plus the foreshortening of the bending.
double BodyAxialForce(const Body& body, const BodyPose& pose);

// The body's torque T = torque_rowᵀ η + ½ (GJ/L) ηᵀ K_T,ff η, N·m: the twist of the end nodes plus
// the twist of the bending (fe/beam_element.hpp ElementTorqueGeometricStiffness).
double BodyTorque(const Body& body, const BodyPose& pose);

// Elastic and modal damping forces on the modal rows, from the potential
//   V = ½ ηᵀ K_ff η + ½ N_lin ηᵀ G η + (EA/8L) (ηᵀ G η)² + ½ T_lin ηᵀ G_T η + (GJ/8L) (ηᵀ G_T η)²,
// G = K_G,ff, N_lin = axial rowᵀη, G_T = K_T,ff, T_lin = torque rowᵀη: the energy of the mean
// axial strain (Δu + ½ηᵀGη)/L (geometric stiffness of the body's own axial force, with the
// foreshortening that keeps a free bent body free of axial force) and of the mean twist
// (Δθx + ½ηᵀG_Tη)/L (the torque's geometric stiffness: Greenhill's buckling under torque)
// plus D_ff η̇. Added into `residual` (size 6 + n_f).
void AddElasticForces(const Body& body, const BodyPose& pose, const VecX& velocity, VecX& residual);

// cK ∂/∂q + cD ∂/∂v of the elastic forces, added into `matrix` ((6 + n_f)²).
void AddElasticMatrices(const Body& body, const BodyPose& pose, double cK, double cD, MatX& matrix);

// V above, J.
double BodyElasticEnergy(const Body& body, const BodyPose& pose);

// ½ vᵀ M(q) v, J.
double BodyKineticEnergy(const Body& body, const BodyPose& pose, const VecX& velocity);

}  // namespace drillflex::model
