// Directional tendency (docs/method.md "Directional tendency"; issue 34): the steady build and turn
// rates a BHA drills at the bit's depth.
//
// In a hole of constant curvature κ = (κ_b, κ_r) at the bit (analyses/tendency_hole.hpp) the static
// equilibrium gives the bit's side force F = (F_b, F_r), positive where the bit pushes the formation
// toward the high side and the right, and the tilt θ = (θ_b, θ_r) of its axis against the hole's. The
// bit cuts sideways as well as ahead: per unit of axial penetration it moves sideways by
//   d(κ) = θ(κ) + S F(κ) / WOB (+ δ, the formation's),
// S the bit's steerability, its lateral over its axial drillability (Menand, Sellami & Simon,
// SPE/IADC 79795; Ho, SPE 16658, calls it the bit anisotropy index). Where d = 0 the bit drills along
// the hole it is in and the hole keeps its curvature: that κ is the steady one. S → ∞ leaves F = 0,
// the zero-side-force criterion (Jogi, Burgess & Bowling, SPE 14768; Williamson & Lubinski, SPE
// 14764); S = 0 leaves θ = 0, the bit drilling along its own axis.
//
// A formation more drillable across its beds than along them adds its own term δ to d (below:
// FormationDeviation), constant for the bit's place and direction.
//
// The root: Newton on d(κ) with a Jacobian of forward differences at the start and Broyden's update
// after (Dennis & Schnabel §8.1), each evaluation one static in the hole of that κ, started from the
// nearest equilibrium found so far carried into it (the first from the case's own equilibrium when
// there is one). Steps are capped at kTendencyStepLimit; a step that does not lower |d| is halved.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/tendency_hole.hpp"
#include "analyses/three_point_yield.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

// The search: curvatures within ±kTendencyCurvatureLimit (30°/100 ft), each Newton step at most
// kTendencyStepLimit (3°/100 ft), converged when the next step is below kTendencyCurvatureTolerance
// (0.001°/100 ft), at most kTendencyEvaluations statics.
inline constexpr double kDegreesPer100Ft = kPi / 180.0 / 30.48;  // rad/m
inline constexpr double kTendencyCurvatureLimit = 30.0 * kDegreesPer100Ft;
inline constexpr double kTendencyStepLimit = 3.0 * kDegreesPer100Ft;
inline constexpr double kTendencyCurvatureTolerance = 0.001 * kDegreesPer100Ft;
inline constexpr double kTendencyDifferenceStep = 0.01 * kDegreesPer100Ft;
// A static starts from the nearest one solved (carried into its hole) when its curvature is at most
// this far, else from the string resting on the wall: a larger change of the hole bends the string
// enough that Newton from the neighbour, its steps cut across the hole, does not find its way
// (measured on the bundled example: 0.1 deg/100 ft of build converged, of turn did not).
inline constexpr double kTendencyWarmStep = 0.05 * kDegreesPer100Ft;
inline constexpr int kTendencyEvaluations = 24;

// The steady rates against one of the BHA's handles (analyses/tendency_sensitivity.hpp).
struct TendencyCurve {
  std::vector<double> values;      // the handle's values (SI: N, rad, m)
  std::vector<double> build_rate;  // rad/m; NaN where that tendency failed
  std::vector<double> turn_rate;   // rad/m
};
struct TendencySensitivities {
  TendencyCurve weight_on_bit;     // the case's WOB × 0.5, 0.75, 1, 1.25, 1.5
  TendencyCurve inclination;       // the bit's inclination −10°, −5°, 0, +5°, +10° (within 0–90°)
  TendencyCurve gauge_reduction;   // every blade's OD less 0, 1/16 in, 1/8 in
};

// A rotary steerable system's rates as directional drillers read them: the natural tendency (0 %
// steer), full steer (100 %), and the yield per unit of steer between them (the rate is linear in the
// steer: the deviation is the steer-weighted mean of the neutral and the steering strings').
struct SteeringRates {
  double steer = 0.0;
  HoleCurvature natural;  // build and right curvature at 0 % steer, 1/m
  HoleCurvature full;     // at 100 %
};

