#include "pipeline/readings_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include <fmt/format.h>

#include "core/error.hpp"
#include "pipeline/roadmap.hpp"
#include "pipeline/sweep_run.hpp"
#include "well/hole.hpp"

namespace drillflex::pipeline {
namespace {

// Readings whose bit depths differ by less than this share a depth's model, m.
constexpr double kSameDepth = 1e-3;
// The friction the stiff model's length is chosen for (StiffCaseAtDepth: its top in tension slacking
// off at this friction): above what a calibration meets in a well.
constexpr double kStiffLengthFriction = 0.6;

TdRun RunOf(io::RigActivity activity) {
  switch (activity) {
    case io::RigActivity::kDrilling: return TdRun::kOnBottom;
    case io::RigActivity::kRotatingOffBottom: return TdRun::kRotatingOffBottom;
    case io::RigActivity::kPickUp: return TdRun::kPickUp;
    case io::RigActivity::kSlackOff: return TdRun::kSlackOff;
    default: break;
  }
  throw LogicError("ReadingsModel: an activity the model has no run for");
}

InputError ReadingError(const io::RigReadings& readings, const io::RigReading& reading, const std::string& message) {
  return InputError({readings.file, reading.line, 0}, "bit_md", message);
}

}  // namespace

bool ModelledReading::failed() const { return !std::isfinite(hook_load) || !std::isfinite(surface_torque); }

double BitDiameter(const io::Case& c) {
  const auto& components = c.input.string.components;
  if (!components.empty() && components.front().type == model::ComponentType::Bit) return components.front().outer_diameter;
  if (c.input.well && !c.input.well->hole.empty()) return c.input.well->hole.Diameter(c.input.bit_md);
  return components.empty() ? 0.0 : components.front().outer_diameter;
}

ReadingsParameters CaseReadingsParameters(const io::Case& c) {
  ReadingsParameters p;
  p.open_hole_friction = c.input.settings.contact.friction;
  const double wob = c.input.operation.weight_on_bit, diameter = BitDiameter(c);
  // TOB = μ_b WOB D / 3.
  if (wob > 0.0 && diameter > 0.0) p.bit_torque_coefficient = 3.0 * c.input.operation.torque_on_bit / (wob * diameter);
  return p;
}

struct ReadingsModel::Depth {
  double bit_md = 0.0;
  std::vector<std::size_t> readings;  // indices into readings_.rows
  io::Case at;                        // the case at this depth (the stiff model's, or the whole string)
  std::unique_ptr<DepthRuns> runs;    // the stiff model, built at the first evaluation
  std::string failure;                // why the model or its rest failed at this depth ("" when not)
};

ReadingsModel::ReadingsModel(const io::Case& c, const io::RigReadings& readings, const ReadingsModelOptions& options)
    : readings_(readings), options_(options), bit_diameter_(BitDiameter(c)) {
  if (!c.well) throw InputError({c.file, 0, 0}, "well", "modelling the rig's readings needs a well");
  if (readings_.rows.empty()) throw InputError({readings_.file, 0, 0}, "", "the readings file has no readings");
  const double shallowest = model::StringLength(c.input.string) - c.input.string.components.back().length *
                                                                      c.input.string.components.back().count;
  const double deepest = c.input.well ? c.input.well->trajectory.end_md() : c.well->bit_md;
  std::vector<std::size_t> order(readings_.rows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return readings_.rows[a].bit_md > readings_.rows[b].bit_md;
  });
  analyses::RoadmapSettings roadmap = options_.roadmap;
  roadmap.friction = {kStiffLengthFriction};
  for (const std::size_t i : order) {
    const io::RigReading& reading = readings_.rows[i];
    if (!(reading.bit_md > shallowest)) {
      throw ReadingError(readings_, reading,
                         fmt::format("a bit MD of {:.6g} m leaves no room for the string below its top component "
                                     "({:.6g} m)",
                                     reading.bit_md, shallowest));
    }
    if (reading.bit_md > deepest + kSameDepth) {
      throw ReadingError(readings_, reading,
                         fmt::format("a bit MD of {:.6g} m is below the well's survey (to {:.6g} m)", reading.bit_md,
                                     deepest));
    }
    if (reading.activity == io::RigActivity::kDrilling && !(reading.weight_on_bit > 0.0)) {
      throw InputError({readings_.file, reading.line, 0}, "wob", "a drilling reading (on bottom) needs a WOB above 0");
    }
    if (depths_.empty() || depths_.back()->bit_md - reading.bit_md > kSameDepth) {
      auto depth = std::make_unique<Depth>();
      depth->bit_md = reading.bit_md;
      depths_.push_back(std::move(depth));
    }
    depths_.back()->readings.push_back(i);
  }
  for (auto& depth : depths_) {
    // The stiff model long enough for the largest WOB at this depth to leave its top in tension.
    io::Case sized = c;
    double wob = 0.0;
    for (const std::size_t i : depth->readings) wob = std::max(wob, readings_.rows[i].weight_on_bit);
    sized.input.operation.weight_on_bit = std::max(wob, 0.0);
    try {
      depth->at = options_.kind == ReadingsModelKind::kSoft ? CaseAtDepth(sized, depth->bit_md)
                                                            : StiffCaseAtDepth(sized, depth->bit_md, roadmap);
      depth->at.input.supports.clear();  // the rig's: the hook at the top, the bit at the hole's centre on bottom
      depth->at.input.operation.weight_on_bit = c.input.operation.weight_on_bit;
    } catch (const InputError& error) {
      throw ReadingError(readings_, readings_.rows[depth->readings.front()], error.what());
    }
  }
}

