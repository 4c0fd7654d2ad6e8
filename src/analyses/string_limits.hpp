// The string's limits along a static answer (issue 37): at every station the von Mises stress on the
// component's rated section against its yield / the design factor, the torque against the
// connections' make-up torque, and the compression against Dawson & Paslay's sinusoidal and Chen, Lin &
// Cheatham's helical buckling loads (model/string_limits.hpp), the buckled zones as MD ranges, and
// which limit is closest and where. Utilisation: load / limit (≥ 1: at or beyond the limit).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "analyses/static_analysis.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

enum class BucklingState { NotScreened, None, Sinusoidal, Helical };
const char* BucklingStateName(BucklingState state);  // "not screened", "none", "sinusoidal", "helical"

inline constexpr double kNoLimit = std::numeric_limits<double>::quiet_NaN();

// One station (analyses::StaticNodeResult). NaN where a limit does not apply.
struct NodeLimits {
  double s = 0.0;                          // m from the bit
  double md = 0.0;                         // m (s without a well)
  Index component = 0;                       // index in the string (model::ComponentAt)
  double yield = kNoLimit;                 // minimum yield strength, Pa (E-75's for steel of no grade)
  double allowable_stress = kNoLimit;      // yield / design factor, Pa
  double von_mises_stress = 0.0;           // on the rated (class) section, Pa
  double stress_utilisation = kNoLimit;    // σ_vm / allowable
  double makeup_torque = kNoLimit;         // N·m, as given
  double torque_utilisation = kNoLimit;    // |T| / make-up torque
  double compression = 0.0;                // N, −axial force (< 0: tension)
  double sinusoidal_load = kNoLimit;       // Dawson–Paslay's F_s, N (in a well)
  double helical_load = kNoLimit;          // Chen's F_h, N
  double buckling_utilisation = kNoLimit;  // compression / F_h (F_h > 0)
  BucklingState buckling = BucklingState::NotScreened;
  // Fatigue (a rotating string only: rpm > 0; model/dogleg_fatigue.hpp), NaN where it does not apply.
  double hole_curvature = kNoLimit;             // the hole's dogleg at the station, 1/m (in a well)
  double dogleg_bending_stress = kNoLimit;      // pipe and HWDP: Lubinski's E D κ/2 · KL/tanh KL, Pa
  double max_dogleg = kNoLimit;                 // pipe and HWDP: Lubinski's permissible curvature, 1/m
  double fatigue_bending_stress = kNoLimit;     // the larger of the static's M c/I and the dogleg's, Pa
  double allowable_bending_stress = kNoLimit;   // RP 7G's endurance limit under the station's tension, Pa
  double fatigue_utilisation = kNoLimit;        // fatigue_bending_stress / allowable_bending_stress
};

// A stretch of stations beyond a buckling load, MD from (the shallower end) to.
struct BuckledZone {
  BucklingState state = BucklingState::Sinusoidal;  // sinusoidal: beyond F_s; helical: beyond F_h
  double md_from = 0.0, md_to = 0.0;                 // m
};

// The largest utilisation of one limit and where; limit "" and NaN when none applies.
struct LimitUtilisation {
  std::string limit;  // "yield", "makeup_torque", "helical_buckling", "fatigue"
  double utilisation = kNoLimit;
  double s = 0.0, md = 0.0;  // m
  Index component = -1;
};

struct StringLimits {
  double design_factor = 0.0;
  std::vector<NodeLimits> nodes;
  std::vector<BuckledZone> zones;  // sinusoidal zones (they include the helical ones), then helical
  LimitUtilisation yield, makeup_torque, helical_buckling;
  LimitUtilisation fatigue;        // a rotating string's worst dogleg (or bending) for fatigue
  LimitUtilisation closest;        // the largest of the four
  // The assumptions the answer rests on, in words (a yield taken as E-75's, no make-up torque given).
  std::vector<std::string> notes;
};

// The sinusoidal and helical buckling loads at a station of `input`'s string in its well (s from the
// bit, md its MD), N, as ComputeStringLimits takes them (below): the larger of the inclined hole's
// (Dawson–Paslay's F_s, Chen's √2 F_s) and the vertical hole's (Lubinski's, Wu & Juvkam-Wold's:
// model/string_limits.hpp), so that near vertical (below a kick-off) the load is the string's own, not
// zero. NaN without a trajectory or a hole there.
struct BucklingLoads {
  double sinusoidal = 0.0;
  double helical = 0.0;
};
BucklingLoads BucklingLoadsAt(const model::ModelInput& input, double s, double md);

// ComputeStringLimits (below) in two halves, for answers read many times over (a transient's samples:
// analyses/limits_envelope.hpp). StationRatings: what of a station's limits does not depend on its load:
// s, md, its component, yield and allowable stress, make-up torque, buckling loads and (rotating, in a
// well) the hole's curvature; the rest as a NodeLimits{} has it. LoadStationLimits: the rest under the
// station's section forces (`result`'s axial force, torque and bending moment), into `node` made by
// StationRatings of the same `input` (every loaded field overwritten where it applies: start each load
// from the ratings).
NodeLimits StationRatings(const model::ModelInput& input, double s, double md, double design_factor);
void LoadStationLimits(const model::ModelInput& input, const StaticNodeResult& result, NodeLimits& node);

// The limits along `nodes` (a static's stations, from the bit upward) of `input`'s string: the rated
// section and yield of the component at each station (model::ComponentAt; its grade or yield, else
// E-75's for steel and nonmag, none for other materials; not the bit), the make-up torque where the
// component gives one, and in a well the buckling loads with w the component's buoyed weight per
// length (model::BuoyedWeightPerLength), E I its body's, θ the hole's inclination at the station and r
// the radial clearance of the component's contact diameter (model::ContactDiameter: its tool joints',
// its blades', else its body's) in the hole there. A vertical station (F_s = 0) is not screened.
// A rotating string (input.operation.rotary_speed > 0) is screened for fatigue at every station of a
// graded steel (the bit and other materials not): the bending stress, the larger of the static's own
// (M c/I on the body) and, for pipe and HWDP, Lubinski's in the hole's dogleg under the station's tension
// (L half the joint spacing: joint_spacing, else the item's length), against RP 7G's allowable bending
// stress under the tensile stress N/A (model/dogleg_fatigue.hpp).
StringLimits ComputeStringLimits(const model::ModelInput& input, const std::vector<StaticNodeResult>& nodes,
                                 double design_factor);

// A dogleg the string rotates through: a stretch of consecutive stations (from the bit upward) screened
// for fatigue where the hole curves (its curvature above kDoglegCurvature), and its worst station.
inline constexpr double kDoglegCurvature = 1e-7;  // 1/m: 0.0002 °/100 ft; a straight hole's is 0 to round-off
struct DoglegFatigue {
  double md_from = 0.0, md_to = 0.0;   // m, the stretch's shallower and deeper station
  double utilisation = 0.0;            // the largest fatigue utilisation in it
  double md = 0.0;                     // m, where
  double curvature = 0.0;              // 1/m, the hole's there
  Index component = -1;                // index in the string
};
// The doglegs of a rotating string's limits (ComputeStringLimits' nodes), by MD from the shallowest.
std::vector<DoglegFatigue> FatigueDoglegs(const StringLimits& limits);

}  // namespace drillflex::analyses
