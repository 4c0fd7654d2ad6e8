// Linear vibration modes (method.md §9.2) about a state q: K = ∂R/∂q at q (v = a = 0, load
// factor 1: the geometric stiffening of the loads in that state is included), M = M(q);
// K x = ω² M x (solvers::SolveModes, sparse shift-invert Lanczos for large models). Each mode is
// classified by the split of its kinetic energy ½ xᵀ M x over the nodes into axial, torsional and
// lateral parts.
#pragma once

#include <vector>

#include "analyses/analysis_settings.hpp"
#include "analyses/string_stations.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"

namespace drillflex::analyses {

struct ModeResult {
  double frequency_hz = 0.0;     // 0 for a rigid-body mode
  double eigenvalue = 0.0;       // ω², rad²/s²
  ModeKind kind = ModeKind::Lateral;  // the dominant family (never All)
  // Kinetic-energy fractions (sum 1): translation along the string axis, rotation about it, rest.
  double axial_fraction = 0.0, torsional_fraction = 0.0, lateral_fraction = 0.0;
  bool rigid_body = false;       // ω² below the rigid-body threshold (unsupported string)
  // Shape per station (ModesResult::s), string frame, scaled so that max |displacement| = 1
  // (rotations by the same factor; a purely torsional mode: max |rotation| = 1).
  std::vector<Vec3> displacement;
  std::vector<Vec3> rotation;
  VecX vector;                   // the mode in the velocity coordinates, M-normalised
};

struct ModesResult {
  std::vector<double> s;          // stations (analyses/string_stations.hpp), m
  std::vector<ModeResult> modes;  // sorted by frequency; rigid-body modes included at 0 Hz
  int rigid_body_modes = 0;       // how many of `modes` are rigid-body modes
};

const char* ModeKindName(ModeKind kind);

// The `count` lowest modes (kind All), or the `count` lowest modes of one family (Lateral,
// Axial, Torsional: more modes are solved progressively until enough are found, at most
// kMaxModesSearched). Throws SolverError if the eigen solver fails.
ModesResult RunModes(const model::BuiltModel& built, const VecX& q, const ModesSettings& settings);

// The same on a bare system model (buckling's frequency method).
ModesResult ComputeModes(const model::SystemModel& model, const VecX& q, const ModesSettings& settings);

inline constexpr int kMaxModesSearched = 400;
// A mode is a rigid-body mode when f < kRigidBodyFrequencyHz.
inline constexpr double kRigidBodyFrequencyHz = 1e-3;

}  // namespace drillflex::analyses
