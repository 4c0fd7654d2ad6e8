// What `sweep` and `stability` share: a sweep's runs on this machine (--jobs) or over MPI ranks.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "pipeline/sweep_mpi.hpp"
#include "pipeline/sweep_run.hpp"

namespace drillflex::app {

// Runs `combinations` of `base` into `directory` (its journal, and runs/ with --keep-runs), printing
// the plan and the progress as `what` ("sweep") on rank 0. Returns the rows in combination order on
// rank 0, nothing on the other ranks (which have then finished their share). An error on any rank
// under MPI ends every rank.
std::optional<std::vector<pipeline::SweepRow>> RunCombinations(const CommandOptions& options,
                                                               const pipeline::SweepMpiSession& mpi,
                                                               const io::Case& base,
                                                               const std::vector<pipeline::SweepCombination>& combinations,
                                                               const std::string& directory, const char* what);

// The rows that failed.
int CountFailed(const std::vector<pipeline::SweepRow>& rows);

}  // namespace drillflex::app
