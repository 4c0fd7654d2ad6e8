#include "pipeline/calibration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "model/hole_friction.hpp"

namespace drillflex::pipeline {
namespace {

constexpr int kParameterCount = 4;
constexpr double kFrictionStep = 0.02;      // forward-difference step of a friction factor
constexpr double kLargestFriction = 1.5;    // the frictions are kept in [0, this]
constexpr double kStronglyCorrelated = 0.95;
// Converged when every step is below its tolerance: frictions and μ_b 1e-4, the offset 10 N.
constexpr std::array<double, kParameterCount> kTolerance{1e-4, 1e-4, 10.0, 1e-4};

using Parameters = std::array<double, kParameterCount>;  // in CalibrationParameter's order

int Index(CalibrationParameter p) { return static_cast<int>(p); }

ReadingsParameters ToModel(const Parameters& p, bool cased_given) {
  ReadingsParameters m;
  m.open_hole_friction = p[0];
  if (cased_given) m.cased_hole_friction = p[1];
  m.hook_load_offset = p[2];
  m.bit_torque_coefficient = p[3];
  return m;
}

// The readings' own scatter: von Neumann's successive differences over the readings sorted by depth
// (σ² = Σ (y_{i+1} − y_i)² / 2(n − 1)); a smooth trend with depth adds little.
double SuccessiveDifferenceScatter(std::vector<std::pair<double, double>> depth_value) {
  std::sort(depth_value.begin(), depth_value.end());
  if (depth_value.size() < 2) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 1; i < depth_value.size(); ++i) {
    const double d = depth_value[i].second - depth_value[i - 1].second;
    sum += d * d;
  }
  return std::sqrt(sum / (2.0 * static_cast<double>(depth_value.size() - 1)));
}

class Fit {
 public:
  Fit(ReadingsModel& model, const io::RigReadings& readings, std::vector<int> free, bool cased_given,
      const std::function<void(const std::string&)>& log)
      : model_(model), readings_(readings), free_(std::move(free)), cased_given_(cased_given), log_(log) {}

  // The weighted residuals of an evaluation (hook loads, then torques), NaN where a run failed.
  Eigen::VectorXd Residuals(const std::vector<ModelledReading>& modelled) const {
    const auto& rows = readings_.rows;
    Eigen::VectorXd r(2 * static_cast<Eigen::Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      r[k] = (modelled[i].hook_load - rows[i].hook_load) / hook_sigma;
      r[k + static_cast<Eigen::Index>(rows.size())] =
          rows[i].surface_torque ? (modelled[i].surface_torque - *rows[i].surface_torque) / torque_sigma : 0.0;
    }
    return r;
  }

  // Σ r² over the readings every evaluation so far modelled (a reading whose run failed anywhere is
  // left out of the comparison, so that the cost compares like with like).
  double Cost(const Eigen::VectorXd& r) const {
    double sum = 0.0;
    for (Eigen::Index k = 0; k < r.size(); ++k) {
      if (used_[static_cast<std::size_t>(k)] && std::isfinite(r[k])) sum += r[k] * r[k];
    }
    return sum;
  }

  void MarkFailures(const Eigen::VectorXd& r) {
    if (used_.empty()) used_.assign(static_cast<std::size_t>(r.size()), true);
    for (Eigen::Index k = 0; k < r.size(); ++k) {
      if (!std::isfinite(r[k])) used_[static_cast<std::size_t>(k)] = false;
    }
  }

  Eigen::VectorXd Evaluate(const Parameters& p, const std::string& what) {
    last_modelled_ = model_.Evaluate(ToModel(p, cased_given_));
    Eigen::VectorXd r = Residuals(last_modelled_);
    MarkFailures(r);
    if (log_) log_(fmt::format("calibration: {}: cost {:.6g}", what, Cost(r)));
    return r;
  }

