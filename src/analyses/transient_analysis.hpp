// Transient dynamics (method.md §9.4): the full nonlinear model integrated in time by the
// generalized-α method (solvers/generalized_alpha.hpp), from the static equilibrium (or the
// undeformed placement), sampled every output_interval: the surface and bit quantities and, at each
// probe, the lateral displacement, whirl angle, contact force and bending moment.
//
// Signals (SI; string frame x up-hole, y right, z high side; case-format.md "Frames and signs"):
//  * surface / bit speed: the spin rate −ω_x of the top / bit node about the string axis, rad/s
//    (clockwise looking down-hole positive, as a drilling engineer reads RPM);
//  * surface torque, hook load: the torque (−M_x: clockwise positive) and axial force (tension
//    positive) in the string at its top node; WOB: the compression at the bit node (−axial force),
//    TOB: the torque there (−M_x) (model/internal_forces.hpp, the elastic section forces at the
//    state: at an end node those of its element, i.e. the section half an element in); with a top
//    drive the surface torque is the drive's, with a block the hook load is the block's force;
//  * at a probe (the string station nearest the given distance from the bit): the lateral
//    displacement (u_y, u_z) from the undeformed placement, which in a well is the hole's axis; the
//    whirl angle, the direction of the offset from the hole axis (with a well, wall_offsets.hpp) or
//    of (u_y, u_z), measured from the high side toward the right, in [0, 2π); the wall contact's
//    normal force at the node at (q, v) (damping included; 0 without a contact); the bending
//    moment magnitude;
//  * the energies of SystemModel::ComputeEnergies (kinetic; strain plus force-element potential).
// The drives (model/drives.hpp, TransientSettings::top_drive and ::block) act at the top node; the
// case's other loads and supports act as they do in statics, constant in time. The wall friction
// follows the state's sliding velocity (never a static analysis's prescribed sliding). Speeds and
// torques are positive clockwise looking down-hole (model/drives.hpp): the surface torque turns the
// string clockwise while drilling, the TOB is the torque the string delivers to the bit (the
// formation's resistance, `operation.torque_on_bit`, at rest).
#pragma once

#include <functional>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "cms/reduction_cache.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"
#include "solvers/generalized_alpha.hpp"

namespace drillflex::analyses {

struct ProbeSample {
  double lateral_y = 0.0;       // m, string frame (right)
  double lateral_z = 0.0;       // m, string frame (high side)
  double whirl_angle = 0.0;     // rad, from the high side toward the right, [0, 2π)
  double contact_force = 0.0;   // N, wall normal force
  double bending_moment = 0.0;  // N·m, magnitude
};

struct TransientSample {
  double time = 0.0;            // s
  double surface_speed = 0.0;   // rad/s, clockwise looking down-hole
  double surface_torque = 0.0;  // N·m, clockwise looking down-hole (the top drive's, if any)
  double hook_load = 0.0;       // N, tension at the top (the block's force, if any)
  double bit_speed = 0.0;       // rad/s, clockwise looking down-hole
  double weight_on_bit = 0.0;   // N, compression at the bit
  double torque_on_bit = 0.0;   // N·m, the torque the string delivers to the bit (clockwise)
  double kinetic_energy = 0.0;    // J
  double potential_energy = 0.0;  // J, strain energy plus the force elements'
  std::vector<ProbeSample> probes;  // in the order of TransientSettings::probes
};

struct TransientResult {
  std::vector<double> probe_s;          // m, the stations the probes read (nearest to the asked s)
  std::vector<TransientSample> samples;  // t = 0, output_interval, ..., duration
  VecX final_q, final_v;                 // the state at t = duration
  // The whole string's positions at some of the samples (TransientSettings::state_frames): every
  // k-th sample from t = 0 and the last (k = ⌈(samples − 1) / (state_frames − 1)⌉, so at most
  // state_frames; one frame: the last only). frame_q.back() is final_q. Empty when state_frames = 0.
  std::vector<double> frame_times;  // s, ascending
  std::vector<VecX> frame_q;        // one per frame_times
  double energy_drift = 0.0;   // max |E(t) − E(0)| / max(|E(0)|, max T), over the samples
  solvers::GeneralizedAlphaStatistics statistics;
  double rho_infinity = 0.8;
};

// Called after every accepted step with the time reached and the duration (s).
using TransientProgress = std::function<void(double time, double duration)>;
// Called at every output sample, t = 0 first, with its time (s) and the state (q, v) there: what a
// caller reads from the whole string at each sample (the string's limits: analyses/limits_envelope.hpp).
using TransientSampleObserver = std::function<void(double time, const VecX& q, const VecX& v)>;

// The model a transient run integrates: the case's `input` with the settings' drives and bit-rock
// law, and without a static analysis's prescribed sliding (the friction follows the motion). Same
// coordinates. The bit-rock law (model/bit_rock.hpp) takes over from the operation's torque on bit
// (and under Detournay's law its WOB), which then act in the start equilibrium only. With a `fluid`,
// the fluid moves with the bodies sideways (model/fluid_inertia.hpp), the annulus's C_m and C_v
// taken at `fluid_frequency` (rad/s; TransientFluidFrequency).
model::ModelInput TransientModelInput(const model::ModelInput& input, const TransientSettings& settings,
                                      double fluid_frequency);

// The circular frequency (rad/s) at which a transient takes the annulus's frequency-dependent
// added mass C_m(ω) and damping C_v(ω) (Chen, Wambsganss & Jendrzejczyk 1976; fe/annulus_fluid.hpp):
//  * the transient's `fluid_frequency`, when given;
//  * 0 when they do not depend on ω (no fluid, an inviscid one, or a given added_mass_coefficient:
//    then there is no annulus damping, model/lateral_fluid.hpp);
//  * else the lowest lateral natural frequency of the linearized model `at_rest` at q0 with the
//    fluid (analyses/modes_analysis.hpp RunModes, FirstLateralMode: the frequency a free lateral
//    vibration rings at, where a linear analysis would take them). A whirl or a forced vibration at
//    another frequency is better served by giving it. Throws SolverError without a lateral mode.
double TransientFluidFrequency(const model::ModelInput& input, const model::BuiltModel& at_rest, const VecX& q0,
                               const TransientSettings& settings);

// The start state q: the static equilibrium of the case's model at rest (without prescribed
// sliding; the supports hold the top, the drives start from it) with `initial_loads` added (solved
// by RunStaticInWell on the case's model with its initial-load group switched on: `input` must carry
// them as its initial_loads, model/builder.hpp), or the reference placement (start: reference).
// Throws SolverError when the statics fail.
VecX TransientStartPositions(const model::ModelInput& input, const model::BuiltModel& built,
                             const TransientSettings& settings, const StaticSettings& static_settings);

// Integrates `built` from (q0, v = 0) over settings.duration, `on_sample` (if any) called at each
// output sample. Throws SolverError (with the time and reason) when a step cannot be completed.
TransientResult RunTransient(const model::BuiltModel& built, const VecX& q0, const TransientSettings& settings,
                             const TransientProgress& progress = {}, const TransientSampleObserver& on_sample = {});

// The integrator options a TransientSettings asks for: fixed steps of time_step, or adaptive steps
// (starting at min(output_interval, 1e-4 s)) at the relative tolerance.
solvers::GeneralizedAlphaOptions TransientIntegratorOptions(const TransientSettings& settings);

}  // namespace drillflex::analyses
