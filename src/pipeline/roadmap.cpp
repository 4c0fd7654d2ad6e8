#include "pipeline/roadmap.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "pipeline/case_run.hpp"
#include "pipeline/sweep_outcome.hpp"

namespace drillflex::pipeline {
namespace {

constexpr double kDefaultRoadmapRpm = 60.0 * kPi / 30.0;  // rad/s

// One static run: the tension and the torque at the surface. Off bottom the case's supports are the
// hook's alone (axial and the spin, as model::DefaultWellSupports holds the top): the bit hangs free
// and lies on the wall like the rest, where the default supports would hold it at the hole's centre
// and take its share of the string's weight off the wall, and the drag with it (6 % of μ W sin I on
// the straight-hole test's 297 m). The pipe above the model to the surface is added either way.
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
  SurfaceLoads loads = CalcSurfaceLoads(results);
  if (off_bottom) loads.hook_load += model::StringAboveWeight(results.model.input);
  return loads;
}

io::Case WithOperation(io::Case c, double friction, double wob, double tob, model::PrescribedSliding sliding) {
  c.input.settings.contact.friction = friction;
  c.input.settings.contact.axial_friction.reset();
  c.input.operation.weight_on_bit = wob;
  c.input.operation.torque_on_bit = tob;
  c.input.operation.rpm = sliding.rotary_speed;
  c.input.operation.hook_load.reset();
  c.input.static_sliding = sliding;
  return c;
}

}  // namespace

io::Case CaseAtDepth(const io::Case& c, double bit_md) {
  if (!c.well) throw InputError({c.file, 0, 0}, "well", "a roadmap needs a well");
  io::Case at = c;
  at.well->bit_md = bit_md;
  at.input.bit_md = bit_md;
  auto& components = at.input.string.components;
  if (components.empty()) throw InputError({c.file, 0, 0}, "string", "the string has no components");
  double below = 0.0;
  for (std::size_t i = 0; i + 1 < components.size(); ++i) below += components[i].length * components[i].count;
  const double joint = components.back().length;
  const int count = static_cast<int>(std::floor((bit_md - below) / joint + 1e-9));
  if (count < 1) {
    throw InputError({c.file, 0, 0}, "string",
                     fmt::format("at a bit MD of {:.6g} m the components below the top one ({:.6g} m) leave no room "
                                 "for a joint of it ({:.6g} m)",
                                 bit_md, below, joint));
  }
  components.back().count = count;
  return at;
}

std::vector<RoadmapPoint> RunRoadmap(const io::Case& c, const RoadmapSettings& settings) {
  if (!c.well) throw InputError({c.file, 0, 0}, "well", "a roadmap needs a well");
  if (settings.step <= 0.0) throw InputError({c.file, 0, 0}, "roadmap.step", "the depth step must be > 0");
  const double td = c.well->bit_md;
  const double rpm = settings.rotary_speed > 0.0       ? settings.rotary_speed
                     : c.input.operation.rpm > 0.0      ? c.input.operation.rpm
                                                        : kDefaultRoadmapRpm;
  std::vector<double> depths;
  for (double md = settings.from_md; md < td - 1e-6; md += settings.step) depths.push_back(md);
  depths.push_back(td);
  std::vector<RoadmapPoint> points;
  for (const double md : depths) {
    const io::Case at = CaseAtDepth(c, md);
    for (const double friction : settings.friction) {
      RoadmapPoint point{md, friction, 0.0, 0.0, 0.0, 0.0, 0.0, ""};
      try {
        point.pick_up =
            RunStaticAtSurface(WithOperation(at, friction, 0.0, 0.0, {settings.trip_speed, 0.0}), true).hook_load;
        point.slack_off =
            RunStaticAtSurface(WithOperation(at, friction, 0.0, 0.0, {-settings.trip_speed, 0.0}), true).hook_load;
        const SurfaceLoads off_bottom = RunStaticAtSurface(WithOperation(at, friction, 0.0, 0.0, {0.0, rpm}), true);
        point.rotating = off_bottom.hook_load;
        point.off_bottom_torque = off_bottom.surface_torque;
        point.on_bottom_torque = RunStaticAtSurface(WithOperation(at, friction, c.input.operation.weight_on_bit,
                                                                  c.input.operation.torque_on_bit, {0.0, rpm}),
                                                    false)
                                     .surface_torque;
      } catch (const SolverError& error) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        point = {md, friction, nan, nan, nan, nan, nan, error.what()};
      }
      points.push_back(point);
    }
  }
  return points;
}

}  // namespace drillflex::pipeline
