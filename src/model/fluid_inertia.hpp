// The drilling fluid in the time domain (method.md §7): the bore fluid and the annulus's added mass
// move with a body sideways, and the annulus damps that motion, in the body's own equations of
// motion (a transient's model; model/builder.hpp ModelInput::transient_fluid_frequency). The linear
// analyses add the same lumps as matrices instead (model/lateral_fluid.hpp).
//
// The model: a point mass m_k and a dashpot c_k at each node k (Body::fluid_lateral_mass, _damping:
// the tributary lumps of lateral_fluid.hpp), acting across the body axis only. With the node's
// velocity in the body frame (method.md §4, model/node_kinematics.hpp)
//   t_k = Aᵀṙ + ω × u_k + Φ_k η̇ = J_k v,   J_k = [Aᵀ, −ũ_k, Φ_k],   u_k = ρ_k + Φ_k η,
// and Π = diag(0, 1, 1) the projection across the body's x axis, the fluid's kinetic energy is
//   T_f = ½ Σ m_k |Π t_k|²
// (a point mass has no rotary inertia, and |Π Aᵀ w| does not change when the frame spins about its
// own axis: the fluid does not turn with the pipe, it adds lateral translational inertia only; the
// axial motion of the string drags none of it). The body-frame lateral plane is the simple choice
// stated: the node's own small elastic tilt Ψ_k η is neglected against the frame's (the same as the
// linear analyses' J_lat). The equations are Lagrange's in the body's quasi-velocities
// (Euler–Poincaré for the frame rotation: d/dt ∂T/∂ω + ω × ∂T/∂ω − ∂T/∂θ), which work out as
//   R_f = Σ_k J_kᵀ F_k + [0; m_k t_k × Π t_k; 0],
//   F_k = m_k (Π ṫ_k + ω × Π t_k) + c_k Π t_k,
//   ṫ_k = J_k a + ω × Φ_k η̇ − ω × Aᵀṙ,
// so that vᵀ R_f = dT_f/dt + Σ c_k |Π t_k|² exactly: the fluid's kinetic energy is conserved with
// the rest, and the dashpots only dissipate. At rest (v = 0) the mass is M_f = Σ m_k J_kᵀ Π J_k, the
// linear analyses' matrix. (For an isotropic mass, Π = I, F_k would be the node's inertial force
// m_k × its body-frame acceleration and the extra moment would vanish: the body's own inertia.)
#pragma once

#include "model/body.hpp"

namespace drillflex::model {

// Whether the body carries fluid lumps.
inline bool HasLateralFluid(const Body& body) { return body.fluid_lateral_mass.size() > 0; }

// R_f(q, v, a) of the body, (6 + n_f): the fluid's inertial and damping forces.
VecX BodyFluidForces(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& acceleration);

// cK ∂R_f/∂q + cD ∂R_f/∂v + cM ∂R_f/∂a added into `matrix` ((6 + n_f)²); ∂/∂q along the increment
// (δr, δA = A skew(δθ), δη). Derivation in fluid_inertia.cpp; checked against central differences
// (tests/model/fluid_inertia_test.cpp).
void AddFluidMatrices(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& acceleration,
                      double cK, double cD, double cM, MatX& matrix);

// M_f(q) = Σ m_k J_kᵀ Π J_k, (6 + n_f)², kg.
MatX BodyFluidMassMatrix(const Body& body, const BodyPose& pose);

// T_f = ½ Σ m_k |Π t_k|², J.
double BodyFluidKineticEnergy(const Body& body, const BodyPose& pose, const VecX& velocity);

// The dashpots' power Σ c_k |Π t_k|² ≥ 0, W (the rate the fluid dissipates energy).
double BodyFluidDampingPower(const Body& body, const BodyPose& pose, const VecX& velocity);

}  // namespace drillflex::model
