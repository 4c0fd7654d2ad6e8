#include "pipeline/roadmap.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>

#include <fmt/format.h>

#include "analyses/soft_string.hpp"
#include "core/error.hpp"
#include "pipeline/roadmap_runs.hpp"
#include "pipeline/sweep_run.hpp"

namespace drillflex::pipeline {
namespace {

constexpr double kDefaultRoadmapRpm = 60.0 * kPi / 30.0;  // rad/s
constexpr int kDefaultDepths = 10;
constexpr std::size_t kMaxPoints = 2000;
// m: the stiff model's top at least this far above the string's highest point in compression (a stand
// of three joints).
constexpr double kStandAboveCompression = 3.0 * model::kDefaultJointSpacing;

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

}  // namespace

bool RoadmapPoint::failed() const {
  for (const double value : {pick_up, slack_off, rotating, off_bottom_torque, on_bottom_torque}) {
    if (!std::isfinite(value)) return true;
  }
  return false;
}

namespace {

// The case at `bit_md` with its top component repeated or cut to make the string `length` long.
io::Case CaseWithStringLength(const io::Case& c, double bit_md, double length) {
  if (!c.well) throw InputError({c.file, 0, 0}, "well", "a roadmap needs a well");
  io::Case at = c;
  at.well->bit_md = bit_md;
  at.input.bit_md = bit_md;
  auto& components = at.input.string.components;
  if (components.empty()) throw InputError({c.file, 0, 0}, "string", "the string has no components");
  const double below = LengthBelowTop(at.input.string);
  model::Component& top = components.back();
  const double room = length - below;
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

}  // namespace

io::Case CaseAtDepth(const io::Case& c, double bit_md) { return CaseWithStringLength(c, bit_md, bit_md); }

io::Case StiffCaseAtDepth(const io::Case& c, double bit_md, const analyses::RoadmapSettings& settings) {
  if (!std::isfinite(settings.stiff_length)) return CaseAtDepth(c, bit_md);
  double length = settings.stiff_length > 0.0 ? settings.stiff_length : model::StringLength(c.input.string);
  // The hook's support holds the stiff part's top along the hole and lets it move across: a top in
  // compression there has nothing to keep it straight (the pipe above would), and the string whirls
  // around the hole in the friction's continuation. So the stiff part reaches a stand above the
  // highest point in compression of the soft string slacking off at the largest friction factor or
  // rotating on bottom under the case's WOB (Johancsik: the neutral point as the rig's T&D has it).
  const model::ModelInput whole = CaseAtDepth(c, bit_md).input;
  const double largest_friction =
      settings.friction.empty() ? 0.0 : *std::max_element(settings.friction.begin(), settings.friction.end());
  analyses::SoftStringOperation slack_off{analyses::SoftStringMotion::SlackOff, largest_friction, largest_friction,
                                          0.0, 0.0, model::kDefaultJointSpacing};
  analyses::SoftStringOperation on_bottom{analyses::SoftStringMotion::Rotating, largest_friction, largest_friction,
                                          whole.operation.weight_on_bit, 0.0, model::kDefaultJointSpacing};
  double compressed = 0.0;  // m from the bit: the highest station in compression
  for (const analyses::SoftStringOperation& run : {slack_off, on_bottom}) {
    for (const analyses::SoftStringStation& station : analyses::ComputeSoftString(whole, run).stations) {
      if (station.axial_force < 0.0) compressed = std::max(compressed, station.s);
    }
  }
  if (compressed > 0.0) {
    // The top component's joints fill the string by whole joints below the length asked (one more
    // asked: the stand stays whole).
    const double joint = whole.string.components.back().length;
    length = std::max(length, compressed + kStandAboveCompression + joint);
  }
  return CaseWithStringLength(c, bit_md, std::min(length, bit_md));
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
  // One task a depth: its model built once, its runs continued from one another
  // (pipeline/roadmap_runs.hpp). The deepest first, so that the longest tasks do not come last.
  const std::vector<double> depths = RoadmapDepths(c, settings);
  std::vector<std::size_t> order(depths.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = order.size() - 1 - k;
  const std::size_t frictions = settings.friction.size();
  std::vector<RoadmapPoint> points(depths.size() * frictions);
  const auto start = std::chrono::steady_clock::now();
  std::mutex progress_mutex;
  int done = 0, failed = 0;
  double depth_total = 0.0, depth_done = 0.0;
  for (const double md : depths) depth_total += md * static_cast<double>(frictions);
  std::mutex log_mutex;
  std::function<void(const std::string&)> log;
  if (options.log) {
    log = [&](const std::string& line) {
      const std::lock_guard<std::mutex> lock(log_mutex);
      options.log(line);
    };
  }
  RunTasksOnThreads(options.jobs, depths.size(), [&](std::size_t task) {
    const std::size_t d = order[task];
    const std::vector<RoadmapPoint> at_depth = RunRoadmapDepth(c, settings, depths[d], log);
    std::copy(at_depth.begin(), at_depth.end(), points.begin() + static_cast<std::ptrdiff_t>(d * frictions));
    if (!options.progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const RoadmapPoint& point : at_depth) failed += point.failed() ? 1 : 0;
    done += static_cast<int>(frictions);
    depth_done += depths[d] * static_cast<double>(frictions);
    options.progress(done, static_cast<int>(points.size()), failed, elapsed * (depth_total - depth_done) / depth_done);
  });
  return points;
}

}  // namespace drillflex::pipeline
