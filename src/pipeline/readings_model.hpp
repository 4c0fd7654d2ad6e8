// The torque-and-drag model of the rig's readings (io/rig_readings.hpp): for each reading, the hook load
// and surface torque the model gives at the reading's bit depth, activity, WOB and rotary speed, under
// a set of the parameters a calibration fits (pipeline/calibration.hpp) or a roadmap's friction factor.
//
//   hook load      = the model's tension at the surface + the hook-load offset (the travelling
//                    equipment, block and top drive, that the rig's hook load includes)
//   surface torque = the model's torque at the surface, the torque on bit on bottom being
//                    TOB = μ_b · WOB · D_bit / 3 (a flat-bottomed bit whose cutters rub the rock with
//                    μ_b over its face: ∫ μ_b (WOB/πR²) r 2πr dr from 0 to R = (2/3) μ_b WOB R)
//
// Activities: drilling (on bottom, rotating), rotating (off bottom), pick_up and slack_off, each the
// run of pipeline/depth_runs.hpp. The stiff-string model keeps each depth's model and its last
// equilibria, so that another set of parameters starts from them (a continuation: a calibration's
// evaluations cost a few Newton iterations a reading); the soft string (Johancsik) is closed form.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "io/case.hpp"
#include "io/rig_readings.hpp"
#include "pipeline/depth_runs.hpp"

namespace drillflex::pipeline {

// What the model of the readings varies.
struct ReadingsParameters {
  double open_hole_friction = 0.25;
  std::optional<double> cased_hole_friction;  // none: each cased section's own (model/hole_friction.hpp)
  double hook_load_offset = 0.0;              // N
  double bit_torque_coefficient = 0.0;        // μ_b
};

// One reading as modelled. A run that failed leaves NaN and says why.
struct ModelledReading {
  double hook_load = 0.0;       // N, with the offset
  double surface_torque = 0.0;  // N·m, clockwise looking down-hole
  std::string message;          // the run's failure or warnings; "" when it solved cleanly
  bool failed() const;
};

enum class ReadingsModelKind { kStiff, kSoft };

struct ReadingsModelOptions {
  ReadingsModelKind kind = ReadingsModelKind::kStiff;
  // The stiff model's length from the bit, the trip speed: as the roadmap's (RoadmapSettings).
  analyses::RoadmapSettings roadmap;
  int jobs = 1;  // depths at once
  // After each depth of an evaluation: depths done and in all.
  std::function<void(int done, int total)> progress;
};

class ReadingsModel {
 public:
  // Refuses (InputError naming the readings file and line) a reading whose depth the case's string
  // does not reach from the surface to the bit or beyond its well, a drilling reading without a WOB.
  ReadingsModel(const io::Case& c, const io::RigReadings& readings, const ReadingsModelOptions& options);
  ~ReadingsModel();
  ReadingsModel(const ReadingsModel&) = delete;
  ReadingsModel& operator=(const ReadingsModel&) = delete;

  // Every reading modelled under `parameters`, in the readings' order.
  std::vector<ModelledReading> Evaluate(const ReadingsParameters& parameters);

  // The bit's diameter for the torque on bit (the bit component's OD, else the hole's at the bit), m.
  double bit_diameter() const { return bit_diameter_; }
  const io::RigReadings& readings() const { return readings_; }
  int evaluations() const { return evaluations_; }

 private:
  struct Depth;
  void EvaluateDepth(Depth& depth, const ReadingsParameters& parameters, std::vector<ModelledReading>& out) const;

  io::RigReadings readings_;
  ReadingsModelOptions options_;
  double bit_diameter_ = 0.0;
  std::vector<std::unique_ptr<Depth>> depths_;  // the readings grouped by bit depth, deepest first
  int evaluations_ = 0;
};

// The case's own parameters: its open-hole friction (model.contact), its cased sections' own, no
// offset, μ_b from its torque and weight on bit (3 TOB / (WOB D_bit); 0 without a WOB).
ReadingsParameters CaseReadingsParameters(const io::Case& c);

// The bit's diameter of a case (the bit component's OD, else the hole's at the bit), m.
double BitDiameter(const io::Case& c);

}  // namespace drillflex::pipeline
