#include "analyses/critical_speeds.hpp"

#include <algorithm>

namespace drillflex::analyses {

std::vector<std::size_t> FindProminentPeaks(const std::vector<double>& values, double relative_prominence) {
  std::vector<std::size_t> peaks;
  const std::size_t n = values.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double height = values[i];
    if (!(values[i - 1] < height && height >= values[i + 1])) continue;
    double left = height, right = height;  // the lowest value on the way to a higher point
    for (std::size_t j = i; j-- > 0 && values[j] <= height;) left = std::min(left, values[j]);
    for (std::size_t j = i + 1; j < n && values[j] <= height; ++j) right = std::min(right, values[j]);
    // A plateau's later points (equal heights to the right) belong to this peak.
    if (height - std::max(left, right) >= relative_prominence * height) peaks.push_back(i);
  }
  return peaks;
}

std::vector<IndexRange> FindRuns(const std::vector<bool>& ok) {
  std::vector<IndexRange> runs;
  for (std::size_t i = 0; i < ok.size(); ++i) {
    if (!ok[i]) continue;
    if (!runs.empty() && runs.back().last + 1 == i) {
      runs.back().last = i;
    } else {
      runs.push_back({i, i});
    }
  }
  return runs;
}

}  // namespace drillflex::analyses
