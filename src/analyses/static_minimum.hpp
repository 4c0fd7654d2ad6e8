// The static equilibrium of a string in a well as the stable minimum of its total potential energy
// (../shared/spec/static-solver.md; solvers/energy_trust_region.hpp), from the string resting on
// the wall (analyses/resting_start.hpp) and twisted by the torque on bit.
//
// The string that does not rotate is conservative (weights, WOB, the torque on bit as a dead
// moment, the wall's compliance ½ k δ²): its equilibrium is found by the energy trust region at the
// case's coupling stiffness, in one solve, and only a stable one is an answer (a straight string
// compressed beyond its buckling load is left along its direction of negative curvature onto the
// wall). A rotating string's friction acts around it and has no energy: its equilibrium is continued
// from the non-rotating minimum by Newton in the friction (static-solver.md §6).
#pragma once

#include <string>

#include "analyses/analysis_settings.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

struct StaticMinimum {
  VecX q;
  bool converged = false;
  int iterations = 0;          // trust-region iterations (+ Newton iterations of the friction continuation)
  int factorizations = 0;
  int negative_curvature_steps = 0;
  double residual_norm = 0.0;  // |R|₂ at q, N
  std::string failure;         // why it did not converge
  // A rotating string whose friction continuation did not reach the full friction: q is then the
  // equilibrium at rest (converged), and `failure` says how far the friction got.
  bool at_rest_only = false;
};

// `input` with a trajectory and a hole and no case supports; `built` made from it. The loads are
// load_scale × the case's (the buckling analysis); `start`, if given, replaces the resting start (a
// nearby equilibrium). Never throws on a failure to converge (see `failure`).
StaticMinimum SolveStaticMinimum(const model::ModelInput& input, const model::BuiltModel& built,
                                 const StaticSettings& settings, double load_scale = 1.0,
                                 const VecX* start = nullptr);

}  // namespace drillflex::analyses
