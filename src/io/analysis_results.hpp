// Results of the analyses into results.json and CSV tables, in the output units of the case
// (case-format.md "Results"). Forces in N | lbf, moments in N·m | ft·lbf, stresses in Pa | psi,
// positions along the string in m | ft, displacements in m | in, angles in degrees.
#pragma once

#include "analyses/buckling_analysis.hpp"
#include "analyses/gyroscopic_modes.hpp"
#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/tendency_analysis.hpp"
#include "analyses/transient_analysis.hpp"
#include "analyses/string_limits.hpp"
#include "analyses/vibration_analysis.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"
#include "model/builder.hpp"

namespace drillflex::io {

// "case", "units", "model": {bodies, coordinates, contacts, ...} and "column_units".
void AddCaseHeader(const Case& c, const model::BuiltModel& built, ResultFiles& files);
// "operation": the WOB the analyses apply (the case's, or what its surface hook load leaves) and,
// with operation.hook_load, the hook load and the string above the model's weight along the hole.
void AddOperation(const Case& c, const model::ModelInput& input, ResultFiles& files);
// "static" and static.csv (one row per station), static_reactions in the JSON. With a well each
// station adds its place in the hole (analyses/wall_offsets.hpp; its md is then the contact's) and
// the bit its tendency in words (analyses/bit_tendency.hpp); contacts.csv lists the wall contacts.
void AddStaticResults(const Case& c, const analyses::StaticResult& result, ResultFiles& files);
// "modes" and modes.csv (frequencies), mode_shapes.csv (per mode and station).
void AddModesResults(const Case& c, const analyses::ModesResult& result, ResultFiles& files);
// "campbell" {rpm, modes per speed, synchronous} and campbell.csv (one row per speed and mode).
void AddCampbellResults(const Case& c, const analyses::CampbellResult& result, ResultFiles& files);
// "buckling" and buckling.csv (frequency against load).
void AddBucklingResults(const Case& c, const analyses::BucklingResult& result, ResultFiles& files);

// "tendency" (case-format.md: build_rate, turn_rate in deg/100 ft | deg/30 m, the bit's side forces
// and tilts at the steady curvature) and tendency.csv (every static of the search).
void AddTendencyResults(const Case& c, const analyses::TendencyResult& result, ResultFiles& files);

// "vibration" (case-format.md: rpm, max_lateral_displacement, max_bending_stress, max_contact_force,
// critical_rpm, safe_windows, ...) and vibration.csv (one row per RPM).
void AddVibrationResults(const Case& c, const analyses::VibrationResult& result, ResultFiles& files);

// "transient" (the integration's figures, the probes' places, the final state) and transient.csv (one
// row per output sample: time, surface RPM and torque, hook load, bit RPM, WOB, TOB, energies, and
// per probe the lateral displacement, whirl angle, contact force and bending moment).
void AddTransientResults(const Case& c, const analyses::TransientResult& result, ResultFiles& files);

// The field rule of thumb for the critical rotary speed of a tube span (validation.md V6):
// 33,055 sqrt(OD² + ID²)/L² rpm (in, ft), for the longest component's OD and ID over the span
// between the outermost lateral supports; without two of them, one tool-joint spacing of a pipe
// with joints, else the whole string.
struct RuleOfThumbSpeed {
  double rotary_speed = 0.0;    // rad/s
  double span = 0.0;            // L, m
  double outer_diameter = 0.0;  // m
  double inner_diameter = 0.0;  // m
};
RuleOfThumbSpeed ComputeRuleOfThumbCriticalSpeed(const Case& c);

// MD of a station: bit MD − s with a well, s without one (measured along the string from the bit).
double StationMd(const Case& c, double s);

// One limit's largest utilisation and where (results.json `static.limits.summary` entries: limit,
// utilisation, s, md, component), in the case's output units; null when no station has the limit.
nlohmann::json UtilisationJson(const Case& c, const analyses::LimitUtilisation& limit);

}  // namespace drillflex::io
