// The linear analyses' matrices about a state q (v = a = 0), in one place: the modes, the vibration
// (analyses/response_solver.hpp), the buckling, the gyroscopic modes and the dynamic relaxation all
// start from Linearize. The drilling fluid's lateral mass and damping are not in them (they depend on
// the frequency: model/lateral_fluid.hpp adds them), nor the gyroscopic matrix G of a spinning string
// (model/gyroscopic_element.hpp ComputeGyroscopicMatrix, per unit spin: the gyroscopic modes add Ω G
// to D).
#pragma once

#include "core/types.hpp"
#include "model/load_parameters.hpp"
#include "model/system_model.hpp"

namespace drillflex::analyses {

// The linearized matrices at q (v = a = 0): K = ∂R/∂q at the load factor, symmetrized
// ½(K + Kᵀ) (the tangent of dead moments and of the rotation parametrization is slightly
// unsymmetric away from equilibrium), M(q) (the steel; the fluid is added by the analyses) and
// D = ∂R/∂v (modal structural damping of the bodies, coupling, support and contact damping).
struct LinearizedSystem {
  SparseMat stiffness;
  SparseMat mass;
  SparseMat damping;
};

// `load`: a bare number is the load factor (model::LoadParameters). The stiffness is taken with the
// wall friction off and its velocity derivative about the static's sliding kept in the damping
// (docs/method.md "The friction of a rotating string, linearized").
LinearizedSystem Linearize(const model::SystemModel& model, const VecX& q, model::LoadParameters load);

}  // namespace drillflex::analyses
