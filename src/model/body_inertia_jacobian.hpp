// Exact derivatives of a body's inertial residual R_in = M(q) a + Q_v(q, v) (model/body_dynamics.hpp):
//   K_in = ∂R_in/∂(position increment) with δr, δA = A skew(δθ), δη   (the tangent of q ⊕ dv),
//   D_in = ∂R_in/∂v,  and  M = ∂R_in/∂a.
//
// Derivation (analytic; checked against central differences in tests/model/inertia_test.cpp).
// Write W = diag(Aᵀ, I, I), the body-frame accelerations α = W a = (Aᵀ r̈, ω̇, η̈) and the body-frame
// residual G = (M̂(η) + C) α + Q̂(η, ω, η̇), so that R_in = Wᵀ G. Here M̂ is the node sum in the
// body-frame velocities w = (Aᵀṙ, ω, η̇), C = body.mass_correction (constant; its velocity-quadratic
// terms are neglected, as in BodyVelocityForces) and Q̂ = W Q_v, which depends on neither A nor ṙ.
// Per node k: u_k = ρ_k + Φ_k η, translational inertial force (body frame)
//   f_k = M_k (a_k + c_k),  a_k = α_t + α_ω × u_k + Φ_k α_η,  c_k = ω×(ω×u_k) + 2 ω×(Φ_k η̇),
// mapped by L̂_kᵀ = [I; ũ_k; Φ_kᵀ], and the gyroscopic moment g_k = Ω_k × J_k Ω_k, Ω_k = ω + Ψ_k η̇,
// mapped by [0; I; Ψ_kᵀ]. Then
//   δθ:  δ(A G_t) = −A skew(G_t) δθ and δα_t = skew(α_t) δθ, so
//        K[:, θ] = Wᵀ (M̂ + C)[:, t] skew(α_t) − [A skew(G_t); 0; 0]
//   δη:  δu_k = Φ_k δη, δ(a_k + c_k) = (skew(α_ω) + skew(ω)²) Φ_k δη, δ(ũ_k f_k) = ũ_k δf_k − f̃_k Φ_k δη
//   ω:   ∂c_k/∂ω = −skew(ω × u_k) − skew(ω) skew(u_k) − 2 skew(Φ_k η̇),  ∂c_k/∂η̇ = 2 skew(ω) Φ_k,
//        ∂g_k/∂Ω_k = skew(Ω_k) J_k − skew(J_k Ω_k);  nothing depends on r or ṙ.
#pragma once

#include "model/body.hpp"

namespace drillflex::model {

// R_in = M(q) a + Q_v(q, v) of one body, (6 + n_f).
VecX BodyInertialForces(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& acceleration);

struct InertiaJacobians {
  MatX stiffness;  // K_in, (6 + n_f)²
  MatX damping;    // D_in, (6 + n_f)²
};

// K_in and D_in at (q, v, a).
InertiaJacobians BodyInertiaJacobians(const Body& body, const BodyPose& pose, const VecX& velocity,
                                      const VecX& acceleration);

// Adds cK·K_in + cD·D_in + cM·M into `matrix` ((6 + n_f)²); skips the parts that vanish (K_in at rest,
// D_in at zero velocity).
void AddInertiaMatrices(const Body& body, const BodyPose& pose, const VecX& velocity, const VecX& acceleration,
                        double cK, double cD, double cM, MatX& matrix);

}  // namespace drillflex::model
