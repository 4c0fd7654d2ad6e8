#include "pipeline/sweep_mpi.hpp"

#include <cstdlib>

#ifdef DRILLFLEX_HAVE_MPI
#include <mpi.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#endif

#include "core/error.hpp"

namespace drillflex::pipeline {

#ifdef DRILLFLEX_HAVE_MPI

namespace {

constexpr int kTagRow = 1;    // worker → rank 0: a finished row's JSON ("" for the first request)
constexpr int kTagWork = 2;   // rank 0 → worker: the index of the next run, −1 for none
constexpr int kStop = -1;

// Started by mpirun / srun: Open MPI's, PMI's or PMIx's variables are set.
bool LaunchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(name)) return true;
  }
  return false;
}

int LocalSize() {
  if (const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE")) return std::max(1, std::atoi(local));
  return 1;
}

// Rank 0's side: answer each worker's message with the next run, record the rows; a thread of its own
// runs cases from the same queue. Only this thread calls MPI (MPI_THREAD_FUNNELED). It polls with
// MPI_Iprobe and a short sleep: a blocking probe spins a core that the local runs need.
std::vector<SweepRow> Master(const io::Case& base, const std::vector<SweepCombination>& combinations,
                             const SweepOptions& options, const SweepMpiSession& session) {
  SweepLedger ledger(combinations, options);
  const std::vector<int>& pending = ledger.pending();
  const std::string runs_directory = (std::filesystem::path(options.directory) / "runs").string();
  std::atomic<std::size_t> next{0};
  auto take = [&]() -> int {
    const std::size_t k = next++;
    return k < pending.size() ? pending[k] : kStop;
  };
  const int threads = AvailableThreads();
  std::thread local([&]() {
    ShareCoresAmongJobs(session.local_size(), threads);
    for (int index = take(); index != kStop; index = take()) {
      ledger.Record(RunSweepCase(base, index, combinations[static_cast<std::size_t>(index)], options.keep_runs,
                                 runs_directory));
    }
  });
  int working = session.size() - 1;
  std::string buffer;
  while (working > 0) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagRow, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      continue;
    }
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    buffer.assign(static_cast<std::size_t>(length), '\0');
    MPI_Recv(buffer.data(), length, MPI_CHAR, status.MPI_SOURCE, kTagRow, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (!buffer.empty()) ledger.Record(SweepRowFromJson(nlohmann::json::parse(buffer)));
    int index = take();
    MPI_Send(&index, 1, MPI_INT, status.MPI_SOURCE, kTagWork, MPI_COMM_WORLD);
    if (index == kStop) --working;
  }
  local.join();
  return ledger.TakeRows();
}

void Worker(const io::Case& base, const std::vector<SweepCombination>& combinations, const SweepOptions& options,
            const SweepMpiSession& session) {
  ShareCoresAmongJobs(session.local_size(), AvailableThreads());
  const std::string runs_directory = (std::filesystem::path(options.directory) / "runs").string();
  std::string message;  // the first: a request with no row
  for (;;) {
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kTagRow, MPI_COMM_WORLD);
    int index = kStop;
    MPI_Recv(&index, 1, MPI_INT, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index == kStop) return;
    const SweepRow row = RunSweepCase(base, index, combinations[static_cast<std::size_t>(index)], options.keep_runs,
                                      runs_directory);
    message = SweepRowToJson(row).dump();
  }
}

}  // namespace

SweepMpiSession::SweepMpiSession() {
  if (!LaunchedByMpi()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  initialized_ = true;
  if (provided < MPI_THREAD_FUNNELED) {
    throw LogicError("MPI does not give MPI_THREAD_FUNNELED: rank 0 cannot run cases beside its dispatch");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  local_size_ = LocalSize();
}

SweepMpiSession::~SweepMpiSession() {
  if (initialized_) MPI_Finalize();
}

bool SweepMpiBuilt() { return true; }

void SweepMpiSession::Abort(int status) const {
  if (initialized_) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

std::vector<SweepRow> RunSweepOverRanks(const io::Case& base, const std::vector<SweepCombination>& combinations,
                                        const SweepOptions& options, const SweepMpiSession& session) {
  if (session.rank() == 0) return Master(base, combinations, options, session);
  Worker(base, combinations, options, session);
  return {};
}

#else  // without MPI: a session is never active.

SweepMpiSession::SweepMpiSession() = default;
SweepMpiSession::~SweepMpiSession() = default;
bool SweepMpiBuilt() { return false; }
void SweepMpiSession::Abort(int status) const { std::exit(status); }

std::vector<SweepRow> RunSweepOverRanks(const io::Case& base, const std::vector<SweepCombination>& combinations,
                                        const SweepOptions& options, const SweepMpiSession&) {
  return RunSweep(base, combinations, options);
}

#endif

}  // namespace drillflex::pipeline
