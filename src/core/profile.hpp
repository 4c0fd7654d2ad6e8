// Where a solve spends its time: named scopes whose wall time and calls are summed while profiling
// is on (`drillflex static --profile`, `drillflex roadmap --profile`, bench/roadmap_bench). Off by
// default, when a scope costs one relaxed atomic load. Scopes nest: each reports its inclusive
// time, so "residual" inside "line search" counts in both. Thread-safe (a mutex per record: scopes
// are coarse, an assembly or a factorization, thousands a solve).
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace drillflex::profile {

void Enable(bool on);
bool Enabled();
// Forgets what was recorded.
void Reset();

struct Entry {
  std::string name;
  double seconds = 0.0;  // wall time summed over the calls (on each thread)
  long calls = 0;
};
// What was recorded, the longest first.
std::vector<Entry> Report();
// The report as a table, one line a scope, with each scope's share of `total_seconds`.
std::string FormatReport(double total_seconds);

class Scope {
 public:
  explicit Scope(const char* name);
  ~Scope();
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;

 private:
  const char* name_;
  std::chrono::steady_clock::time_point start_;
  bool active_;
};

}  // namespace drillflex::profile
