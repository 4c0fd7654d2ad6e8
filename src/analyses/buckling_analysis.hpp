// Buckling (method.md §9.3), two ways:
//  (a) the linearized buckling eigenproblem (K_0 + μ K_G) x = 0 with K_0 the tangent at the
//      reference placement under no load and K_G = (K_T(q_ref, λ_ref) − K_0)/λ_ref, q_ref the
//      static equilibrium at load factor λ_ref; μ is the multiplier of the case's loads at
//      buckling (solvers::SolveBuckling). λ_ref starts at 1 (halved while no equilibrium is
//      found) and is then iterated to μ by the secant method on μ(λ_ref) − λ_ref: the tangent is
//      NOT linear in the load here, because the stiff coupling and support springs change their
//      lever arms with the bodies' axial shortening (terms ~k·u·δu, tiny relative to k but large
//      against the geometric stiffness once condensed onto the soft buckling directions).
//      K_T − (K_0 + λ K_G(1)) grows as λ² (measured), and extrapolating K_G from λ_ref = 1 was
//      20–67 % low on the V2 columns (pinned-pinned: μ = 57.9 against 131.0); at λ_ref = μ the
//      problem is exact, K_0 + μ (K_T(μ) − K_0)/μ = K_T(μ), i.e. μ is where the tangent of the
//      prebuckling path becomes singular. Higher multipliers (`modes` > 1) are those of the last
//      K_G, approximate;
//  (b) the paper's Figure 5: the lowest non-zero natural frequency f against the load factor,
//      f² extrapolated to zero: ω² (signed) at frequency_points load factors evenly from 0 to
//      below the estimate of (a) (or to 1), the root of a quadratic through the last three, then
//      samples at 0.9, 0.97 and 0.99 of the current root estimate, re-extrapolated each time;
//      converged when the last two estimates agree to 1e-4.
//  (c) about the case's equilibrium, for a string in a well and whenever the WOB alone is scaled:
//      the multiplier at which the lowest lateral natural frequency of the string at rest about
//      its equilibrium under the scaled loads reaches zero, the equilibria found from the case's
//      own upward (buckling_analysis.cpp SolveAboutEquilibrium). Nothing but its contacts and the
//      tension above may hold such a string laterally, so (a)'s unloaded K_0 is singular; the
//      stiffness of the loaded static state is not. (An eigenproblem about the equilibrium with
//      K_G = dK_T/dμ along the path, differenced, was tried and dropped: the stiff springs' lever
//      arm terms made it say 1.03 on the bundled example and 1.26 on Lubinski's string, whose
//      equilibria stay stable to 2.0 and 8.6: docs/validation.md.)
// Which loads the multiplier μ scales (BucklingSettings::scale): the WOB alone when the case has
// one (the engineer's question: what WOB buckles the string; the weight, fluid and the other loads
// stay), every load otherwise. The critical WOB is reported either way (WOB × μ).
// The critical load is reported as the largest axial compression in the string at λ = 1 times
// the multiplier for (a) and (b) (prebuckling is linear); for (c) as the largest compression
// extrapolated along the last two equilibria to μ.
#pragma once

#include <vector>

#include "analyses/analysis_settings.hpp"
#include "analyses/string_stations.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

struct FrequencyLoadPoint {
  double load_factor = 0.0;      // λ
  double compression = 0.0;      // largest axial compression at λ, N (> 0 compressive)
  double frequency_hz = 0.0;     // lowest non-zero natural frequency at λ
};

