// The headline results of one run of a sweep (a row of sweep.csv): what a drilling engineer compares
// across a design study, read from the run's results.
#pragma once

#include <limits>
#include <string>

#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {

inline constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();

// SI; kNotComputed (NaN, an empty cell in sweep.csv, null in sweep.json) where the run's analyses
// give no such figure.
struct SweepOutcome {
  bool converged = false;
  std::string message;                          // why the run failed ("" when it converged)
  double bit_side_force = kNotComputed;         // N (static, in a well)
  std::string bit_tendency;                     // "build", "drop", "hold" (static, in a well)
  double largest_contact_force = kNotComputed;  // N, the largest wall contact force (static)
  double peak_von_mises_stress = kNotComputed;  // Pa (static)
  double first_critical_speed = kNotComputed;     // rad/s: the vibration's lowest critical RPM, else the modes' first lateral
  double stick_slip_severity = kNotComputed;    // (max − min) / mean bit speed over the transient's second half
  double whirl_speed = kNotComputed;            // rad/s, the whirling probe's precession (0: no whirl; transient)
  std::string whirl;                            // "none", "forward", "backward" (transient; pipeline/drilling_regime.hpp)
  std::string regime;                           // "smooth", "stick-slip, backward whirl", ... (transient)
  // N: tension at the surface, and N·m, the torque at the top (static: ComputeSurfaceLoads; else the
  // transient's end).
  double hook_load = kNotComputed;
  double surface_torque = kNotComputed;
  // rad/m: the steady build and turn rates (tendency).
  double build_rate = kNotComputed;
  double turn_rate = kNotComputed;
};

// What the rig sees of a static equilibrium: the tension at the surface (N; the top support's axial
// reaction, plus, for a string in a well on its default supports, the buoyed weight of the pipe above
// the model to the surface) and the torque there (N·m, the top support's, positive clockwise looking
// down-hole: the torque the rig turns the string with, as the transient's surface_torque). The reactions, not the top
// node's section forces, which are its element's, half an element down. NaN without a support at the
// top (a string held elsewhere).
struct SurfaceLoads {
  double hook_load = kNotComputed;
  double surface_torque = kNotComputed;
};
SurfaceLoads ComputeSurfaceLoads(const CaseResults& results);

// The headline of a finished run.
SweepOutcome SummarizeRun(const CaseResults& results);

// The stick-slip severity of a transient: (max − min) / mean of the bit's speed over the second half
// of the run (after the spin-up), as the report shows it (src/io/report/report.js): 0 steady rotation;
// a bit that stops and swings to twice its mean reads 2. NaN when the bit's mean speed there is zero.
double StickSlipSeverity(const analyses::TransientResult& result);

}  // namespace drillflex::pipeline
