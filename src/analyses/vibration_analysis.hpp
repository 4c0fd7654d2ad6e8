// Forced lateral/axial/torsional response against rotary speed (method.md §9.2): the critical-speed
// map. The string is linearized about a state q (the static equilibrium: RunStaticInWell in a
// well), analyses/linearization.hpp Linearize: K = ∂R/∂q (the geometric stiffening of the axial load and
// the springs of the wall contacts closed at q; open contacts add nothing, so free parts may pass
// the wall: the paper's rule), M(q) with the fluid (model/lateral_fluid.hpp), D = ∂R/∂v plus the
// fluid damping. For every rotary speed Ω of the sweep and every excitation at its frequency ω
//   (K − ω² M(ω) + iω D(ω)) X = F,       x(t) = Re(X e^{iωt})
// is solved once per distinct frequency (every excitation at that frequency a right-hand side; the
// annulus terms at each ω when the fluid is viscous), analyses/response_solver.hpp: by default
// (method reduced) projected on a rational Krylov basis of the response to the excitations' loads
// over the band of excitation frequencies (solvers/projected_harmonic.hpp); with method direct, a
// sparse LU of the full system per frequency (the reference). Excitations (case-format.md, analyses/analysis_settings.hpp Excitation):
//  * imbalance `me` at `at`: the force m e Ω² rotating with the string at 1× (forward), i.e. the
//    lateral pair F = m e Ω² (e_y − i e_z) in the string frame at the node: Re(F e^{iΩt}) =
//    m e Ω² (cos Ωt e_y + sin Ωt e_z);
//  * bit: at the bit node at `harmonic` × Ω: a lateral force of amplitude `lateral` rotating in
//    the same sense, an axial force `axial` along the string axis and a torque `torsional` about
//    it, all in phase;
//  * motor: a lateral force `lateral` rotating at lobes × the motor's rotor speed (given by the
//    excitation's `speed`, else the motor's rev_per_volume × operation.flow_rate), at `at` (default:
//    the middle of the string's first motor); this frequency does not follow the rotary speed.
// The amplitude at a node sums the amplitudes of the responses at different frequencies (their
// peaks may coincide); excitations at one frequency are superposed in phase.
//
// Per RPM, the largest over the stations of: the lateral displacement amplitude (the major
// semi-axis of the node's orbit in the string frame's y-z plane), its ratio to the radial
// clearance at q (nodes with an open wall contact; none without a well), the bending-stress
// amplitude E (OD/2) κ of the element-mean curvature κ = (Ψ_{k+1} − Ψ_k) X_η / ℓ of each FE element
// (again the orbit's major semi-axis), and the contact-force amplitude k_n |n · X_k| at the contacts
// closed at q (normal stiffness × the amplitude of the node's radial motion).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "core/types.hpp"
#include "model/builder.hpp"
#include "model/lateral_fluid.hpp"