// The industry's buckling check of a string lying in an inclined hole, beside the eigenproblem: at
// each station of the case's equilibrium in compression F, Dawson & Paslay's (1984) sinusoidal
// buckling load F_sin = 2 √(EI w sin θ / r) (w the buoyed weight per length, θ the inclination, r
// the radial clearance of the contact circle) and Chen, Lin & Cheatham's (1990) helical load
// F_hel = 2√2 F_sin. With every load scaled by λ, F grows as λ and F_sin as √λ, so the string
// reaches F_sin first at λ = min (F_sin / F)² over the stations; with the WOB alone scaled by μ,
// F grows by (μ − 1) WOB (a dead load, frictionless at rest) and F_sin stays: μ = min 1 + (F_sin − F)/WOB.
struct SinusoidalBucklingScreen {
  bool computed = false;          // a string in a well with some station in compression
  double load_factor = 0.0;       // the multiplier at which the first station reaches F_sin (< 1: beyond it)
  double s = 0.0, md = 0.0;       // that station, m
  double compression = 0.0;       // its compression at λ = 1, N
  double sinusoidal_load = 0.0;   // its F_sin at λ = 1, N
  double helical_load = 0.0;      // its F_hel at λ = 1, N
  double largest_ratio = 0.0;     // max F / F_sin over the stations with F_sin > 0, at λ = 1 (> 1: buckled)
};

struct BucklingResult {
  bool scaled_wob = false;        // the multiplier scales the WOB alone (else every load)
  bool about_equilibrium = false; // found by (c) below, not by (a) and (b)
  // (c) only: no onset up to the largest multiplier sampled. The string's lowest lateral frequency
  // rose with the load at every sample up to it, each equilibrium stable (ω² > 0): the compression
  // presses the string harder onto the wall (the outside of a curve) rather than buckling it. Then
  // load_factor, critical_load and critical_wob are lower bounds (the loads at that multiplier), the
  // mode the lowest lateral mode there, and frequency_method_converged false.
  bool lower_bound = false;
  // The frequency route found the string buckled at the case's loads (ω² ≤ 0 there, or compressed
  // beyond Dawson–Paslay's load with a frequency that rises as the post-buckled string is pressed) and
  // searched for the onset below them: load_factor < 1.
  bool buckled_at_case_loads = false;
  // The onset is the pipe above the model reaching Dawson–Paslay's F_sin at the model's top
  // (model/string_above.hpp): the modelled string stands up to it.
  bool onset_above_model = false;
  double critical_wob = 0.0;      // the WOB at buckling, N: WOB × μ (0 without a WOB)
  // (a) the eigenproblem
  double load_factor = 0.0;       // μ_cr: the case's loads × μ_cr buckle the string
  double critical_load = 0.0;     // compression at λ = 1 × μ_cr, N
  std::vector<double> load_factors;  // the lowest `modes` multipliers, ascending
  double reference_load_factor = 1.0;  // the final λ_ref of K_G (≈ μ_cr when iterated)
  double reference_compression = 0.0;  // largest axial compression at λ = 1, N
  // (b) frequency against load
  bool frequency_method_converged = false;
  double frequency_load_factor = 0.0;   // μ from f² → 0
  double frequency_critical_load = 0.0; // N
  double unloaded_frequency_hz = 0.0;   // f₀ at λ = 0
  std::vector<FrequencyLoadPoint> frequency_table;  // ascending λ
  // The buckled mode (a): per station, string frame, max |displacement| = 1.
  std::vector<double> s;
  std::vector<Vec3> mode_displacement;
  std::vector<Vec3> mode_rotation;
  // In a well: Dawson–Paslay's check (above).
  SinusoidalBucklingScreen sinusoidal;
};

// `built` made from `input`. Each equilibrium under λ × the loads is found as the static analysis
// finds it (a string in a well: its energy's minimum, analyses/static_minimum.hpp; `static_settings`
// for the log). Throws SolverError if the case's loads do not buckle the string (no positive
// multiplier), no static equilibrium is found even at 1/64 of the loads, or the eigenproblem fails
// (e.g. an unsupported string: K_0 singular). The frequency method never throws: see
// frequency_method_converged.
BucklingResult RunBuckling(const model::ModelInput& input, const model::BuiltModel& built,
                           const BucklingSettings& settings, const StaticSettings& static_settings = {});

}  // namespace drillflex::analyses
