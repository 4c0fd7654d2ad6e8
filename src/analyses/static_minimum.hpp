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

// `input` with a trajectory and a hole; `built` made from it, evaluated under `parameters` (the loads
// scaled or replaced: the buckling analysis's multiplier, the roadmap's WOB and friction; its
// sliding says whether the string moves). `start`, if given, replaces the resting start (a nearby
// equilibrium). Never throws on a failure to converge (see `failure`).
StaticMinimum SolveStaticMinimum(const model::ModelInput& input, const model::BuiltModel& built,
                                 const StaticSettings& settings, const model::LoadParameters& parameters = 1.0,
                                 const VecX* start = nullptr);

// A sliding string's equilibrium continued from its equilibrium at rest `at_rest` (the friction factor
// from 0 to 1 by Newton, static-solver.md §6), under `parameters`. Never throws on a failure to
// converge (see `failure`).
struct FrictionContinuation {
  VecX q;
  bool converged = false;
  int iterations = 0;
  double residual_norm = 0.0;
  std::string failure;
};
FrictionContinuation ContinueInFriction(const model::BuiltModel& built, const StaticSettings& settings,
                                        const model::LoadParameters& parameters, const VecX& at_rest);

// `input` with the values of `parameters` in it (the buoyed weight, WOB and torque on bit scaled or
// replaced, the friction coefficients, the sliding), for what reads the input rather than the model:
// the resting start's soft-string estimate and the twist under torque.
model::ModelInput EffectiveInput(const model::ModelInput& input, const model::LoadParameters& parameters);

// Whether the string moves against the wall under `parameters` (its friction has a prescribed
// direction): the case's static_sliding, or the block's own.
bool Slides(const model::ModelInput& input, const model::LoadParameters& parameters);

}  // namespace drillflex::analyses
