#include "app/batch_progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include <fmt/format.h>

namespace drillflex::app {

void ShowBatchProgress(const char* what, int done, int total, int failed, double seconds_left) {
  static const bool terminal = isatty(STDERR_FILENO) == 1;
  const int remaining = total - done;
  const std::string left = seconds_left >= 0.0 && remaining > 0 ? fmt::format(", about {:.0f} s left", seconds_left) : "";
  const std::string line = fmt::format("{}: {} / {} done, {} failed{}", what, done, total, failed, left);
  if (terminal) {
    std::fprintf(stderr, "\r%s   %s", line.c_str(), remaining == 0 ? "\n" : "");
    std::fflush(stderr);
  } else if (total > 0 && (remaining == 0 || done % std::max(1, total / 10) == 0)) {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

}  // namespace drillflex::app
