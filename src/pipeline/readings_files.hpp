// The rig's readings beside the model in result files: the readings and what the model gives at each
// (roadmap.json `readings`, calibration's `results.json`), and a CSV of the residuals, in the case's
// output units.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/case.hpp"
#include "io/rig_readings.hpp"
#include "pipeline/readings_model.hpp"

namespace drillflex::pipeline {

// One model of the readings: a label ("μ 0.25", "fitted") and each reading as modelled.
struct ModelledReadings {
  std::string label;
  double open_hole_friction = 0.0;
  std::vector<ModelledReading> modelled;  // in the readings' order
};

// {file, units, bit_md, activity, hook_load, surface_torque (null where not read), wob, rpm, line, models:
// [{label, friction, hook_load, surface_torque, hook_load_residual, torque_residual, message}]}: columns
// as lists, in the case's output units.
nlohmann::json ReadingsJson(const io::Case& c, const io::RigReadings& readings,
                            const std::vector<ModelledReadings>& models);

// One row a reading and model: bit_md, activity, model, friction, the read and modelled hook load and
// torque and their residuals (model − reading), wob, rpm, line, message.
std::string ReadingsCsv(const io::Case& c, const io::RigReadings& readings, const std::vector<ModelledReadings>& models);

}  // namespace drillflex::pipeline
