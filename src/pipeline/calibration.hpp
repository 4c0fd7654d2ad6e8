// Calibration of the torque-and-drag model to the rig's readings (`drillflex calibrate`): the open- and
// cased-hole friction factors, the hook-load offset (the travelling equipment the rig's hook load
// includes) and the bit's torque coefficient μ_b (TOB = μ_b · WOB · D_bit / 3) that make the model of
// the readings (pipeline/readings_model.hpp) match them in the least-squares sense.
//
// Method: Levenberg–Marquardt (Marquardt 1963; Nocedal & Wright, Numerical Optimization §10.3) on the
// residuals r_i = (model_i(p) − reading_i) / σ_c, σ_c each channel's scatter (hook load, torque):
// first the readings' own, by the von Neumann successive-difference estimate over the readings sorted
// by depth (σ² = Σ (y_{i+1} − y_i)² / 2(n − 1), blind to a smooth trend), then the fit's residual RMS of
// each channel, refitted once with those weights. The Jacobian: ∂hook load/∂offset = 1 and ∂torque/∂μ_b
// = WOB D_bit / 3 exactly (linear), the frictions' columns by forward differences (h = 0.005) on the
// model, which starts each evaluation from the last one's equilibria. The frictions are kept in [0, 1.5].
//
// Uncertainty: the covariance C = (JᵀWJ)⁻¹ at the optimum (W the final channel weights, so that the
// reduced χ² is about 1), the 95 % interval p ± t₀.₉₇₅(n − k) √C_kk (Student's t), the correlation
// C_jk / √(C_jj C_kk). A parameter the readings do not move (its column zero: no readings in cased hole
// for its friction, no torque for μ_b) is left out with a warning, or refused when asked by name; a pair
// correlated beyond ±0.95 is named in a warning (the readings cannot tell them apart).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "io/case.hpp"
#include "io/result_files.hpp"
#include "io/rig_readings.hpp"
#include "pipeline/readings_model.hpp"

namespace drillflex::pipeline {

enum class CalibrationParameter { kOpenHoleFriction, kCasedHoleFriction, kHookLoadOffset, kBitTorqueCoefficient };
// "open_hole_friction", "cased_hole_friction", "hook_load_offset", "bit_torque_coefficient".
const char* CalibrationParameterName(CalibrationParameter parameter);
// The parameter of a name; none for an unknown one.
std::optional<CalibrationParameter> CalibrationParameterOf(const std::string& name);

struct CalibrationSettings {
  // The parameters to fit; empty: all four, those the readings cannot determine left out.
  std::vector<CalibrationParameter> fit;
  ReadingsModelOptions model;  // stiff or soft, jobs, the roadmap's trip speed and stiff length
  int max_iterations = 30;
  // After each model evaluation: what it was for ("start", "iteration 3", ...), the cost.
  std::function<void(const std::string&)> log;
};

struct FittedParameter {
  CalibrationParameter parameter = CalibrationParameter::kOpenHoleFriction;
  bool fitted = false;       // false: held at its value (the case's), not fitted
  double value = 0.0;        // SI (N for the offset)
  double standard_error = 0.0;
  double low = 0.0, high = 0.0;  // the 95 % interval
  std::string note;          // why it was not fitted, or ""
};

struct ReadingResidual {
  const io::RigReading* reading = nullptr;
  ModelledReading modelled;
  double hook_load_residual = 0.0;  // model − reading, N (NaN when the run failed)
  double torque_residual = 0.0;     // N·m (NaN without a torque reading or when the run failed)
};

struct CalibrationResult {
  std::vector<FittedParameter> parameters;  // the four, in CalibrationParameter's order
  std::vector<CalibrationParameter> fitted; // the order of the correlation's rows
  Eigen::MatrixXd correlation;
  std::vector<ReadingResidual> residuals;   // every reading, in the readings' order
  double hook_load_rms = 0.0;               // N, over the readings modelled
  double torque_rms = 0.0;                  // N·m
  double hook_load_scatter = 0.0;           // σ of the weights, N
  double torque_scatter = 0.0;              // N·m
  int hook_load_count = 0, torque_count = 0;
  int iterations = 0;
  int evaluations = 0;                      // of the whole readings model
  bool converged = false;
  std::vector<std::string> warnings;
  ReadingsModelKind model = ReadingsModelKind::kStiff;
  double bit_diameter = 0.0;                // m
};

// Fits `settings.fit` to `readings`. Throws InputError (the readings file) for a parameter asked by
// name that the readings cannot determine, or fewer readings than parameters; SolverError when the
// model fails at more than half the readings.
CalibrationResult Calibrate(const io::Case& c, const io::RigReadings& readings, const CalibrationSettings& settings);

// results.json (`calibration`: each parameter's value, 95 % interval, standard error, whether it was
// fitted and why not; the correlation; the residuals' RMS; the readings with the fitted model's values;
// hook_load_offset in the case's force unit), calibration.csv (a row a reading: read, modelled,
// residual) and report.html with the fitted broomstick and the residuals against depth when `report`.
io::ResultFiles ComposeCalibrationFiles(const io::Case& c, const io::RigReadings& readings,
                                        const CalibrationResult& result, const std::string& directory, bool report,
                                        double run_seconds);

// Student's t quantile at p = 0.975 (a two-sided 95 % interval) for `dof` ≥ 1 degrees of freedom: the
// tabulated values to 10, beyond them the Cornish–Fisher expansion about the normal quantile
// (Abramowitz & Stegun 26.7.5, four terms).
double StudentQuantile975(int dof);

}  // namespace drillflex::pipeline