namespace drillflex::analyses {

struct SpeedWindow {
  double from = 0.0, to = 0.0;  // rad/s
};

inline constexpr double kQuietFactor = 1.5;

// The reduced sweep is checked against a direct solve of every load pattern at this many
// frequencies spread over the sweep; a relative error (vector norm) above the tolerance sends the
// whole sweep to the direct solver. Measured on the bundled example: 1.8 % (its amplitudes then
// within 0.3 % of the direct sweep's, docs/validation.md); on the 3 km string about its centreline
// placement (a dense spectrum with no contact and no tension) the basis misses by 1130 %, and the
// sweep runs directly.
inline constexpr int kReducedCheckPoints = 5;
inline constexpr double kReducedCheckTolerance = 0.05;

// A critical RPM with what makes it one.
struct CriticalSpeed {
  double rotary_speed = 0.0;    // rad/s
  double severity = 0.0;        // the clearance ratio there (without clearances: the displacement, m)
  double displacement = 0.0;    // the largest lateral displacement amplitude there, m
  double bending_stress = 0.0;  // the largest bending-stress amplitude there, Pa
  Index excitation = -1;         // the excitation that drives it (its response is the largest there)
  double frequency = 0.0;       // that excitation's frequency there, rad/s: the natural frequency met
};

struct VibrationResult {
  std::vector<double> rotary_speeds;             // Ω, rad/s
  std::vector<double> max_lateral_displacement;  // m
  std::vector<double> max_clearance_ratio;       // –; empty without clearances (no well)
  std::vector<double> max_bending_stress;        // Pa
  std::vector<double> max_contact_force;         // N (0 without closed contacts)
  std::vector<double> s_max_displacement;        // where the displacement peaks, m from the bit
  // The critical-speed map (analyses/critical_speeds.hpp): the peaks of the clearance ratio (of the
  // displacement without clearances), and the windows that stay below the limits.
  std::vector<double> critical_rotary_speeds;  // rad/s, ascending
  std::vector<CriticalSpeed> critical_speeds;  // the same peaks, most severe first
  std::vector<SpeedWindow> safe_windows;
  // The RPM ranges whose severity (clearance ratio, else displacement) stays within kQuietFactor of
  // the least of the sweep: where to drill when no window is safe.
  std::vector<SpeedWindow> quietest_windows;
  double clearance_fraction = 0.0;   // the limits used (VibrationSettings)
  double stress_limit = 0.0;         // Pa
  int closed_contacts = 0;           // wall contacts closed at q (springs of the linear model)
  std::vector<double> excitation_frequencies;  // ω of each excitation at the first RPM, rad/s
  // Per excitation (in the settings' order), per RPM: the largest station displacement amplitude of
  // the response at that excitation's frequency, m (excitations at the same frequency there share
  // one response: each gets its sum). The map's one curve per excitation.
  std::vector<std::vector<double>> excitation_displacement;
  VibrationMethod method = VibrationMethod::Reduced;  // how the sweep was solved
  Index basis_size = 0;  // reduced: the columns of the basis
  // Reduced: the largest relative error of the reduced response against the direct one at the
  // check frequencies (above kReducedCheckTolerance the sweep is solved directly instead).
  double reduced_check_error = 0.0;
  // Reduced: the undamped modes (of K and the reference mass) between the sweep's lowest and highest
  // excitation frequencies; -1 when the count failed (a shift on an eigenvalue).
  int band_modes = -1;
  std::string method_note;  // why a reduced request was solved directly
};

// The excitation frequency ω (rad/s) of an excitation at rotary speed Ω; `motor_speed` is the
// rotor speed (rad/s) for a motor excitation.
double ExcitationFrequency(const Excitation& excitation, double rotary_speed, double motor_speed);

// An excitation as an engineer names it: "imbalance 1×", "bit 3×", "motor".
std::string ExcitationName(const Excitation& excitation);

// The rotor speed of a motor excitation (rad/s): its `speed`, else rev_per_volume × flow rate of the
// string's first motor. Throws InputError (key path analyses.vibration.excitations[index]) when
// neither is known, or when there is no motor to take the lobes or place from.
double MotorSpeed(const Excitation& excitation, const model::ModelInput& input, Index index);

// The excitations of a vibration analysis whose case gives none (docs/case-format.md "Vibration"): a mass
// imbalance of kDefaultImbalance at 1× at the middle of the string's first MWD or LWD, else of its BHA
// (the components below its first drill pipe or HWDP; the whole string without one), and the bit's
// 3× (a tricone's three-lobed bottom, a PDC's blade pattern) with kDefaultBit* amplitudes.
inline constexpr double kDefaultImbalance = 0.02;            // kg·m (1.74 lb·in)
inline constexpr double kDefaultBitLateral = 2224.1108;       // N (500 lbf)
inline constexpr double kDefaultBitAxial = 4448.2216;         // N (1000 lbf)
inline constexpr double kDefaultBitTorsional = 271.16359;     // N·m (200 ft·lbf)
std::vector<Excitation> DefaultExcitations(const model::StringConfig& string);

// Runs the sweep about q. `input` is what `built` was built from (the string, the motor's data,
// the operation). Throws SolverError when a frequency hits an undamped resonance, InputError for
// an excitation the string cannot take (see MotorSpeed).
VibrationResult RunVibration(const model::BuiltModel& built, const model::ModelInput& input,
                             const model::LateralFluid& fluid, const VecX& q, const VibrationSettings& settings);

}  // namespace drillflex::analyses