  // The Jacobian of the weighted residuals in the free parameters at p (r = the residuals there).
  Eigen::MatrixXd Jacobian(const Parameters& p, const Eigen::VectorXd& r, const std::string& what) {
    const auto& rows = readings_.rows;
    const auto n = static_cast<Eigen::Index>(rows.size());
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(r.size(), static_cast<Eigen::Index>(free_.size()));
    for (std::size_t j = 0; j < free_.size(); ++j) {
      const int k = free_[j];
      const auto col = static_cast<Eigen::Index>(j);
      if (k == Index(CalibrationParameter::kHookLoadOffset)) {
        J.col(col).head(n).setConstant(1.0 / hook_sigma);
      } else if (k == Index(CalibrationParameter::kBitTorqueCoefficient)) {
        for (Eigen::Index i = 0; i < n; ++i) {
          const io::RigReading& reading = rows[static_cast<std::size_t>(i)];
          const bool on_bottom = reading.activity == io::RigActivity::kDrilling && reading.surface_torque;
          // TOB = μ_b WOB D / 3 reaches the surface whole (the string's twist carries it up).
          J(n + i, col) = on_bottom ? reading.weight_on_bit * model_.bit_diameter() / 3.0 / torque_sigma : 0.0;
        }
      } else {
        Parameters stepped = p;
        // Forward, or backward at the upper bound.
        const double h = p[static_cast<std::size_t>(k)] + kFrictionStep > kLargestFriction ? -kFrictionStep : kFrictionStep;
        stepped[static_cast<std::size_t>(k)] += h;
        const Eigen::VectorXd moved = Evaluate(stepped, fmt::format("{}, {} + {:g}", what,
                                                                    CalibrationParameterName(
                                                                        static_cast<CalibrationParameter>(k)),
                                                                    h));
        J.col(col) = (moved - r) / h;
      }
    }
    for (Eigen::Index i = 0; i < J.rows(); ++i) {
      if (!used_[static_cast<std::size_t>(i)] || !std::isfinite(r[i])) J.row(i).setZero();
    }
    for (Eigen::Index i = 0; i < J.rows(); ++i) {
      for (Eigen::Index j = 0; j < J.cols(); ++j) {
        if (!std::isfinite(J(i, j))) J.row(i).setZero();
      }
    }
    return J;
  }

  const std::vector<ModelledReading>& last_modelled() const { return last_modelled_; }
  const std::vector<int>& free() const { return free_; }
  void SetFree(std::vector<int> free) { free_ = std::move(free); }

  double hook_sigma = 1.0, torque_sigma = 1.0;

 private:
  ReadingsModel& model_;
  const io::RigReadings& readings_;
  std::vector<int> free_;
  bool cased_given_;
  std::function<void(const std::string&)> log_;
  std::vector<bool> used_;
  std::vector<ModelledReading> last_modelled_;
};

// Keeps the frictions inside their bounds.
void Bound(Parameters& p) {
  for (const CalibrationParameter k : {CalibrationParameter::kOpenHoleFriction, CalibrationParameter::kCasedHoleFriction}) {
    double& friction = p[static_cast<std::size_t>(Index(k))];
    friction = std::clamp(friction, 0.0, kLargestFriction);
  }
}

struct LmOutcome {
  Parameters p{};
  Eigen::VectorXd r;
  Eigen::MatrixXd J;                     // at p
  std::vector<ModelledReading> modelled;  // the readings modelled at p
  int iterations = 0;
  bool converged = false;                 // the last step was below every tolerance
};

// Levenberg–Marquardt from p (Marquardt's scaling: λ diag(JᵀJ)). Converged when a step is below every
// parameter's tolerance; it stops unconverged when ten growing λ find no step that lowers the cost, or
// after max_iterations.
LmOutcome LevenbergMarquardt(Fit& fit, Parameters p, int max_iterations, int& iterations_so_far) {
  LmOutcome out;
  Eigen::VectorXd r = fit.Evaluate(p, "start");
  out.modelled = fit.last_modelled();
  double cost = fit.Cost(r);
  double lambda = 1e-3;
  const std::vector<int>& free = fit.free();
  bool fresh_jacobian = false;  // out.J is at p
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    ++iterations_so_far;
    out.iterations = iteration;
    out.J = fit.Jacobian(p, r, fmt::format("iteration {}", iterations_so_far));
    fresh_jacobian = true;
    Eigen::VectorXd rr = r;
    for (Eigen::Index i = 0; i < rr.size(); ++i) {
      if (!std::isfinite(rr[i]) || out.J.row(i).isZero(0.0)) rr[i] = 0.0;
    }
    const Eigen::MatrixXd JtJ = out.J.transpose() * out.J;
    const Eigen::VectorXd gradient = out.J.transpose() * rr;
    bool stepped = false, small = false;
    for (int attempt = 0; attempt < 10 && !stepped; ++attempt) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal() += lambda * JtJ.diagonal().cwiseMax(1e-12);
      const Eigen::VectorXd delta = A.ldlt().solve(-gradient);
      Parameters trial = p;
      for (std::size_t j = 0; j < free.size(); ++j) trial[static_cast<std::size_t>(free[j])] += delta[static_cast<Eigen::Index>(j)];
      Bound(trial);
      small = true;
      for (std::size_t j = 0; j < free.size(); ++j) {
        const auto k = static_cast<std::size_t>(free[j]);
        if (std::abs(trial[k] - p[k]) > kTolerance[k]) small = false;
      }
      const Eigen::VectorXd r_trial = fit.Evaluate(trial, fmt::format("iteration {} step", iterations_so_far));
      const double trial_cost = fit.Cost(r_trial);
      if (trial_cost <= cost) {
        p = trial;
        r = r_trial;
        out.modelled = fit.last_modelled();
        cost = fit.Cost(r);  // failures marked since
        lambda = std::max(lambda / 3.0, 1e-9);
        stepped = true;
        fresh_jacobian = false;
      } else {
        lambda *= 4.0;
        if (small) break;  // the step is below tolerance and no better: at the minimum
      }
    }
    if (small) {
      out.converged = true;
      break;
    }
    if (!stepped) break;  // no step lowers the cost: stuck, not converged
  }
  if (!fresh_jacobian) out.J = fit.Jacobian(p, r, "the last iterate");
  out.p = p;
  out.r = r;
  return out;
}

