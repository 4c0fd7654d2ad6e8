#include "pipeline/roadmap.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>

#include <fmt/format.h>

#include "core/error.hpp"
#include "pipeline/case_run.hpp"
#include "pipeline/sweep_outcome.hpp"
#include "pipeline/sweep_run.hpp"

namespace drillflex::pipeline {
namespace {

constexpr double kDefaultRoadmapRpm = 60.0 * kPi / 30.0;  // rad/s
constexpr int kDefaultDepths = 10;
constexpr std::size_t kMaxPoints = 2000;

InputError RoadmapError(const io::Case& c, const std::string& key, const std::string& message) {
  return InputError({c.file, 0, 0}, "analyses.roadmap." + key, message);
}

// The length of the string below its top component (m).
double LengthBelowTop(const model::StringConfig& string) {
  double below = 0.0;
  for (std::size_t i = 0; i + 1 < string.components.size(); ++i) {
    below += string.components[i].length * string.components[i].count;
  }
  return below;
}

// The shallowest bit depth with room for the top component above the rest (m): one joint of it, or
// any length of a single one (CaseAtDepth), taken as a hundredth of it.
double ShallowestDepth(const io::Case& c) {
  const auto& components = c.input.string.components;
  if (components.empty()) return 0.0;
  const model::Component& top = components.back();
  return LengthBelowTop(c.input.string) + (top.count == 1 ? 0.01 : 1.0) * top.length;
}

// One static run: the tension and the torque at the surface. Off bottom the case's supports are the
// hook's alone (axial and the spin, as model::DefaultWellSupports holds the top), found by the
// energy's minimum: the bit hangs free and lies on the wall like the rest, where the default supports
// would hold it at the hole's centre and take its share of the string's weight off the wall, and the
// drag with it (6 % of μ W sin I on tests/pipeline/roadmap_test.cpp's 297 m). The pipe above the model
// to the surface hangs along the hole without friction (model::StringAboveWeight): less than a joint.
SurfaceLoads RunStaticAtSurface(io::Case c, bool off_bottom) {
  if (off_bottom) {
    model::Support hook;
    hook.at = model::StringLength(c.input.string);
    hook.fixed[model::kX] = hook.fixed[model::kRx] = true;
    c.input.supports = {hook};
    analyses::StaticSettings settings = c.analyses.static_analysis.value_or(analyses::StaticSettings{});
    settings.energy_minimum_on_case_supports = true;
    c.analyses.static_analysis = settings;
  }
  const CaseResults results = RunCase(c, AnalysisRequest::Only(Analysis::Static));
  SurfaceLoads loads = ComputeSurfaceLoads(results);
  if (off_bottom) loads.hook_load += model::StringAboveWeight(results.model.input);
  return loads;
}

// The case with one friction factor (axial and around the string), a WOB and TOB, and the string's
// motion: axial (pulling out > 0) or turning.
io::Case WithOperation(io::Case c, double friction, double wob, double tob, model::PrescribedSliding sliding) {
  c.input.settings.contact.friction = friction;
  c.input.settings.contact.axial_friction.reset();
  c.input.operation.weight_on_bit = wob;
  c.input.operation.torque_on_bit = tob;
  c.input.operation.rotary_speed = sliding.rotary_speed;
  c.input.operation.hook_load.reset();
  c.input.static_sliding = sliding;
  return c;
}

RoadmapPoint FailedPoint(double md, double friction, const std::string& message) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {md, friction, nan, nan, nan, nan, nan, message};
}

RoadmapPoint RunRoadmapPoint(const io::Case& c, const analyses::RoadmapSettings& settings, double md, double friction) {
  const io::Case at = CaseAtDepth(c, md);
  RoadmapPoint point{md, friction, 0.0, 0.0, 0.0, 0.0, 0.0, ""};
  const double rpm = settings.rotary_speed;
  try {
    point.pick_up =
        RunStaticAtSurface(WithOperation(at, friction, 0.0, 0.0, {settings.trip_speed, 0.0}), true).hook_load;
    point.slack_off =
        RunStaticAtSurface(WithOperation(at, friction, 0.0, 0.0, {-settings.trip_speed, 0.0}), true).hook_load;
    const SurfaceLoads off_bottom = RunStaticAtSurface(WithOperation(at, friction, 0.0, 0.0, {0.0, rpm}), true);
    point.rotating = off_bottom.hook_load;
    point.off_bottom_torque = off_bottom.surface_torque;
    const io::Case drilling =
        WithOperation(at, friction, c.input.operation.weight_on_bit, c.input.operation.torque_on_bit, {0.0, rpm});
    point.on_bottom_torque = RunStaticAtSurface(drilling, false).surface_torque;
  } catch (const SolverError& error) {
    return FailedPoint(md, friction, error.what());
  } catch (const InputError& error) {  // the model at this depth (as a sweep's run: pipeline/sweep_run.hpp)
    return FailedPoint(md, friction, error.what());
  }
  return point;
}

}  // namespace