ReadingsModel::~ReadingsModel() = default;

void ReadingsModel::EvaluateDepth(Depth& depth, const ReadingsParameters& parameters,
                                  std::vector<ModelledReading>& out) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const HoleFrictionFactors friction{parameters.open_hole_friction, parameters.cased_hole_friction};
  if (options_.kind == ReadingsModelKind::kStiff && !depth.runs && depth.failure.empty()) {
    try {
      depth.runs = std::make_unique<DepthRuns>(depth.at);
      depth.runs->SolveAtRest();
    } catch (const SolverError& error) {
      depth.failure = error.what();
    } catch (const InputError& error) {
      depth.failure = error.what();
    }
  }
  for (const std::size_t i : depth.readings) {
    const io::RigReading& reading = readings_.rows[i];
    ModelledReading& modelled = out[i];
    modelled = {nan, nan, depth.failure};
    if (!depth.failure.empty()) continue;
    const TdRun run = RunOf(reading.activity);
    TdRunLoads loads;
    loads.trip_speed = options_.roadmap.trip_speed;
    loads.rotary_speed = reading.rotary_speed;
    if (run == TdRun::kOnBottom) {
      loads.weight_on_bit = reading.weight_on_bit;
      loads.torque_on_bit = parameters.bit_torque_coefficient * reading.weight_on_bit * bit_diameter_ / 3.0;
    }
    try {
      SurfaceReading surface;
      if (options_.kind == ReadingsModelKind::kSoft) {
        surface = SoftSurfaceReading(depth.at.input, run, friction, loads);
      } else {
        depth.runs->ClearNotes();
        surface = depth.runs->Run(run, friction, loads);
        for (const std::string& note : depth.runs->notes()) {
          modelled.message += (modelled.message.empty() ? "" : "; ") + note;
        }
      }
      modelled.hook_load = surface.hook_load + parameters.hook_load_offset;
      modelled.surface_torque = surface.surface_torque;
    } catch (const SolverError& error) {
      modelled.message = error.what();
    }
  }
}

std::vector<ModelledReading> ReadingsModel::Evaluate(const ReadingsParameters& parameters) {
  std::vector<ModelledReading> out(readings_.rows.size());
  std::mutex progress_mutex;
  int done = 0;
  const int total = static_cast<int>(depths_.size());
  RunTasksOnThreads(options_.jobs, depths_.size(), [&](std::size_t k) {
    EvaluateDepth(*depths_[k], parameters, out);
    if (!options_.progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex);
    options_.progress(++done, total);
  });
  ++evaluations_;
  return out;
}

}  // namespace drillflex::pipeline
