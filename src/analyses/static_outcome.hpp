// The static equilibrium as the chain of strategies found it (analyses/static_solve.hpp): the solver's
// solution (solvers::StaticSolution: the state, converged, iterations, load steps, |R|) and what the
// chain adds. The static analysis's result (analyses/static_analysis.hpp StaticResult) extends it with
// the quantities derived from the state.
#pragma once

#include <string>
#include <vector>

#include "solvers/newton.hpp"

namespace drillflex::analyses {

struct StaticOutcome : solvers::StaticSolution {
  // Iterations here count the Newton / trust-region iterations, or relaxation steps, of every strategy tried.
  bool stable = false;  // checked by the energy minimum: the tangent stiffness has no negative eigenvalue
  // How the equilibrium was found (results.json `static.method_used`): "continuation" (Newton from a
  // neighbouring equilibrium), "energy-minimum" (the energy trust region from the resting start),
  // "energy-minimum+friction" (then continued in the sliding friction), "newton" (load stepping),
  // "dynamic-relaxation".
  std::string method;
  std::string failure;  // why no strategy converged (empty when one did)
  // What the engineer must know about the answer (a fallback that was needed, a rotating string
  // answered at rest), in words; also in results.json (`static.warnings`).
  std::vector<std::string> warnings;
};

}  // namespace drillflex::analyses