double Rms(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  double sum = 0.0;
  for (const double v : values) sum += v * v;
  return std::sqrt(sum / static_cast<double>(values.size()));
}

}  // namespace

const char* CalibrationParameterName(CalibrationParameter parameter) {
  switch (parameter) {
    case CalibrationParameter::kOpenHoleFriction: return "open_hole_friction";
    case CalibrationParameter::kCasedHoleFriction: return "cased_hole_friction";
    case CalibrationParameter::kHookLoadOffset: return "hook_load_offset";
    case CalibrationParameter::kBitTorqueCoefficient: return "bit_torque_coefficient";
  }
  return "?";
}

std::optional<CalibrationParameter> CalibrationParameterOf(const std::string& name) {
  for (int k = 0; k < kParameterCount; ++k) {
    const auto p = static_cast<CalibrationParameter>(k);
    if (name == CalibrationParameterName(p)) return p;
  }
  return std::nullopt;
}

double StudentQuantile975(int dof) {
  static constexpr std::array<double, 10> kTable{12.706205, 4.302653, 3.182446, 2.776445, 2.570582,
                                                 2.446912,  2.364624, 2.306004, 2.262157, 2.228139};
  if (dof < 1) throw LogicError("StudentQuantile975: at least one degree of freedom");
  if (dof <= 10) return kTable[static_cast<std::size_t>(dof - 1)];
  const double z = 1.959963984540054, v = dof;
  const double z2 = z * z;
  const double g1 = (z2 + 1.0) * z / 4.0;
  const double g2 = ((5.0 * z2 + 16.0) * z2 + 3.0) * z / 96.0;
  const double g3 = (((3.0 * z2 + 19.0) * z2 + 17.0) * z2 - 15.0) * z / 384.0;
  const double g4 = ((((79.0 * z2 + 776.0) * z2 + 1482.0) * z2 - 1920.0) * z2 - 945.0) * z / 92160.0;
  return z + g1 / v + g2 / (v * v) + g3 / (v * v * v) + g4 / (v * v * v * v);
}

