#include "pipeline/roadmap_runs.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "analyses/resting_start.hpp"
#include "analyses/soft_string.hpp"
#include "analyses/static_minimum.hpp"
#include "analyses/static_solve.hpp"
#include "core/error.hpp"
#include "core/profile.hpp"
#include "model/spring_elements.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {
namespace {

using Motion = analyses::SoftStringMotion;

// Newton iterations of the first rotating run at the full friction before the continuation takes over.
constexpr int kDirectIterations = 20;

// The parameter block of a run off bottom: the bit free (the hook's support holds the string), no
// WOB or torque on bit, the friction factor `friction` along and around the string.
model::LoadParameters OffBottom(double friction) {
  model::LoadParameters parameters;
  parameters.bit_support_factor = 0.0;
  parameters.weight_on_bit = 0.0;
  parameters.torque_on_bit = 0.0;
  parameters.wall_friction = model::WallFriction{friction, friction};
  return parameters;
}

// On bottom: the bit held at the hole centre, the case's WOB and torque on bit.
model::LoadParameters OnBottom(double friction) {
  model::LoadParameters parameters;
  parameters.wall_friction = model::WallFriction{friction, friction};
  return parameters;
}

model::LoadParameters Sliding(model::LoadParameters parameters, double axial_speed, double rotary_speed) {
  parameters.sliding_mode = model::SlidingMode::kPrescribed;
  parameters.sliding = {axial_speed, rotary_speed};
  return parameters;
}

// The tension and torque at the surface.
struct SurfaceReading {
  double hook_load = 0.0;       // N
  double surface_torque = 0.0;  // N·m, clockwise looking down-hole
};

// Elements of the soft string above the stiff model: at most a joint (pipeline/roadmap_soft.cpp).
constexpr double kSoftElementLength = model::kDefaultJointSpacing;

// The pipe above the stiff model to the surface: the depth case's top component continued from the
// model's top (its MD the "bit" of a soft string whose bottom carries the model's top tension and
// torque). Empty when the model reaches the surface.
std::optional<model::ModelInput> PipeAbove(const model::ModelInput& input) {
  const double top_md = input.bit_md - model::StringLength(input.string);
  if (!input.trajectory || top_md <= input.trajectory->start_md() + 1e-6) return std::nullopt;
  model::ModelInput above = input;
  above.bit_md = top_md;
  model::Component pipe = input.string.components.back();
  pipe.count = 1;
  above.string.components = {pipe};
  return above;
}

// The reading at the surface of an equilibrium q: the hook's reaction at the model's top (the string
// frame: x up the hole) is the tension there, its moment about x the torque; the soft string above
// (Johancsik with the rotating string's climb, as the stiff model has it) carries them to the surface
// under the run's motion and friction factor.
SurfaceReading ReadSurface(const CaseModel& m, const std::optional<model::ModelInput>& above, const VecX& q,
                           const model::LoadParameters& parameters, analyses::SoftStringMotion motion, double friction) {
  const model::SystemModel& system = m.built.system;
  const auto poses = system.Poses(q);
  const VecX rest = VecX::Zero(system.num_velocities());
  for (const int index : m.built.support_elements) {
    const auto* support = dynamic_cast<const model::SupportElement*>(system.elements()[index].get());
    if (support == nullptr || support->holds_bit()) continue;
    const Vec6 reaction = support->Reaction(system.StateOf(*support, poses, rest, 0.0, parameters));
    // The support's moment about x resists the drive's clockwise turn.
    const SurfaceReading at_top{reaction.x(), -reaction[3]};
    if (!above) return at_top;
    analyses::SoftStringOperation operation;
    operation.motion = motion;
    operation.axial_friction = operation.tangential_friction = friction;
    operation.weight_on_bit = -at_top.hook_load;  // the model's top pulls the pipe above down
    operation.torque_on_bit = at_top.surface_torque;
    operation.max_element_length = kSoftElementLength;
    operation.wall_climb = true;
    const analyses::SoftStringResult soft = analyses::ComputeSoftString(*above, operation);
    return {soft.hook_load, soft.surface_torque};
  }
  throw LogicError("roadmap: the model has no hook support at its top");
}

// The runs of one depth, in the order of RunRoadmapDepth's header.
class DepthRuns {
 public:
  DepthRuns(const io::Case& at, const analyses::RoadmapSettings& settings,
            const std::function<void(const std::string&)>& log)
      : model_(BuildCaseModel(at)), above_(PipeAbove(at.input)), settings_(settings),
        static_settings_(at.analyses.static_analysis.value_or(analyses::StaticSettings{})), log_(log) {
    static_settings_.log = nullptr;
    if (log_) static_settings_.log = [this](const std::string& line) { log_(prefix_ + line); };
  }
  DepthRuns(const DepthRuns&) = delete;  // static_settings_.log holds `this`
  DepthRuns& operator=(const DepthRuns&) = delete;

