// Linear vibration modes (method.md §9.2) about a state q: K = ∂R/∂q at q (v = a = 0, load
// factor 1: the geometric stiffening of the loads in that state is included), M = M(q)
// (analyses/linearization.hpp Linearize); K x = ω² M x (solvers::SolveModes: dense, or sparse
// Lanczos for large models). Each mode is classified by the split of its kinetic energy ½ xᵀ M x
// over the nodes into axial, torsional and lateral parts.
#pragma once

#include <vector>

#include "analyses/analysis_settings.hpp"
#include "analyses/linearization.hpp"
#include "analyses/string_stations.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"
#include "model/lateral_fluid.hpp"
#include "solvers/eigen.hpp"

namespace drillflex::analyses {

// The whirl of a mode about a spinning string: forward (its lateral orbits turn with the spin),
// backward, planar (|whirl_index| ≤ kPlanarWhirlIndex: orbits nearly lines), or none (no gyroscopic
// analysis, or an axial or torsional mode).
enum class Whirl { None, Forward, Backward, Planar };
inline constexpr double kPlanarWhirlIndex = 0.05;
const char* WhirlName(Whirl whirl);

struct ModeResult {
  double frequency_hz = 0.0;     // 0 for a rigid-body mode
  double eigenvalue = 0.0;       // ω², rad²/s²
  // ζ = ζ_s + φᵀ D φ / (2 ω φᵀ M φ) of the undamped mode φ: the case's structural damping ratio
  // ζ_s (a loss factor 2ζ_s on K, analyses/vibration_analysis.hpp) plus the viscous damping D at
  // ω (the bodies' modal damping, couplings, supports, contacts, fluid); 0 for a rigid-body mode.
  // First order in D (exact for proportional damping). See ComputeModes for the fluid.
  double damping_ratio = 0.0;
  ModeKind kind = ModeKind::Lateral;  // the dominant family (never All)
  // Kinetic-energy fractions (sum 1): translation along the string axis, rotation about it, rest.
  double axial_fraction = 0.0, torsional_fraction = 0.0, lateral_fraction = 0.0;
  bool rigid_body = false;       // one of the CountRigidBodyModes lowest |ω²| (unsupported directions)
  // ω² < 0 (reported with frequency 0): the linearized stiffness is negative along the mode. At a
  // static equilibrium in a well these come from the wall friction's tangent (μ × the normal
  // stiffness, non-symmetric, symmetrized by Linearize): the bundled example has 33, none with
  // `friction: 0` (docs/validation.md, issue 5 modes). Not a vibration mode; no critical speed.
  bool negative_stiffness = false;
  // Rigid, or 0 ≤ f < kNearZeroFrequencyHz: a motion the linearized string barely resists.
  bool near_zero = false;
  // With the gyroscopic terms (analyses/gyroscopic_modes.hpp): the whirl of the mode's lateral orbits
  // against the spin, whirl_index = −Σ 2 Im(Y Z̄) / Σ (|Y|² + |Z|²) over the stations, Y and Z the
  // complex amplitudes of the string-frame y and z displacement (Σ 2 Im(Y Z̄) > 0: the orbits turn
  // about +x; the spin turns about −x, clockwise looking down-hole): +1 circular forward, −1
  // circular backward.
  Whirl whirl = Whirl::None;
  double whirl_index = 0.0;
  // Shape per station (ModesResult::s), string frame, scaled so that max |displacement| = 1
  // (rotations by the same factor; a purely torsional mode: max |rotation| = 1).
  std::vector<Vec3> displacement;
  std::vector<Vec3> rotation;
  VecX vector;                   // the mode in the velocity coordinates, M-normalised
};

struct ModesResult {
  std::vector<double> s;          // stations (analyses/string_stations.hpp), m
  // Sorted by ω² (a negative ω² of an unstable state comes first, with frequency 0). Kind All
  // includes the rigid-body modes (frequency 0, rigid_body set); a family excludes them.
  std::vector<ModeResult> modes;
  Index rigid_body_modes = 0;       // how many of `modes` are rigid-body modes
  Index near_zero_modes = 0;        // how many are near zero (ModeResult::near_zero, rigid ones included)
  Index negative_stiffness_modes = 0;  // how many have ω² < 0
  // With the gyroscopic terms (analyses/gyroscopic_modes.hpp): at this spin (rad/s), on a basis of
  // this many undamped modes; the modes then carry their whirl.
  bool gyroscopic = false;
  double rotary_speed = 0.0;
  Index basis_size = 0;
};

// A mode below this is near zero: no rotary speed of a drilling sweep meets it at any harmonic (0.6
// rpm at 1×), so it is no critical speed; it is reported, flagged, not hidden.
inline constexpr double kNearZeroFrequencyHz = 0.01;

// The lowest lateral mode that is neither near zero nor of negative stiffness (the one a rotary speed meets first at 1×); null
// without one.
const ModeResult* FirstLateralMode(const ModesResult& result);

const char* ModeKindName(ModeKind kind);

// Without the gyroscopic terms: `settings.gyroscopic` is ComputeGyroscopicModes' (analyses/gyroscopic_modes.hpp).
// The `count` lowest modes (kind All), or the `count` lowest modes of one family (Lateral,
// Axial, Torsional: more modes are solved progressively until enough are found, at most
// kMaxModesSearched). Axial and torsional modes are first sought with every node's lateral
// translation held by stiff springs (the bending modes pushed far up, so the lowest modes are the
// family's): kept when each also satisfies the free system to 1e-6 (uncoupled families: a straight
// string), else the full progressive search. Throws SolverError if the eigen solver fails.
//
// Drilling fluid (`fluid`, model/lateral_fluid.hpp): its lateral mass joins M. The eigenproblem
// is solved with the annulus added mass at its inviscid C_m (or the case's override); with a
// viscous fluid each reported mode's frequency is then corrected for the frequency-dependent
// C_m(ω) by the fixed point of the Rayleigh quotient ω² = φᵀKφ / φᵀ(M_s + M_f(ω))φ on the shape φ
// found with the inviscid mass (the shape's change with C_m is neglected: the added mass is close
// to proportional to the steel's along a uniform section), and its damping ratio includes the
// fluid damping C_v(ω) at that ω.
ModesResult RunModes(const model::BuiltModel& built, const VecX& q, const ModesSettings& settings,
                     const model::LateralFluid* fluid = nullptr);

// The same on a bare system model at a given load factor (buckling's frequency method).
ModesResult ComputeModes(const model::SystemModel& model, const VecX& q, const ModesSettings& settings,
                         double load_factor = 1.0, const model::LateralFluid* fluid = nullptr);

inline constexpr Index kMaxModesSearched = 400;

// Kinetic energy ½ vᵀ M v of a velocity field v split into its axial, torsional and lateral parts
// (lumped nodal masses and rotary inertias; the fluid is not counted).
struct EnergySplit {
  double axial = 0.0, torsional = 0.0, lateral = 0.0;
};
EnergySplit SplitKineticEnergy(const model::SystemModel& model, const std::vector<model::BodyPose>& poses,
                               const VecX& v);

// Fills mode.displacement and mode.rotation per station from mode.vector (see ModeResult).
void FillShape(const model::SystemModel& model, const std::vector<model::BodyPose>& poses,
               const std::vector<Station>& stations, ModeResult& mode);

// The `count` lowest modes of K x = ω² M x (ascending, M-normalised): solvers::SolveModes.
solvers::ModalResult LowestModes(const LinearizedSystem& system, int count);

// The number of rigid-body modes of the linearized system at q: the rigid motions of the whole
// string (translation t, rotation θ about its centroid c: ṙ_b = t + θ × (r_b − c), ω_b = A_bᵀ θ,
// η̇ = 0, exact also for a deformed string) that the stiffness does not resist, i.e. the
// eigenvalues μ of Vᵀ K V x = μ Vᵀ M V x (6 × 6) below 1e-9 max_i(K_ii/M_ii). A restrained rigid
// motion has μ of the order of a support stiffness over the string's mass, a free one μ at the
// round-off level ε max_i(K_ii/M_ii): both are orders of magnitude from the threshold, whereas
// the computed ω² of a free mode (round-off ~1e-3 Hz with the stiff couplings) could not be told
// from a slow elastic one (a long string under tension: ~0.03 Hz).
Index CountRigidBodyModes(const model::SystemModel& model, const VecX& q, const LinearizedSystem& system);

}  // namespace drillflex::analyses