namespace {

// Which parameters the readings can determine: those asked for (all four when none is), less those
// the readings cannot (why_not says why: refused when asked for by name, else held with a warning).
struct FreeParameters {
  std::vector<int> free;  // indices of the fitted parameters, ascending
  std::array<std::string, kParameterCount> why_not;
};
FreeParameters ChooseFreeParameters(const io::RigReadings& readings, const CalibrationSettings& settings,
                                    bool has_casing, int on_bottom_torques, CalibrationResult& result) {
  FreeParameters chosen;
  const bool asked = !settings.fit.empty();
  std::vector<CalibrationParameter> wanted = settings.fit;
  if (!asked) {
    wanted = {CalibrationParameter::kOpenHoleFriction, CalibrationParameter::kCasedHoleFriction,
              CalibrationParameter::kHookLoadOffset, CalibrationParameter::kBitTorqueCoefficient};
  }
  auto& why_not = chosen.why_not;
  if (!has_casing) why_not[1] = "the well has no cased hole section (well.hole `cased: true`)";
  if (on_bottom_torques == 0) why_not[3] = "no surface torque was read on bottom (drilling)";
  std::vector<int>& free = chosen.free;
  for (const CalibrationParameter parameter : wanted) {
    const int k = Index(parameter);
    if (std::find(free.begin(), free.end(), k) != free.end()) continue;
    if (!why_not[static_cast<std::size_t>(k)].empty()) {
      if (asked) {
        throw InputError({readings.file, 0, 0}, "",
                         fmt::format("the readings cannot determine {}: {}", CalibrationParameterName(parameter),
                                     why_not[static_cast<std::size_t>(k)]));
      }
      result.warnings.push_back(fmt::format("{} not fitted: {}", CalibrationParameterName(parameter),
                                            why_not[static_cast<std::size_t>(k)]));
      continue;
    }
    free.push_back(k);
  }
  std::sort(free.begin(), free.end());
  return chosen;
}

// Refuses a fit whose model failed at more than half of the readings; warns of fewer failures.
void CheckModelFailures(const std::vector<ModelledReading>& modelled, CalibrationResult& result) {
  int failures = 0;
  for (const ModelledReading& m : modelled) failures += m.failed() ? 1 : 0;
  if (2 * failures > static_cast<int>(modelled.size())) {
    std::string why;
    for (const ModelledReading& m : modelled) {
      if (m.failed()) {
        why = m.message;
        break;
      }
    }
    throw SolverError(fmt::format("calibration: the model failed at {} of {} readings (the first: {})", failures,
                                  modelled.size(), why));
  }
  if (failures > 0) {
    result.warnings.push_back(fmt::format("the model failed at {} of {} readings; they are left out of the fit",
                                          failures, modelled.size()));
  }
}

// Each parameter's value and 95 % interval (Student's t on the residuals' degrees of freedom, the
// covariance the pseudo-inverse of JᵀJ of the weighted residuals), fitted or held.
void AddParameters(const LmOutcome& outcome, const FreeParameters& chosen, bool has_casing,
                   const Eigen::MatrixXd& covariance, CalibrationResult& result) {
  const Eigen::MatrixXd& J = outcome.J;
  const std::vector<int>& free = chosen.free;
  int used = 0;
  for (Eigen::Index i = 0; i < J.rows(); ++i) used += J.row(i).isZero(0.0) ? 0 : 1;
  const int dof = std::max(1, used - static_cast<int>(free.size()));
  const double t = StudentQuantile975(dof);
  for (int k = 0; k < kParameterCount; ++k) {
    FittedParameter fp;
    fp.parameter = static_cast<CalibrationParameter>(k);
    fp.value = outcome.p[static_cast<std::size_t>(k)];
    fp.low = fp.high = fp.value;
    const auto at = std::find(free.begin(), free.end(), k);
    if (at != free.end()) {
      const auto j = static_cast<Eigen::Index>(at - free.begin());
      fp.fitted = true;
      fp.standard_error = std::sqrt(std::max(covariance(j, j), 0.0));
      fp.low = fp.value - t * fp.standard_error;
      fp.high = fp.value + t * fp.standard_error;
      if (J.col(j).squaredNorm() <= 0.0) fp.note = "the readings do not move it";
    } else {
      const std::string& why = chosen.why_not[static_cast<std::size_t>(k)];
      fp.note = why.empty() ? "not asked for" : why;
      if (k == 1 && !has_casing) fp.value = std::numeric_limits<double>::quiet_NaN();
    }
    result.parameters.push_back(fp);
  }
}

// The fitted parameters' correlation, with a warning for each pair beyond ±kStronglyCorrelated naming
// what would tell them apart: the activities the readings lack, else readings over a longer stretch.
void AddCorrelations(const io::RigReadings& readings, const std::vector<int>& free, const Eigen::MatrixXd& covariance,
                     CalibrationResult& result) {
  std::vector<std::string> missing;
  for (const io::RigActivity activity : {io::RigActivity::kPickUp, io::RigActivity::kSlackOff,
                                         io::RigActivity::kRotatingOffBottom, io::RigActivity::kDrilling}) {
    const bool read = std::any_of(readings.rows.begin(), readings.rows.end(),
                                  [&](const io::RigReading& r) { return r.activity == activity; });
    if (!read) missing.push_back(io::RigActivityName(activity));
  }
  std::string what_would_separate = "readings over a longer stretch of hole, or at other WOBs, would";
  if (!missing.empty()) {
    what_would_separate = "the readings have no";
    for (std::size_t i = 0; i < missing.size(); ++i) {
      what_would_separate += (i == 0 ? " " : i + 1 == missing.size() ? " or " : ", ") + missing[i];
    }
    what_would_separate += " rows; they would separate them";
  }
  const auto m = static_cast<Eigen::Index>(free.size());
  result.correlation = Eigen::MatrixXd::Identity(m, m);
  for (Eigen::Index a = 0; a < m; ++a) {
    result.fitted.push_back(static_cast<CalibrationParameter>(free[static_cast<std::size_t>(a)]));
    for (Eigen::Index b = 0; b < m; ++b) {
      const double scale = std::sqrt(covariance(a, a) * covariance(b, b));
      result.correlation(a, b) = scale > 0.0 ? covariance(a, b) / scale : (a == b ? 1.0 : 0.0);
      if (b > a && std::abs(result.correlation(a, b)) > kStronglyCorrelated) {
        result.warnings.push_back(fmt::format(
            "{} and {} are correlated {:+.3f}: the readings can hardly tell them apart ({})",
            CalibrationParameterName(static_cast<CalibrationParameter>(free[static_cast<std::size_t>(a)])),
            CalibrationParameterName(static_cast<CalibrationParameter>(free[static_cast<std::size_t>(b)])),
            result.correlation(a, b), what_would_separate));
      }
    }
  }
}

// Each reading's modelled values and residuals (NaN where the model failed or nothing was read),
// and each channel's RMS.
void AddResiduals(const io::RigReadings& readings, const std::vector<ModelledReading>& modelled,
                  CalibrationResult& result) {
  std::vector<double> hook_residuals, torque_residuals;
  for (std::size_t i = 0; i < readings.rows.size(); ++i) {
    ReadingResidual residual;
    residual.reading = &readings.rows[i];
    residual.modelled = modelled[i];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    residual.hook_load_residual = modelled[i].failed() ? nan : modelled[i].hook_load - readings.rows[i].hook_load;
    residual.torque_residual = modelled[i].failed() || !readings.rows[i].surface_torque
                                   ? nan
                                   : modelled[i].surface_torque - *readings.rows[i].surface_torque;
    if (std::isfinite(residual.hook_load_residual)) hook_residuals.push_back(residual.hook_load_residual);
    if (std::isfinite(residual.torque_residual)) torque_residuals.push_back(residual.torque_residual);
    result.residuals.push_back(residual);
  }
  result.hook_load_rms = Rms(hook_residuals);
  result.torque_rms = Rms(torque_residuals);
  result.hook_load_count = static_cast<int>(hook_residuals.size());
  result.torque_count = static_cast<int>(torque_residuals.size());
}

}  // namespace