  // At rest off bottom (no friction): the start of the first friction factor's runs.
  void SolveAtRest() {
    Label(0.0, "at rest off bottom");
    model::LoadParameters parameters = OffBottom(0.0);
    parameters.sliding_mode = model::SlidingMode::kVelocities;
    rest_ = Solve(parameters, nullptr, "at rest off bottom");
  }

  // The point at one friction factor. A run that fails leaves its own quantities NaN and adds its
  // reason to the point's message; the others stand.
  RoadmapPoint Point(double bit_md, double friction) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    RoadmapPoint point{bit_md, friction, nan, nan, nan, nan, nan, ""};
    notes_.clear();
    const double trip = settings_.trip_speed, rpm = settings_.rotary_speed;
    auto run = [&](const char* name, auto&& solve) {
      Label(friction, name);
      try {
        solve();
      } catch (const SolverError& error) {
        point.message += (point.message.empty() ? "" : "; ") + std::string(error.what());
      }
    };
    run("pulling out", [&] {
      const model::LoadParameters pick_up = Sliding(OffBottom(friction), trip, 0.0);
      pick_up_ = Solve(pick_up, pick_up_ ? &*pick_up_ : &*rest_, "pulling out");
      point.pick_up = ReadSurface(model_, above_, *pick_up_, pick_up, Motion::PickUp, friction).hook_load;
    });
    run("running in", [&] {
      const model::LoadParameters slack_off = Sliding(OffBottom(friction), -trip, 0.0);
      slack_off_ = Solve(slack_off, slack_off_ ? &*slack_off_ : &*rest_, "running in");
      point.slack_off = ReadSurface(model_, above_, *slack_off_, slack_off, Motion::SlackOff, friction).hook_load;
    });
    run("rotating off bottom", [&] {
      const model::LoadParameters rotating = Sliding(OffBottom(friction), 0.0, rpm);
      rotating_ = rotating_ ? Solve(rotating, &*rotating_, "rotating off bottom") : FromRest(rotating);
      const SurfaceReading off_bottom = ReadSurface(model_, above_, *rotating_, rotating, Motion::Rotating, friction);
      point.rotating = off_bottom.hook_load;
      point.off_bottom_torque = off_bottom.surface_torque;
    });
    run("on bottom", [&] {
      // The string at rest on bottom does not depend on the friction: a depth where its energy's
      // minimum was not found is not solved again at every friction factor.
      if (!on_bottom_ && !on_bottom_failure_.empty()) throw SolverError(on_bottom_failure_);
      const model::LoadParameters drilling = Sliding(OnBottom(friction), 0.0, rpm);
      // Answered at rest at the friction before (its friction walks the contacts around the hole):
      // the equilibrium at rest does not depend on the friction, and neither does the answer.
      if (!on_bottom_at_rest_.empty()) {
        notes_.push_back(on_bottom_at_rest_);
        point.on_bottom_torque =
            ReadSurface(model_, above_, *on_bottom_, drilling, Motion::Rotating, friction).surface_torque;
        return;
      }
      const std::size_t noted = notes_.size();
      on_bottom_ = on_bottom_ ? Solve(drilling, &*on_bottom_, "on bottom") : OnBottomCold(drilling);
      if (notes_.size() > noted) on_bottom_at_rest_ = notes_.back();
      point.on_bottom_torque =
          ReadSurface(model_, above_, *on_bottom_, drilling, Motion::Rotating, friction).surface_torque;
    });
    for (const std::string& note : notes_) point.message += (point.message.empty() ? "" : "; ") + note;
    return point;
  }

