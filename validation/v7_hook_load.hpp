// V7 of validation.md in time, the hook load of a string sliding along a straight inclined hole
// (validation/v7-hook-load/): the V7 pipe (v7_pipe.hpp), off bottom, from the static equilibrium at
// rest, moved by the block at a steady velocity (pulling out or running in). Once the whole string
// slides, every contact's friction μN (N = w_b sin I per length on the low side) acts along the hole
// against the motion, and the hook load is Johancsik's (straight section, nothing at the bit):
//   F_top = w_b L (cos I ± μ sin I)   (+ pulling out, − running in),
// which the transient must give within 3 % (validation.md V7). The block's start also sets off a
// standing axial wave (a quarter wave between the block and the free bit end, period 4L/c) that
// nothing damps while the string slides: the friction μN is then constant, so the oscillation is a
// free one about the sliding state (its velocity amplitude, ΔF/(ρAc), stays well below the block's
// speed: the string never stops). The hook load "once the motion is steady" is therefore its mean
// over whole periods of that wave after `from` (between the first and last upward crossings of the
// mean), and the motion is steady when each period's own mean agrees with it within 0.5 %. At t = 0
// the hook load is the static one, w_b L cos I, within 1 %.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "v7_pipe.hpp"
#include "validation_support.hpp"

namespace drillflex::validation {

// Johancsik's hook load of `length_ft` of the V7 pipe, lbf: sign +1 pulling out, −1 running in, 0 at rest.
inline double JohancsikHookLoad(double length_ft, double sign) {
  return kV7BuoyedWeight * length_ft * (std::cos(kV7Inclination) + sign * kV7Friction * std::sin(kV7Inclination));
}

// The mean of y(t) over [t_i, t_j] (trapezoids).
inline double MeanOver(const std::vector<double>& t, const std::vector<double>& y, std::size_t i, std::size_t j) {
  double area = 0.0;
  for (std::size_t k = i; k < j; ++k) area += 0.5 * (y[k] + y[k + 1]) * (t[k + 1] - t[k]);
  return area / (t[j] - t[i]);
}

// The samples after `from` at which y rises through `level`.
inline std::vector<std::size_t> UpwardCrossings(const std::vector<double>& t, const std::vector<double>& y,
                                                double level, double from) {
  std::vector<std::size_t> up;
  for (std::size_t k = 1; k < t.size(); ++k) {
    if (t[k - 1] >= from && y[k - 1] < level && y[k] >= level) up.push_back(k);
  }
  return up;
}

// Runs `file` (a `length_ft` long string moved by the block, `sign` as above) and checks its hook
// load over the whole wave periods after `from` (s).
inline void CheckSlidingHookLoad(const std::string& file, double length_ft, double sign, double from) {
  const auto results = RunCaseTimed("transient", file);
  ASSERT_TRUE(results.contains("transient"));
  const CsvColumns csv = ReadCsv(ResultsDirectory(file) + "/transient.csv");
  const auto& time = csv["time"];
  const auto& hook = csv["hook_load"];  // lbf (the case's field units)
  const double at_rest = JohancsikHookLoad(length_ft, 0.0), reference = JohancsikHookLoad(length_ft, sign);
  // The mean over whole periods: crossings of the mean over the window, then of the mean over the
  // periods they bound (a fixed point after a few rounds).
  std::size_t first = 0;
  while (first + 1 < time.size() && time[first] < from) ++first;
  double mean = MeanOver(time, hook, first, time.size() - 1);
  std::vector<std::size_t> up;
  for (int round = 0; round < 4; ++round) {
    up = UpwardCrossings(time, hook, mean, from);
    ASSERT_GE(up.size(), 2u) << "no whole period of the axial wave after " << from << " s";
    mean = MeanOver(time, hook, up.front(), up.back());
  }
  std::printf("V7 %s, %.0f ft: hook load at rest %.1f lbf (w L cos I = %.1f, %+.3f %%); sliding, over %zu periods "
              "of %.3f s from t = %.2f s: %.1f lbf (Johancsik %.1f, %+.3f %%)\n",
              sign > 0.0 ? "pulling out" : "running in", length_ft, hook.front(), at_rest,
              100.0 * RelativeError(hook.front(), at_rest), up.size() - 1,
              (time[up.back()] - time[up.front()]) / static_cast<double>(up.size() - 1), time[up.front()], mean,
              reference, 100.0 * RelativeError(mean, reference));
  EXPECT_LT(std::abs(RelativeError(hook.front(), at_rest)), 0.01);
  EXPECT_LT(std::abs(RelativeError(mean, reference)), 0.03);
  for (std::size_t k = 0; k + 1 < up.size(); ++k) {
    const double period_mean = MeanOver(time, hook, up[k], up[k + 1]);
    std::printf("V7 %s, %.0f ft: period %zu from t = %.3f s: mean %.1f lbf\n", sign > 0.0 ? "pulling out" : "running in",
                length_ft, k + 1, time[up[k]], period_mean);
    EXPECT_LT(std::abs(RelativeError(period_mean, mean)), 0.005) << "period " << k + 1 << ": not steady";
  }
}

}  // namespace drillflex::validation