CalibrationResult Calibrate(const io::Case& c, const io::RigReadings& readings, const CalibrationSettings& settings) {
  CalibrationResult result;
  result.model = settings.model.kind;
  ReadingsModel model(c, readings, settings.model);
  result.bit_diameter = model.bit_diameter();
  const std::vector<well::HoleSection> sections =
      c.input.well ? c.input.well->hole.sections() : std::vector<well::HoleSection>{};
  const bool has_casing = model::HasCasedHole(sections);
  const ReadingsParameters start = CaseReadingsParameters(c);
  // The cased hole's start: the case's friction (its cased sections' own are a start only when fitted).
  Parameters p{start.open_hole_friction, start.open_hole_friction, 0.0, start.bit_torque_coefficient};
  for (const well::HoleSection& section : sections) {
    if (section.cased && section.friction) p[1] = *section.friction;
  }
  int torque_readings = 0, on_bottom_torques = 0;
  for (const io::RigReading& reading : readings.rows) {
    if (!reading.surface_torque) continue;
    ++torque_readings;
    if (reading.activity == io::RigActivity::kDrilling) ++on_bottom_torques;
  }
  const FreeParameters chosen = ChooseFreeParameters(readings, settings, has_casing, on_bottom_torques, result);
  const std::vector<int>& free = chosen.free;
  const int observations = static_cast<int>(readings.rows.size()) + torque_readings;
  if (observations <= static_cast<int>(free.size())) {
    throw InputError({readings.file, 0, 0}, "",
                     fmt::format("{} values read (hook loads and torques) cannot determine {} parameters", observations,
                                 free.size()));
  }

  // The channels' scatter: the readings' own first.
  std::vector<std::pair<double, double>> hooks, torques;
  for (const io::RigReading& reading : readings.rows) {
    hooks.emplace_back(reading.bit_md, reading.hook_load);
    if (reading.surface_torque) torques.emplace_back(reading.bit_md, *reading.surface_torque);
  }
  const bool fit_cased = std::find(free.begin(), free.end(), Index(CalibrationParameter::kCasedHoleFriction)) != free.end();
  Fit fit(model, readings, free, fit_cased, settings.log);
  // A floor: 0.1 % of the channel's largest reading (readings repeated exactly have no scatter).
  const auto floor = [](const std::vector<std::pair<double, double>>& values) {
    double largest = 0.0;
    for (const auto& [md, v] : values) largest = std::max(largest, std::abs(v));
    return std::max(1e-3 * largest, 1e-9);
  };
  fit.hook_sigma = std::max(SuccessiveDifferenceScatter(hooks), floor(hooks));
  fit.torque_sigma = torques.empty() ? 1.0 : std::max(SuccessiveDifferenceScatter(torques), floor(torques));

  int iterations = 0;
  LmOutcome outcome = LevenbergMarquardt(fit, p, settings.max_iterations, iterations);
  // Refit with each channel's residual RMS as its scatter.
  {
    std::vector<double> hook, torque;
    for (std::size_t i = 0; i < readings.rows.size(); ++i) {
      if (outcome.modelled[i].failed()) continue;
      hook.push_back(outcome.modelled[i].hook_load - readings.rows[i].hook_load);
      if (readings.rows[i].surface_torque) {
        torque.push_back(outcome.modelled[i].surface_torque - *readings.rows[i].surface_torque);
      }
    }
    fit.hook_sigma = std::max(Rms(hook), floor(hooks));
    if (!torques.empty()) fit.torque_sigma = std::max(Rms(torque), floor(torques));
    outcome = LevenbergMarquardt(fit, outcome.p, settings.max_iterations, iterations);
  }
  CheckModelFailures(outcome.modelled, result);

  const Eigen::MatrixXd covariance =
      (outcome.J.transpose() * outcome.J).completeOrthogonalDecomposition().pseudoInverse();
  AddParameters(outcome, chosen, has_casing, covariance, result);
  AddCorrelations(readings, free, covariance, result);
  AddResiduals(readings, outcome.modelled, result);
  result.hook_load_scatter = fit.hook_sigma;
  result.torque_scatter = fit.torque_sigma;
  result.iterations = iterations;
  result.evaluations = model.evaluations();
  result.converged = outcome.converged;
  if (!outcome.converged) {
    result.warnings.push_back(fmt::format("the fit did not converge in {} iterations", settings.max_iterations));
  }
  return result;
}

}  // namespace drillflex::pipeline
