// Reading a whirl from a transient.csv probe: the whirl angle made continuous, and its rate.
#pragma once

#include <cstddef>
#include <vector>

namespace drillflex::validation {

// The whirl angle (degrees, wrapped to [0, 360)) made continuous.
inline std::vector<double> Unwrapped(const std::vector<double>& angle) {
  std::vector<double> out(angle.size());
  double turns = 0.0;
  for (std::size_t i = 0; i < angle.size(); ++i) {
    if (i > 0) {
      const double step = angle[i] - angle[i - 1];
      if (step > 180.0) turns -= 360.0;
      if (step < -180.0) turns += 360.0;
    }
    out[i] = angle[i] + turns;
  }
  return out;
}

// Least-squares slope of y(x) over the samples with x ≥ from.
inline double Slope(const std::vector<double>& x, const std::vector<double>& y, double from) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] < from) continue;
    n += 1.0;
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace drillflex::validation
