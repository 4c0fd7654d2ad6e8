// What every bench needs beside Google Benchmark: the process's peak memory and the source tree's
// files (DRILLFLEX_SOURCE_DIR, set by bench/CMakeLists.txt).
#pragma once

#include <sys/resource.h>

#include <filesystem>
#include <string>

namespace drillflex::bench {

// The process's peak resident size so far, MB (getrusage's ru_maxrss is in kB on Linux).
inline double PeakMemoryMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// A file of the source tree by its path from the repository's root.
inline std::string SourcePath(const char* relative) {
  return (std::filesystem::path(DRILLFLEX_SOURCE_DIR) / relative).string();
}

}  // namespace drillflex::bench