io::Case CaseAtDepth(const io::Case& c, double bit_md) {
  if (!c.well) throw InputError({c.file, 0, 0}, "well", "a roadmap needs a well");
  io::Case at = c;
  at.well->bit_md = bit_md;
  at.input.bit_md = bit_md;
  auto& components = at.input.string.components;
  if (components.empty()) throw InputError({c.file, 0, 0}, "string", "the string has no components");
  const double below = LengthBelowTop(at.input.string);
  model::Component& top = components.back();
  const double room = bit_md - below;
  const int count = static_cast<int>(std::floor(room / top.length + 1e-9));
  if (top.count == 1 ? room <= 0.0 : count < 1) {
    throw InputError({c.file, 0, 0}, "string",
                     fmt::format("at a bit MD of {:.6g} m the components below the top one ({:.6g} m) leave no room "
                                 "for a joint of it ({:.6g} m)",
                                 bit_md, below, top.length));
  }
  if (top.count == 1) {
    top.length = room;
  } else {
    top.count = count;
  }
  return at;
}

analyses::RoadmapSettings CompleteRoadmapSettings(const io::Case& c, const analyses::RoadmapSettings& settings) {
  if (!c.well) throw InputError({c.file, 0, 0}, "well", "a roadmap needs a well");
  analyses::RoadmapSettings complete = settings;
  const double td = c.well->bit_md;
  const double shallowest = ShallowestDepth(c);
  if (complete.from_md == 0.0) complete.from_md = std::min(td, std::max(shallowest, 0.1 * td));
  if (complete.from_md > td + 1e-9) {
    throw RoadmapError(c, "from", fmt::format("the first depth {:.6g} m is below the bit MD {:.6g} m", complete.from_md, td));
  }
  if (complete.from_md < shallowest - 1e-9) {
    throw RoadmapError(c, "from",
                       fmt::format("at {:.6g} m the string below its top component and one joint of it (or a "
                                   "hundredth of a single one: {:.6g} m) do not fit above the bit",
                                   complete.from_md, shallowest));
  }
  if (complete.step == 0.0) {
    complete.step = td > complete.from_md ? (td - complete.from_md) / (kDefaultDepths - 1) : 1.0;
  }
  if (complete.friction.empty()) {
    const double mu = c.input.settings.contact.friction;
    for (const double factor : {mu - 0.1, mu, mu + 0.1}) {
      if (factor >= 0.0) complete.friction.push_back(factor);
    }
  }
  if (complete.rotary_speed == 0.0) {
    complete.rotary_speed = c.input.operation.rotary_speed > 0.0 ? c.input.operation.rotary_speed : kDefaultRoadmapRpm;
  }
  const double depths = std::floor((td - complete.from_md) / complete.step + 1e-9) + 2.0;
  if (depths * static_cast<double>(complete.friction.size()) > static_cast<double>(kMaxPoints)) {
    throw RoadmapError(c, "step", fmt::format("more than {} points (depths × friction factors): use a larger step",
                                              kMaxPoints));
  }
  return complete;
}

std::vector<double> RoadmapDepths(const io::Case& c, const analyses::RoadmapSettings& settings) {
  const double td = c.well->bit_md;
  std::vector<double> depths;
  // Depth k from the start (not a running sum: no drift of the step's round-off).
  for (int k = 0; settings.from_md + k * settings.step < td - 1e-6 * settings.step; ++k) {
    depths.push_back(settings.from_md + k * settings.step);
  }
  depths.push_back(td);
  return depths;
}

std::vector<RoadmapPoint> RunRoadmap(const io::Case& c, const analyses::RoadmapSettings& settings,
                                     const RoadmapOptions& options) {
  struct Task {
    double md;
    double friction;
  };
  std::vector<Task> tasks;
  for (const double md : RoadmapDepths(c, settings)) {
    for (const double friction : settings.friction) tasks.push_back({md, friction});
  }
  std::vector<RoadmapPoint> points(tasks.size());
  const auto start = std::chrono::steady_clock::now();
  std::mutex progress_mutex;
  int done = 0, failed = 0;
  double depth_total = 0.0, depth_done = 0.0;
  for (const Task& task : tasks) depth_total += task.md;
  RunTasksOnThreads(options.jobs, tasks.size(), [&](std::size_t k) {
    points[k] = RunRoadmapPoint(c, settings, tasks[k].md, tasks[k].friction);
    if (!options.progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    failed += points[k].message.empty() ? 0 : 1;
    depth_done += tasks[k].md;
    options.progress(++done, static_cast<int>(tasks.size()), failed, elapsed * (depth_total - depth_done) / depth_done);
  });
  return points;
}

}  // namespace drillflex::pipeline
