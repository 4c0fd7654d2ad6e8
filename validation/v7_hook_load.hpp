// V7 of validation.md in time, the hook load of a string sliding along a straight inclined hole
// (validation/v7-hook-load/): the V7 pipe (v7_pipe.hpp), off bottom, from the static equilibrium at
// rest, moved by the block at a steady velocity (pulling out or running in). Once the whole string
// slides, every contact's friction μN (N = w_b sin I per length on the low side) acts along the hole
// against the motion, and the hook load is Johancsik's (straight section, nothing at the bit):
//   F_top = w_b L (cos I ± μ sin I)   (+ pulling out, − running in),
// which the transient must give within 3 % (validation.md V7). The start of the sliding (the friction
// steps from none at rest to μN all along) sets off a standing axial wave (a quarter wave between the
// block and the free bit end, period 4L/c) that nothing damps while the string slides: μN is then
// constant, so the oscillation is a free one about the sliding state (its velocity swing at the bit,
// ΔF/(ρAc), is 0.1 ft/s over 1000 ft, ~0.5 ft/s over 10,000 ft, where the lower string nearly stops
// once a period; docs/validation.md). The hook load "once the motion is steady" is therefore its mean
// over whole periods of that wave, the last ones that fit after `from`: T = 4L/c with the bar speed
// c = sqrt(E/ρ) of the pipe's steel (the bore mud does not move axially with it in drillflex's
// inertia; measured 0.244–0.245 s over 1000 ft, 2.44 s over 10,000 ft). The motion is steady when each
// period's own mean agrees with the whole mean within 0.5 %. At t = 0 the hook load is the static
// one, w_b L cos I, within 1 %.
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

// The quarter-wave period 4L/c of `length_ft` of the V7 pipe, s: c = sqrt(E/ρ), the case's steel.
inline double AxialWavePeriod(double length_ft) {
  constexpr double kE = 2.1e11, kDensity = 8424.0164;  // Pa, kg/m³ (validation/v7-hook-load)
  return 4.0 * length_ft * kMetresPerFoot * std::sqrt(kDensity / kE);
}

// The sample nearest time t.
inline std::size_t SampleAt(const std::vector<double>& time, double t) {
  std::size_t k = 0;
  while (k + 1 < time.size() && std::abs(time[k + 1] - t) <= std::abs(time[k] - t)) ++k;
  return k;
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
  // The whole periods that fit between `from` and the end, counted back from the end.
  const double period = AxialWavePeriod(length_ft);
  const int periods = static_cast<int>(std::floor((time.back() - from) / period));
  ASSERT_GE(periods, 1) << "no whole period of the axial wave after " << from << " s";
  std::vector<std::size_t> up;  // the samples bounding the periods
  for (int k = periods; k >= 0; --k) up.push_back(SampleAt(time, time.back() - k * period));
  const double mean = MeanOver(time, hook, up.front(), up.back());
  std::printf("V7 %s, %.0f ft: hook load at rest %.1f lbf (w L cos I = %.1f, %+.3f %%); sliding, over %zu periods "
              "of %.3f s from t = %.2f s: %.1f lbf (Johancsik %.1f, %+.3f %%)\n",
              sign > 0.0 ? "pulling out" : "running in", length_ft, hook.front(), at_rest,
              100.0 * RelativeError(hook.front(), at_rest), up.size() - 1, period, time[up.front()], mean,
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