// One static of the search: the hole's curvature and what the bit does in it.
struct TendencyPoint {
  HoleCurvature curvature;      // 1/m
  BitReport bit;                // side forces and tilts
  double deviation_build = 0.0;  // d_b: sideways per axial penetration toward the high side, rad
  double deviation_right = 0.0;  // d_r: the same toward the right, rad
  std::string method;           // how its static was found
};

struct TendencyResult {
  HoleCurvature curvature;        // the steady curvature at the bit, 1/m
  double build_rate = 0.0;        // dI/ds = κ_b, rad/m (> 0 builds)
  double turn_rate = 0.0;         // dA/ds = κ_r / sin I, rad/m (> 0 turns right; 0 in a vertical hole)
  double dogleg_severity = 0.0;   // |κ|, rad/m
  double inclination = 0.0;       // at the bit, rad
  double azimuth = 0.0;           // at the bit, rad
  double steerability = 0.0;
  double weight_on_bit = 0.0;     // N
  double arc_length = 0.0;        // m: the steady hole's arc above the bit
  int toolfaces = 1;              // the bend's toolfaces a rotating bent motor's deviation is averaged over
  int statics = 0;                // of the search: trace × the statics a point averages
  std::optional<SteeringRates> steering;  // with a rotary steerable system
  std::vector<TendencyPoint> trace;  // every static of the search, in order
  Index steady_index = 0;              // the answer's in `trace`
  StaticResult equilibrium;       // in the steady hole
  std::optional<TendencySensitivities> sensitivities;  // when the settings ask for them
  std::optional<ThreePointYield> three_point;          // a bent motor's geometric yield, beside
};

// Builds a model for an input (the pipeline's, with the case's reductions).
using ModelFactory = std::function<model::BuiltModel(const model::ModelInput&)>;

// The steady curvature of the string of `input` (a string in a well, with a bit and a WOB, on the
// default supports) at its bit depth. A rotating bent motor (operation.rpm > 0) averages the bit's
// deviation over its bend at four toolfaces a quarter turn apart. Throws InputError (no file: the
// caller names it) for a string the tendency cannot take, and SolverError when a static fails or no
// curvature within ±30°/100 ft is steady (with d and the side force at both ends). `first`: the
// curvature the search starts from (default: the case hole's own at the bit). (The case's own
// equilibrium is no start: carried from the case's hole, which is not an arc, into the steady one it
// misfit the stiff couplings and the bit's support by more than Newton from a neighbour recovers.)
TendencyResult RunTendency(const model::ModelInput& input, const ModelFactory& build, const StaticSettings& statics,
                           const TendencySettings& settings, std::optional<HoleCurvature> first = std::nullopt);

// The formation's term δ of the bit's deviation (its build and right components at the bit, rad), for
// a drilling direction along the hole's tangent b at the bit: with the bedding's normal n (b·n ≥ 0) and
// drillabilities D_⊥ = 1 + h across the beds and D_∥ = 1 − h along them, the bit penetrates along
// D_⊥ (b·n) n + D_∥ (b − (b·n) n), turned toward n by h sin 2α to first order in h (α the angle between
// b and n; the anisotropic drillability of Lubinski & Woods' formation, Ho's formation index h): as a
// vector across the hole, 2 h (b·n) (n − (b·n) b).
HoleCurvature FormationDeviation(const FormationSettings& formation, const well::PathFrame& bit);

// The reasons `input` cannot have a tendency, as (key, message) for an InputError; none when it can.
std::optional<std::pair<std::string, std::string>> TendencyInputProblem(const model::ModelInput& input);

// The hole above the model's top that the steady hole has too: the BHA drilled it, so the arc goes on
// there, and the pipe above the top (model/string_above.hpp) lies in it.
inline constexpr double kTendencyHoleAboveTop = 30.0;  // m

// The length over which the steady hole is an arc: the modelled string and kTendencyHoleAboveTop above
// it, but no longer than a quarter turn of the arc (straight above that), and no shorter than the BHA
// (the string below its first drill pipe), m.
double TendencyArcLength(const model::StringConfig& string, double curvature);

}  // namespace drillflex::analyses
