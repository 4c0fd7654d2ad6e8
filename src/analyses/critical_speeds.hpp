// The critical-speed map read from a forced-response sweep (analyses/vibration_analysis.hpp):
// critical RPMs (the resonance peaks) and safe RPM windows.
#pragma once

#include <cstddef>
#include <vector>

namespace drillflex::analyses {

// A peak of the curve counts when its prominence is at least this fraction of its height.
inline constexpr double kCriticalPeakProminence = 0.1;

// Indices of the interior local maxima y_i (y_{i−1} < y_i ≥ y_{i+1}) whose prominence is at least
// `relative_prominence` × y_i. Prominence (the topographic one, as in SciPy's find_peaks): y_i
// minus the higher of the two lowest values between i and the nearest higher point on each side
// (or the end of the curve on that side).
std::vector<std::size_t> FindProminentPeaks(const std::vector<double>& values, double relative_prominence);

struct IndexRange {
  std::size_t first = 0, last = 0;  // inclusive
};

// Maximal runs of consecutive indices where `ok[i]` holds.
std::vector<IndexRange> FindRuns(const std::vector<bool>& ok);

}  // namespace drillflex::analyses
