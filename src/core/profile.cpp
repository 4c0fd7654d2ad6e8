#include "core/profile.hpp"

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>

#include <fmt/format.h>

namespace drillflex::profile {
namespace {

std::atomic<bool> enabled{false};

struct Totals {
  std::mutex mutex;
  std::map<std::string, Entry> entries;
};

Totals& GetTotals() {
  static Totals totals;
  return totals;
}

}  // namespace

void Enable(bool on) { enabled.store(on, std::memory_order_relaxed); }
bool Enabled() { return enabled.load(std::memory_order_relaxed); }

void Reset() {
  Totals& totals = GetTotals();
  const std::lock_guard<std::mutex> lock(totals.mutex);
  totals.entries.clear();
}

std::vector<Entry> Report() {
  Totals& totals = GetTotals();
  std::vector<Entry> report;
  {
    const std::lock_guard<std::mutex> lock(totals.mutex);
    for (const auto& [name, entry] : totals.entries) report.push_back(entry);
  }
  std::sort(report.begin(), report.end(), [](const Entry& a, const Entry& b) { return a.seconds > b.seconds; });
  return report;
}

std::string FormatReport(double total_seconds) {
  std::string text = fmt::format("{:<40} {:>10} {:>7} {:>9}\n", "scope (inclusive)", "seconds", "share", "calls");
  for (const Entry& entry : Report()) {
    text += fmt::format("{:<40} {:>10.4f} {:>6.1f}% {:>9}\n", entry.name, entry.seconds,
                        total_seconds > 0.0 ? 100.0 * entry.seconds / total_seconds : 0.0, entry.calls);
  }
  return text;
}

Scope::Scope(const char* name) : name_(name), active_(Enabled()) {
  if (active_) start_ = std::chrono::steady_clock::now();
}

Scope::~Scope() {
  if (!active_) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  Totals& totals = GetTotals();
  const std::lock_guard<std::mutex> lock(totals.mutex);
  Entry& entry = totals.entries[name_];
  entry.name = name_;
  entry.seconds += seconds;
  ++entry.calls;
}

}  // namespace drillflex::profile