 private:
  // The prefix of the solvers' progress lines of the run that follows.
  void Label(double friction, const char* run) {
    if (log_) prefix_ = fmt::format("roadmap {:.6g} m, friction {:g}, {}: ", model_.input.bit_md, friction, run);
  }

  // The run under `parameters` from `start` (or the whole chain without one); SolverError when it fails.
  // A warning (a sliding string answered at rest: its friction found no static balance, as a string
  // that whirls) is kept for the point's message; the run's values stand, as the static's do.
  VecX Solve(const model::LoadParameters& parameters, const VecX* start, const char* run) {
    const analyses::StaticOutcome outcome =
        analyses::SolveStaticEquilibrium(model_.input, model_.built, static_settings_, parameters, start);
    if (!outcome.converged) throw SolverError(fmt::format("{}: {}", run, outcome.failure));
    for (const std::string& warning : outcome.warnings) notes_.push_back(fmt::format("{}: {}", run, warning));
    return outcome.q;
  }

  // The first rotating run: from the string at rest twisted by the friction torque it will carry,
  // Newton at the full friction; else the friction continued from rest, else the whole chain.
  VecX FromRest(const model::LoadParameters& parameters) {
    model::ModelInput no_torque = model_.input;
    no_torque.operation.torque_on_bit = 0.0;
    VecX twisted = *rest_;
    analyses::TwistUnderTorque(no_torque, model_.built, twisted, parameters);
    const analyses::StaticOutcome direct =
        analyses::SolveFromNeighbour(model_.built, static_settings_, parameters, twisted, kDirectIterations);
    if (direct.converged) return direct.q;
    const analyses::FrictionContinuation moving =
        analyses::ContinueInFriction(model_.built, static_settings_, parameters, *rest_);
    if (moving.converged) return moving.q;
    return Solve(parameters, nullptr, "rotating off bottom");
  }

  // The first run on bottom: the whole chain, from the string resting on the wall under the WOB. (From
  // the string off bottom, the bit centred and the WOB applied at once, the string slides down the
  // hole by its change of stretch, ~0.4 m over 7 400 ft, and the BHA's contacts all change: Newton
  // thrashed and the energy's minimum took 35 iterations where the cold solve takes 7.)
  VecX OnBottomCold(const model::LoadParameters& parameters) {
    try {
      return Solve(parameters, nullptr, "on bottom");
    } catch (const SolverError& error) {
      on_bottom_failure_ = error.what();
      throw;
    }
  }

  CaseModel model_;
  std::optional<model::ModelInput> above_;  // the pipe above the model, by the soft string
  const analyses::RoadmapSettings& settings_;
  analyses::StaticSettings static_settings_;
  std::optional<VecX> rest_, pick_up_, slack_off_, rotating_, on_bottom_;
  std::string on_bottom_failure_;  // why the first on-bottom run failed at this depth
  std::vector<std::string> notes_;  // the warnings of the point's runs
  std::string on_bottom_at_rest_;   // the warning of an on-bottom run answered at rest
  std::function<void(const std::string&)> log_;
  std::string prefix_;  // of the log's lines: the depth, friction factor and run
};

RoadmapPoint FailedPoint(double md, double friction, const std::string& message) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {md, friction, nan, nan, nan, nan, nan, message};
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
  try {
    io::Case at = StiffCaseAtDepth(c, bit_md, settings);
    at.input.supports.clear();  // the rig's: the hook at the top, the bit at the hole's centre on bottom
    runs.emplace(at, settings, log);
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
      points[k] = runs->Point(bit_md, settings.friction[k]);
    } catch (const SolverError& error) {
      points[k] = FailedPoint(bit_md, settings.friction[k], error.what());
    }
  }
  return points;
}

}  // namespace drillflex::pipeline
