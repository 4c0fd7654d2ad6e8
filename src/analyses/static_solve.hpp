// The static equilibrium of a built model under a parameter block (model/load_parameters.hpp): one
// chain of strategies, each returning its outcome (none throws to say it did not converge):
//
//   1. From a nearby equilibrium, when the caller has one (a roadmap's neighbouring run: the same
//      depth at another friction factor or motion, the previous depth shifted along the hole):
//      Newton at the full parameters, its steps cut to kWallStepLimit across the hole, the
//      factorization kept while the residual contracts (solvers/newton.hpp).
//   2. A string in a well on the default supports: the stable minimum of the energy at rest
//      from the string resting on the wall (analyses/static_minimum.hpp), then, for a string that
//      slides against the wall, Newton continued in the friction from 0 to its value.
//   3. Any other string (on its case supports, without a well): Newton with load stepping from the
//      reference placement.
//   4. `method: relaxation` in the case: dynamic relaxation (analyses/dynamic_relaxation.hpp).
//
// A strategy that fails hands over to the next with its reason kept; the outcome says which one
// found the equilibrium (results.json `static.method_used`).
#pragma once

#include "analyses/analysis_settings.hpp"
#include "analyses/static_outcome.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// The chain above. `input` is what `built` was built from; `start` a nearby equilibrium of the same
// model, or null.
StaticOutcome SolveStaticEquilibrium(const model::ModelInput& input, const model::BuiltModel& built,
                                     const StaticSettings& settings, const model::LoadParameters& parameters = 1.0,
                                     const VecX* start = nullptr);

// Strategies 3 and 4 alone: a string on its case supports (or without a well), whatever its input.
StaticOutcome SolveOnSupports(const model::BuiltModel& built, const StaticSettings& settings,
                              const model::LoadParameters& parameters = 1.0);

// Strategy 1 alone: Newton at the full parameters from `start`, at most `max_iterations` iterations.
StaticOutcome SolveFromNeighbour(const model::BuiltModel& built, const StaticSettings& settings,
                                 const model::LoadParameters& parameters, const VecX& start, int max_iterations);

}  // namespace drillflex::analyses
