#include "pipeline/sweep_outcome.hpp"

#include <algorithm>
#include <cmath>

#include "analyses/bit_tendency.hpp"
#include "pipeline/drilling_regime.hpp"

namespace drillflex::pipeline {

double StickSlipSeverity(const analyses::TransientResult& result) {
  const auto& samples = result.samples;
  if (samples.empty()) return kNotComputed;
  // The second half of the samples, as the report takes it.
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest, sum = 0.0;
  int count = 0;
  for (std::size_t i = samples.size() / 2; i < samples.size(); ++i) {
    lowest = std::min(lowest, samples[i].bit_speed);
    highest = std::max(highest, samples[i].bit_speed);
    sum += samples[i].bit_speed;
    ++count;
  }
  const double mean = count > 0 ? sum / count : 0.0;
  if (mean == 0.0) return kNotComputed;
  return (highest - lowest) / std::abs(mean);
}

SurfaceLoads ComputeSurfaceLoads(const CaseResults& results) {
  SurfaceLoads loads;
  if (!results.static_result) return loads;
  const model::ModelInput& input = results.model.input;
  const double top = model::StringLength(input.string);
  for (const analyses::SupportReaction& reaction : results.static_result->reactions) {
    if (std::abs(reaction.s - top) > 1e-6 * std::max(1.0, top)) continue;
    const bool pipe_above = input.well && input.supports.empty();
    loads.hook_load = reaction.force.x() + (pipe_above ? model::StringAboveWeight(input) : 0.0);
    loads.surface_torque = -reaction.moment.x();  // the support's moment about x resists the drive's clockwise turn
  }
  return loads;
}

namespace {

void SummarizeStatic(const CaseResults& results, SweepOutcome& outcome) {
  const analyses::StaticResult& result = *results.static_result;
  if (result.bit) {
    outcome.bit_side_force = result.bit->side_force;
    outcome.bit_tendency = std::string(analyses::TendencyName(analyses::ClassifyBitTendency(*result.bit).inclination));
  }
  if (!result.contacts.empty()) {
    outcome.largest_contact_force = 0.0;
    for (const auto& contact : result.contacts) {
      outcome.largest_contact_force = std::max(outcome.largest_contact_force, contact.normal_force);
    }
  } else if (results.model.input.well) {
    outcome.largest_contact_force = 0.0;  // in a well, no contact carries force
  }
  if (!result.nodes.empty()) {
    outcome.peak_von_mises_stress = 0.0;
    for (const auto& node : result.nodes) {
      outcome.peak_von_mises_stress = std::max(outcome.peak_von_mises_stress, node.von_mises_stress);
    }
  }
  const SurfaceLoads surface = ComputeSurfaceLoads(results);
  outcome.hook_load = surface.hook_load;
  outcome.surface_torque = surface.surface_torque;
}

}  // namespace

SweepOutcome SummarizeRun(const CaseResults& results) {
  SweepOutcome outcome;
  outcome.converged = true;
  if (results.static_result) SummarizeStatic(results, outcome);
  if (results.tendency) {
    outcome.build_rate = results.tendency->build_rate;
    outcome.turn_rate = results.tendency->turn_rate;
  }
  if (results.vibration && !results.vibration->critical_speeds.empty()) {
    double lowest = std::numeric_limits<double>::infinity();
    for (const auto& critical : results.vibration->critical_speeds) lowest = std::min(lowest, critical.rotary_speed);
    outcome.first_critical_speed = lowest;
  } else if (results.modes) {
    if (const analyses::ModeResult* mode = analyses::FirstLateralMode(*results.modes)) {
      outcome.first_critical_speed = 2.0 * kPi * mode->frequency_hz;  // one turn a period: ω = 2π f
    }
  }
  if (results.transient && !results.transient->samples.empty()) {
    outcome.stick_slip_severity = StickSlipSeverity(*results.transient);
    // Probes with no wall (no well) get no clearance, so no whirl is read there.
    std::vector<double> clearance;
    for (const double s : results.transient->probe_s) {
      clearance.push_back(model::RadialClearanceAt(results.model.input, s).value_or(kNotComputed));
    }
    const DrillingRegime regime = ClassifyDrillingRegime(*results.transient, clearance);
    outcome.whirl_speed = regime.whirl_speed;
    outcome.whirl = analyses::WhirlName(regime.whirl);
    outcome.regime = regime.Name();
    if (!results.static_result) {
      outcome.hook_load = results.transient->samples.back().hook_load;
      outcome.surface_torque = results.transient->samples.back().surface_torque;
    }
  }
  return outcome;
}

}  // namespace drillflex::pipeline
