// A sweep over MPI ranks (`mpirun -np N drillflex sweep ...`): rank 0 hands the runs out one at a
// time (a rank asks for the next when it has finished one: runs take 0.2 s to minutes, so a fixed
// split would leave ranks idle), runs cases itself on a second thread, gathers the rows and keeps the
// journal; the table it writes is the serial one's. Built only with DRILLFLEX_MPI (Open MPI); without
// it a session is never active and the sweep runs on this machine alone.
#pragma once

#include <cstdlib>
#include <vector>

#include "io/case.hpp"
#include "pipeline/sweep_run.hpp"

namespace drillflex::pipeline {

// MPI for one sweep: initialized when this process was started by an MPI launcher (its environment
// says so), finalized when the session ends. Inactive (rank 0 of 1) otherwise.
class SweepMpiSession {
 public:
  SweepMpiSession();
  ~SweepMpiSession();
  SweepMpiSession(const SweepMpiSession&) = delete;
  SweepMpiSession& operator=(const SweepMpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool active() const { return size_ > 1; }
  // Ranks of this job on this machine (the cores a rank's runs may use are shared among them).
  int local_size() const { return local_size_; }
  // Ends every rank of the job (an error on one rank mid-sweep would leave the others waiting).
  [[noreturn]] void Abort(int status) const;

 private:
  bool initialized_ = false;
  int rank_ = 0;
  int size_ = 1;
  int local_size_ = 1;
};

// True when drillflex was built with MPI.
bool SweepMpiBuilt();

// The sweep over the session's ranks. Returns the rows (combination order) on rank 0, none elsewhere.
// Bytes a message carries: 4 for a run's index, about 600 for a row back (its JSON).
std::vector<SweepRow> RunSweepOverRanks(const io::Case& base, const std::vector<SweepCombination>& combinations,
                                        const SweepOptions& options, const SweepMpiSession& session);

}  // namespace drillflex::pipeline
