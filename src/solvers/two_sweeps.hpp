// Two independent sweeps of a block-tridiagonal factorization or solve (one from each end of a
// string toward its middle block: solvers/block_tridiagonal_lu.hpp, block_tridiagonal_cholesky.hpp),
// side by side on two OpenMP threads.
#pragma once

#include <cstddef>
#include <exception>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace drillflex::solvers {

// Below this many blocks both sweeps run on the calling thread: a thread's start costs more.
constexpr std::size_t kParallelBlocks = 16;

// Runs the two independent sweeps, side by side on two OpenMP threads when `parallel` and the caller
// allows more than one thread, one after the other otherwise; an exception in either is rethrown here.
template <typename First, typename Second>
void RunBoth(bool parallel, const First& first, const Second& second) {
#ifdef _OPENMP
  parallel = parallel && omp_get_max_threads() > 1;
#else
  static_cast<void>(parallel);  // without OpenMP the pragma below is ignored: one after the other
#endif
  std::exception_ptr failure;
  auto guarded = [&failure](const auto& task) {
    try {
      task();
    } catch (...) {
#pragma omp critical(drillflex_block_lu_failure)
      if (!failure) failure = std::current_exception();
    }
  };
#pragma omp parallel sections num_threads(2) if (parallel)
  {
#pragma omp section
    guarded(first);
#pragma omp section
    guarded(second);
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace drillflex::solvers
