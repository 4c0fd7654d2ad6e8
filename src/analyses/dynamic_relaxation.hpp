// Static equilibrium by dynamic relaxation (method.md §9.1: the paper's way, kept as the fallback
// and cross-check of Newton): the pseudo-dynamics M v̇ + C v + R(q) = 0 with R the static residual
// at load factor 1, artificial viscous damping C = 2 ζ ω₁ M (ζ = 1: critical for the lowest mode),
// integrated by a semi-implicit (linearly implicit) Euler step with the static tangent K(q):
//   (M/h + C + h K) v₁ = M v₀/h − R(q₀),   q₁ = q₀ ⊕ h v₁,
// h = 1/ω₁ (ω₁ the lowest elastic frequency at the start). The inertia terms' position
// derivatives are not needed (the pseudo-motion is slow; only M(q) enters). Stops when the
// pseudo-kinetic energy has decayed (|h v|∞ below the increment tolerance) and R is small.
#pragma once

#include "core/types.hpp"
#include "model/load_parameters.hpp"
#include "model/system_model.hpp"

namespace drillflex::analyses {

struct RelaxationOptions {
  int max_steps = 2000;
  double increment_tolerance = 1e-10;  // on |h v|∞ (units of v)
  double damping_ratio = 1.0;          // ζ of C = 2 ζ ω₁ M
};

struct RelaxationResult {
  VecX q;
  bool converged = false;
  int steps = 0;
  double residual_norm = 0.0;  // |R|₂ at q, N
  double kinetic_energy = 0.0; // ½ vᵀ M v of the last step, J
};

// Throws SolverError when it does not converge within max_steps.
RelaxationResult SolveByDynamicRelaxation(const model::SystemModel& model, const RelaxationOptions& options,
                                          const model::LoadParameters& parameters = 1.0);

}  // namespace drillflex::analyses
