// What each analysis is asked to do, as a case describes it: plain data in SI.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/bit_rock.hpp"
#include "model/drives.hpp"
#include "model/string_config.hpp"

namespace drillflex::analyses {

// How the static equilibrium is found: the chain of strategies of analyses/static_solve.hpp (from a
// neighbour, the energy's minimum with the friction continued, load stepping: case key `method: newton`,
// the default), or dynamic relaxation alone (`method: relaxation`).
enum class StaticMethod { StrategyChain, DynamicRelaxation };
struct StaticSettings {
  StaticMethod method = StaticMethod::StrategyChain;
  int max_iterations = 200;
  // Where the MWD's inclination sensor sits, m from the bit (analyses/mwd_sag.hpp); none: the middle of
  // the string's first MWD component.
  std::optional<double> mwd_at;
  // Where the solver's progress goes (one line per stage and Newton iteration); none when empty.
  std::function<void(const std::string&)> log;
};

enum class ModeKind { All, Lateral, Axial, Torsional };
// Rotary speeds of a Campbell diagram: from, from + step, … up to `to` (rad/s).
struct SpeedRange {
  double from = 0.0, to = 0.0, step = 0.0;
};

struct ModesSettings {
  int count = 10;
  ModeKind kind = ModeKind::All;
  // The gyroscopic terms of the string spinning at `rotary_speed` (analyses/gyroscopic_modes.hpp).
  bool gyroscopic = false;
  double rotary_speed = 0.0;  // rad/s, clockwise looking down-hole: operation.rpm
  // The frequencies against the rotary speed (needs `gyroscopic`).
  std::optional<SpeedRange> campbell;
};

enum class ExcitationType { Imbalance, Bit, Motor };
struct Excitation {
  ExcitationType type = ExcitationType::Imbalance;
  double at = 0.0;          // m from the bit (imbalance)
  double imbalance = 0.0;   // kg·m (m·e)
  int harmonic = 1;         // multiple of the rotary speed (bit: blades or cones)
  double lateral = 0.0;     // N
  double axial = 0.0;       // N
  double torsional = 0.0;   // N·m
  int lobes = 0;            // motor rotor lobes (0: the motor component's)
  std::optional<double> motor_speed;  // rad/s, motor rotor speed (default: rev_per_volume × flow rate)
  int source_line = 0;
};

// How the sweep solves (K − ω²M(ω) + iωD(ω)) X = F (analyses/vibration_analysis.hpp): projected on a
// basis of the response to its loads over the band (solvers/projected_harmonic.hpp), or on the
// full sparse system at every frequency (the reference).
enum class VibrationMethod { Reduced, Direct };

struct VibrationSettings {
  VibrationMethod method = VibrationMethod::Reduced;
  // Reduced: the basis's expansion frequencies over the excitation band and block steps at each
  // (solvers::KrylovBasisOptions).
  int basis_shifts = 20;
  int basis_depth = 2;
  double speed_from = 20.0 * kPi / 30.0;  // rad/s
  double speed_to = 250.0 * kPi / 30.0;   // rad/s
  double speed_step = 1.0 * kPi / 30.0;   // rad/s
  std::vector<Excitation> excitations;
  // Safe windows (analyses/critical_speeds.hpp): the lateral displacement amplitude stays below
  // this fraction of the radial clearance, and the bending-stress amplitude below the limit.
  double clearance_fraction = 0.5;
  double stress_limit = 10000.0 * 6894.757293168;  // Pa (10 ksi): a screening value, set your own
};

// Which loads the buckling multiplier scales (case key analyses.buckling.scale).
enum class BucklingScale {
  Automatic,  // the WOB when the case has one, else every load
  Wob,        // the weight on bit alone; the weight, the fluid and the other loads stay as they are
  AllLoads,   // every load: weight, WOB, torque, the case's loads
};
struct BucklingSettings {
  BucklingScale scale = BucklingScale::Automatic;
  int modes = 1;  // buckling modes reported
  // The frequency-against-load method (the paper's Figure 5) beside the eigenproblem.
  bool frequency_method = true;
  int frequency_points = 4;  // load levels in the first f² sweep (refined near the estimate)
};

// Where a transient run starts (analyses/transient_analysis.hpp).
enum class TransientStart {
  Equilibrium,  // the static equilibrium under the case's loads plus `initial_loads`
  Reference,    // the undeformed placement, at rest
};
struct TransientSettings {
  double duration = 1.0;          // s
  double output_interval = 0.01;  // s
  std::vector<double> probes;     // m from the bit
  std::optional<double> time_step;  // s; fixed steps of this size; default adaptive
  double rho_infinity = 0.8;      // generalized-α spectral radius at ωh → ∞ (1: no numerical damping)
  double tolerance = 1e-4;        // relative local error per step (solvers/generalized_alpha.hpp)
  TransientStart start = TransientStart::Equilibrium;
  // Loads (string frame, as `loads`) that act in the start equilibrium only and are removed at
  // t = 0: a string released from a deflected shape (free vibration).
  std::vector<model::Load> initial_loads;
  // The rock's reaction on the bit as a law of its motion (model/bit_rock.hpp); it takes over from
  // the case's torque on bit (and, for Detournay's law, the WOB), which then act in the start
  // equilibrium only (analyses/transient_analysis.hpp, TransientModelInput).
  std::optional<model::BitRockParameters> bit_rock;
  // The drives at the top (model/drives.hpp); none: the supports hold the top as in statics.
  std::optional<model::TopDrive> top_drive;
  std::optional<model::BlockDrive> block;
  // Imbalances turning with the string (`excitations` of type imbalance, as in the vibration
  // analysis: model/imbalance_element.hpp).
  std::vector<model::Imbalance> imbalances;
  // How many frames of the whole string's state (its positions q) to keep, evenly spread over the
  // output samples, t = 0 and the last among them (TransientResult::frame_q; 0: none, the memory
  // of a run as without frames). Set by the command line (a VTK frame series, io/vtk_files.hpp).
  int state_frames = 0;
  // The case's `vtk_frames` when it gives one (io/analyses_section.cpp): the frames the command line
  // asks for, instead of its default, when it writes the VTK files. RunTransient reads state_frames only.
  std::optional<int> vtk_frames;
  // The circular frequency at which the annulus fluid's C_m(ω) and C_v(ω) are taken (`fluid_frequency`
  // in Hz in the case), rad/s; unset: analyses/transient_analysis.hpp TransientFluidFrequency's default.
  std::optional<double> fluid_frequency;
};

// Which model a roadmap runs: the stiff string (the case's bodies, contacts and buckling), the soft
// string (Johancsik: analyses/soft_string.hpp, the engineer's familiar cross-check), or both.
enum class RoadmapModel { Stiff, Soft, Both };

// The torque-and-drag roadmap (`drillflex roadmap`, pipeline/roadmap.hpp): bit depths from `from_md`
// down to the case's bit MD at `step`, each friction factor at each depth. A zero or empty member
// takes its default (pipeline::CompleteRoadmapSettings).
struct RoadmapSettings {
  double from_md = 0.0;           // m: the first bit depth; 0: a tenth of the way, or where the string fits
  double step = 0.0;              // m; 0: ten depths in all
  std::vector<double> friction;   // the friction factors (axial and around the string alike); empty:
                                  // the case's and 0.1 either side. They are the open hole's: in the
                                  // well.hole sections marked `cased`,
  std::optional<double> cased_friction = std::nullopt;  // this factor at every line; none: each cased section's own
                                         // (its `friction`, else the case's model.contact)
  double rotary_speed = 0.0;      // rad/s off and on bottom; 0: the case's rpm, else 60 rpm
  double trip_speed = 0.3048;     // m/s pulling out and running in (> 0; the friction is Coulomb, so
                                  // above its regularization velocity only its sign counts)
  RoadmapModel model = RoadmapModel::Stiff;
  // The stiff model's length of string from the bit, m: the case's string cut to it, or its top
  // component repeated up to it; the pipe above, to the surface, by the soft string (Johancsik, the
  // rotating string climbing the wall) from the stiff part's top tension and torque. 0: the case's
  // own string (what the case models stiff); infinity (`surface` in the case): the whole string.
  double stiff_length = 0.0;
};

// The analyses a plain `run` performs, in the order static, modes, vibration, buckling, transient.
// `roadmap` holds the settings of `drillflex roadmap` (a sweep of statics, not run by `run`).
// The bit's steerability by default: 0.25, the top of MADSim's example range (5–25 %); at 0.05 the bit's
// tilt outweighs its side force and a 45 ft pendulum at 30° builds (docs/method.md "Directional
// tendency"), where every pendulum drops. Set the bit's own where it is known.
inline constexpr double kDefaultSteerability = 0.25;

// A rotary steerable system (case key analyses.tendency.rss). Its housing holds the toolface still in
// space while the string turns; it steers a fraction `steer` of the time (the duty cycle: 0 neutral, 1
// full steer). Push-the-bit: pads at `at` push the bit toward the toolface with `force`. Point-the-bit
// (analyses/point_the_bit.hpp): the drive shaft, deflected between the fulcrum bearing at `at` and a
// cam above it, tilts the bit's axis by `offset` against the tool's toward the toolface.
enum class RssType { Push, Point };

// The largest point-the-bit offset the case may ask: the tools' are 0.2–1.2 deg.
inline constexpr double kMaxRssOffset = 3.0 * kDegree;  // rad

struct RssSettings {
  RssType type = RssType::Push;
  double at = 0.0;        // m from the bit: the pads (push), the fulcrum bearing (point)
  double force = 0.0;     // N: the pads' (push)
  double offset = 0.0;    // rad: the bit's axis against the tool's (point)
  double toolface = 0.0;  // rad: 0 the high side, π/2 the right
  double steer = 1.0;     // the duty cycle, 0–1
  int source_line = 0;
};

// The formation's anisotropy (case key analyses.tendency.formation): drillability across the bedding
// against along it, h = (D_⊥ − D_∥)/(D_⊥ + D_∥) (> 0: the bit turns toward the bedding's normal, the
// "updip" tendency), and the bedding's dip and the azimuth it dips toward.
struct FormationSettings {
  double anisotropy = 0.0;   // h, −1 < h < 1
  double dip = 0.0;          // rad, 0 horizontal beds
  double dip_azimuth = 0.0;  // rad, the direction the beds dip toward
};

// What a directional tendency is asked (case key analyses.tendency; analyses/tendency_analysis.hpp).
struct TendencySettings {
  double steerability = kDefaultSteerability;  // S ≥ 0: lateral over axial drillability (1e6: zero side force)
  // The steady rates also against WOB, inclination and the stabilizers' gauge
  // (analyses/tendency_sensitivity.hpp): ten more tendencies.
  bool sensitivities = false;
  std::optional<RssSettings> rss;
  std::optional<FormationSettings> formation;
};

struct AnalysesConfig {
  std::optional<StaticSettings> static_analysis;
  std::optional<ModesSettings> modes;
  std::optional<VibrationSettings> vibration;
  std::optional<BucklingSettings> buckling;
  std::optional<TransientSettings> transient;
  std::optional<RoadmapSettings> roadmap;
  std::optional<TendencySettings> tendency;
};

}  // namespace drillflex::analyses
