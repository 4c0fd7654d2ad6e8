#include "pipeline/roadmap_runs.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/profile.hpp"
#include "pipeline/depth_runs.hpp"

namespace drillflex::pipeline {
namespace {

RoadmapPoint FailedPoint(double md, double friction, const std::string& message) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  RoadmapPoint point;
  point.bit_md = md;
  point.friction = friction;
  point.pick_up = point.slack_off = point.rotating = point.off_bottom_torque = point.on_bottom_torque = nan;
  point.message = message;
  return point;
}

// The point of one friction factor at a depth: its four runs, each screened on its own stations along
// `whole` (the case's string at the depth to the surface). A run that fails leaves its own quantities NaN
// and adds its reason to the point's message; the others stand.
RoadmapPoint Point(DepthRuns& runs, const model::ModelInput& whole, const analyses::RoadmapSettings& settings,
                   double friction) {
  RoadmapPoint point = FailedPoint(runs.bit_md(), friction, "");
  point.screens.emplace();
  runs.ClearNotes();
  const HoleFrictionFactors factors{friction, settings.cased_friction};
  TdRunLoads loads;
  loads.trip_speed = settings.trip_speed;
  loads.rotary_speed = settings.rotary_speed;
  auto run = [&](TdRun kind, auto&& take) {
    try {
      take(runs.Run(kind, factors, loads));
      RunScreen& screen = kind == TdRun::kPickUp             ? point.screens->pick_up
                          : kind == TdRun::kSlackOff          ? point.screens->slack_off
                          : kind == TdRun::kRotatingOffBottom ? point.screens->rotating
                                                              : point.screens->on_bottom;
      const bool rotating = kind == TdRun::kRotatingOffBottom || kind == TdRun::kOnBottom;
      screen = ScreenRun(whole, runs.Stations(kind), rotating);
    } catch (const SolverError& error) {
      point.message += (point.message.empty() ? "" : "; ") + std::string(error.what());
    }
  };
  run(TdRun::kPickUp, [&](const SurfaceReading& r) { point.pick_up = r.hook_load; });
  run(TdRun::kSlackOff, [&](const SurfaceReading& r) { point.slack_off = r.hook_load; });
  run(TdRun::kRotatingOffBottom, [&](const SurfaceReading& r) {
    point.rotating = r.hook_load;
    point.off_bottom_torque = r.surface_torque;
  });
  run(TdRun::kOnBottom, [&](const SurfaceReading& r) { point.on_bottom_torque = r.surface_torque; });
  for (const std::string& note : runs.notes()) point.message += (point.message.empty() ? "" : "; ") + note;
  return point;
}

}  // namespace

std::vector<RoadmapPoint> RunRoadmapDepth(const io::Case& c, const analyses::RoadmapSettings& settings, double bit_md,
                                          const std::function<void(const std::string&)>& log) {
  const profile::Scope scope("roadmap: a depth");
  std::vector<RoadmapPoint> points(settings.friction.size());
  std::vector<std::size_t> order(settings.friction.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return settings.friction[a] < settings.friction[b]; });
  std::optional<DepthRuns> runs;
  std::optional<model::ModelInput> whole;  // the string at the depth to the surface, for the screens
  try {
    whole = CaseAtDepth(c, bit_md).input;
    io::Case at = StiffCaseAtDepth(c, bit_md, settings);
    at.input.supports.clear();  // the rig's: the hook at the top, the bit at the hole's centre on bottom
    runs.emplace(at, log);
    runs->SolveAtRest();
  } catch (const SolverError& error) {
    for (std::size_t k = 0; k < points.size(); ++k) points[k] = FailedPoint(bit_md, settings.friction[k], error.what());
    return points;
  } catch (const InputError& error) {  // the model at this depth (as a sweep's run: pipeline/sweep_run.hpp)
    for (std::size_t k = 0; k < points.size(); ++k) points[k] = FailedPoint(bit_md, settings.friction[k], error.what());
    return points;
  }
  for (const std::size_t k : order) {
    try {
      points[k] = Point(*runs, *whole, settings, settings.friction[k]);
    } catch (const SolverError& error) {
      points[k] = FailedPoint(bit_md, settings.friction[k], error.what());
    }
  }
  return points;
}

}  // namespace drillflex::pipeline
