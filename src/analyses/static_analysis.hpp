// Static analysis (method.md §9.1): the equilibrium R(q) = 0 of the string under its loads
// (weight, applied loads, supports), found by the chain of analyses/static_solve.hpp, and the
// results along the string.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "analyses/static_outcome.hpp"
#include "analyses/string_stations.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"
#include "solvers/newton.hpp"

namespace drillflex::analyses {

// Results at one station (analyses/string_stations.hpp). Frames: the string frame at the node
// (x along the string toward the top). SI.
struct StaticNodeResult {
  double s = 0.0;                      // m from the bit
  Vec3 position = Vec3::Zero();        // global, m
  Vec3 displacement = Vec3::Zero();    // string frame, relative to the undeformed placement, m
  Vec3 rotation = Vec3::Zero();        // string frame, rad
  double lateral_offset = 0.0;         // |displacement ⊥ string axis|, m
  double axial_force = 0.0;            // N, tension positive
  double torque = 0.0;                 // N·m
  double bending_moment = 0.0;         // N·m (magnitude)
  double shear_force = 0.0;            // N (magnitude)
  Vec3 force = Vec3::Zero();           // (N, V_y, V_z) string frame, model/internal_forces.hpp
  Vec3 moment = Vec3::Zero();          // (T, M_y, M_z) string frame
  double bending_stress = 0.0;         // M (OD/2) / I, Pa
  double von_mises_stress = 0.0;       // sqrt(σ² + 3τ²), σ = |N|/A + M c/I, τ = T c/J, Pa
  // The node's place in the hole (analyses/wall_offsets.hpp); set only with a well (has_wall).
  // hole_offset is measured from the hole axis, lateral_offset from the undeformed placement.
  bool has_wall = false;                // the fields below are set
  bool wall_contact = false;            // a wall contact acts at the node (all but the bit's nodes)
  double md = 0.0;                      // MD of the hole cross-section through the node, m
  double hole_offset = 0.0;             // ρ: distance of the node from the hole axis, m
  double offset_high_side_angle = 0.0;  // direction of the offset, rad: 0 high side, π/2 right, π low side
  double clearance = 0.0;               // R_h − R_c − ρ, m (< 0: pressed into the wall by N/k_n)
  double hole_diameter = 0.0;           // D at md, m
};

// The reaction a case support exerts on the string, string frame at the support.
struct SupportReaction {
  double s = 0.0;                // m
  Vec3 force = Vec3::Zero();     // N
  Vec3 moment = Vec3::Zero();    // N·m
};

// What the pipe above the model holds the top with (model/string_above.hpp), string frame at the top,
// and the top's tension at rest it takes.
struct PipeAboveReaction {
  double s = 0.0;              // m, the top
  Vec3 force = Vec3::Zero();   // N
  Vec3 moment = Vec3::Zero();  // N·m
  double tension = 0.0;        // N (< 0: compression)
  bool buckled = false;        // compressed beyond its F_sin: it holds nothing
};

// The MWD sensor's sag (analyses/mwd_sag.hpp): its axis against the hole's at the sensor.
struct MwdSag {
  double s = 0.0;                     // the sensor, m from the bit
  double md = 0.0;                    // its MD, m
  double axis_inclination = 0.0;      // what the sensor reads, rad
  double hole_inclination = 0.0;      // the hole's at the sensor's MD, rad
  double sag = 0.0;                   // axis − hole, rad (> 0: the sensor reads high; subtract it)
  double axis_azimuth = 0.0;          // rad, [0, 2π)
  double hole_azimuth = 0.0;          // rad, [0, 2π)
};

// A wall contact that carries force (model/wall_contact.hpp), for output.
struct ContactReport {
  double s = 0.0;                 // m from the bit
  double md = 0.0;                // m
  double normal_force = 0.0;      // N
  double friction_force = 0.0;    // N (magnitude)
  double high_side_angle = 0.0;   // rad: 0 high side, π/2 right, π low side
  Index component = 0;              // index in the string
  Vec3 contact_point = Vec3::Zero();  // where the string touches the wall (global), m
  Vec3 normal = Vec3::Zero();         // unit, from the hole axis toward the contact (global)
};

// The bit's directional tendency (case-format.md "Frames and signs"), from the reaction of the
// support at the bit: the force the bit exerts on the formation and the tilt of its axis.
struct BitReport {
  double side_force = 0.0;   // N, magnitude of the lateral force on the formation
  double build_force = 0.0;  // N, toward the high side (> 0 builds)
  double walk_force = 0.0;   // N, toward the right (> 0 walks right)
  double tilt = 0.0;         // rad, bit axis (down-hole) against the hole axis, > 0 toward the high side
  double tilt_right = 0.0;   // rad, the same toward the right (looking down-hole)
};

// The static analysis's result: the equilibrium as found (StaticOutcome: the state, how, its warnings)
// and what is derived from it.
struct StaticResult : StaticOutcome {
  std::vector<StaticNodeResult> nodes;    // from the bit upward
  std::vector<SupportReaction> reactions; // one per case support, in case order
  std::optional<PipeAboveReaction> pipe_above;  // with the pipe above the model (model.top)
  std::vector<ContactReport> contacts;     // wall contacts carrying force, from the bit upward
  std::optional<BitReport> bit;            // in a well, with a support at the bit
  std::optional<MwdSag> mwd;               // in a well, with an MWD component or analyses.static.mwd_at
};

// The contacts carrying force and the bit report at a state (filled in by RunStatic), the model
// evaluated under `parameters` (its friction, the bit's hold).
std::vector<ContactReport> ContactReports(const model::BuiltModel& built, const VecX& q,
                                          const model::LoadParameters& parameters = 1.0);
std::optional<BitReport> ComputeBitReport(const model::BuiltModel& built, const StaticResult& result);

// The static equilibrium of a string on its case supports (or without a well): Newton with load
// stepping from the reference placement (at most min(max_iterations, 50) iterations a load step),
// or dynamic relaxation when the settings ask for it (at most max_iterations × 10 pseudo-time
// steps). Throws SolverError, saying where and why, when it does not converge.
StaticResult RunStatic(const model::BuiltModel& built, const StaticSettings& settings);

// The static equilibrium of `built` (made from `input`) under `parameters`, by the chain of
// analyses/static_solve.hpp: a string in a well on the default supports by the energy's minimum
// from the string resting on the wall, continued in the friction when it slides; other strings as
// RunStatic. `start`: a nearby equilibrium of the same bodies to go from first (the chain's strategy
// 1), or null. Throws SolverError, saying why, when no strategy converges.
StaticResult RunStaticInWell(const model::ModelInput& input, const model::BuiltModel& built,
                             const StaticSettings& settings, const model::LoadParameters& parameters = 1.0,
                             const VecX* start = nullptr);

// The results along the string, the reactions, the contacts and the bit of a converged equilibrium
// under `parameters` (CheckForcesResolved first).
StaticResult WithResults(const model::BuiltModel& built, StaticResult result, const model::LoadParameters& parameters);

// The results at a given state q (used by RunStatic, buckling and tests), the dead loads scaled by
// `load` (model::NodalLoadElement::Scale) for the axial force inside bodies
// (model/internal_forces.hpp). At a joint the internal forces are the coupling force (the section
// between the two bodies; a point load at the joint acts on the upper body's node, above it).
std::vector<StaticNodeResult> StaticNodeResults(const model::BuiltModel& built, const VecX& q,
                                                const model::LoadParameters& load = 1.0);
// The same at the listed stations only (indices into StringStations(built.system)), in that order: a
// transient run's samples (the bit, the top, the probes) without the forces of the whole string.
std::vector<StaticNodeResult> StaticNodeResults(const model::BuiltModel& built, const VecX& q,
                                                const model::LoadParameters& load, std::span<const Index> station_indices);
std::vector<SupportReaction> SupportReactions(const model::BuiltModel& built, const VecX& q,
                                             const model::LoadParameters& parameters = 1.0);

// A converged `result` that leaves more than 1 % of the model's force scale (its loads) unbalanced is
// no equilibrium of them (a solver stops where the state no longer changes: with couplings so stiff
// that the residual's round-off floor exceeds the loads): throws SolverError naming the stiffest body
// (largest EA/ℓ: a component too short, or a modulus too large). Above 0.1 % it adds a warning saying
// how well the result balances. Every static solve passes its result through it.
void CheckForcesResolved(const model::BuiltModel& built, StaticResult& result);

// Newton options recommended for this model (model-orientation notes): increment tolerance 1e-10,
// no line search (stiff couplings), load stepping as the safeguard.
solvers::NewtonOptions DefaultNewtonOptions();

}  // namespace drillflex::analyses
