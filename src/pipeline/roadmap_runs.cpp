#include "pipeline/roadmap_runs.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <optional>

#include <fmt/format.h>

#include "analyses/resting_start.hpp"
#include "analyses/static_minimum.hpp"
#include "analyses/static_solve.hpp"
#include "core/error.hpp"
#include "core/profile.hpp"
#include "model/spring_elements.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {
namespace {

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

// The tension and torque at the surface of an equilibrium q: the hook's reaction at the model's top
// (the string frame: x up the hole) and the pipe above the model to the surface, hanging along the
// hole without friction (model::StringAboveWeight: less than a joint).
struct SurfaceReading {
  double hook_load = 0.0;       // N
  double surface_torque = 0.0;  // N·m, clockwise looking down-hole
};

SurfaceReading ReadSurface(const CaseModel& m, const VecX& q, const model::LoadParameters& parameters) {
  const model::SystemModel& system = m.built.system;
  const auto poses = system.Poses(q);
  const VecX rest = VecX::Zero(system.num_velocities());
  for (const int index : m.built.support_elements) {
    const auto* support = dynamic_cast<const model::SupportElement*>(system.elements()[index].get());
    if (support == nullptr || support->holds_bit()) continue;
    const Vec6 reaction = support->Reaction(system.StateOf(*support, poses, rest, 0.0, parameters));
    // The support's moment about x resists the drive's clockwise turn.
    return {reaction.x() + model::StringAboveWeight(m.input), -reaction[3]};
  }
  throw LogicError("roadmap: the model has no hook support at its top");
}

// The runs of one depth, in the order of RunRoadmapDepth's header.
class DepthRuns {
 public:
  DepthRuns(const io::Case& at, const analyses::RoadmapSettings& settings)
      : model_(BuildCaseModel(at)), settings_(settings),
        static_settings_(at.analyses.static_analysis.value_or(analyses::StaticSettings{})) {
    static_settings_.log = nullptr;
  }

  // At rest off bottom (no friction): the start of the first friction factor's runs.
  void SolveAtRest() {
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
    auto run = [&](auto&& solve) {
      try {
        solve();
      } catch (const SolverError& error) {
        point.message += (point.message.empty() ? "" : "; ") + std::string(error.what());
      }
    };
    run([&] {
      const model::LoadParameters pick_up = Sliding(OffBottom(friction), trip, 0.0);
      pick_up_ = Solve(pick_up, pick_up_ ? &*pick_up_ : &*rest_, "pulling out");
      point.pick_up = ReadSurface(model_, *pick_up_, pick_up).hook_load;
    });
    run([&] {
      const model::LoadParameters slack_off = Sliding(OffBottom(friction), -trip, 0.0);
      slack_off_ = Solve(slack_off, slack_off_ ? &*slack_off_ : &*rest_, "running in");
      point.slack_off = ReadSurface(model_, *slack_off_, slack_off).hook_load;
    });
    run([&] {
      const model::LoadParameters rotating = Sliding(OffBottom(friction), 0.0, rpm);
      rotating_ = rotating_ ? Solve(rotating, &*rotating_, "rotating off bottom") : FromRest(rotating);
      const SurfaceReading off_bottom = ReadSurface(model_, *rotating_, rotating);
      point.rotating = off_bottom.hook_load;
      point.off_bottom_torque = off_bottom.surface_torque;
    });
    run([&] {
      // The string at rest on bottom does not depend on the friction: a depth where its energy's
      // minimum was not found is not solved again at every friction factor.
      if (!on_bottom_ && !on_bottom_failure_.empty()) throw SolverError(on_bottom_failure_);
      const model::LoadParameters drilling = Sliding(OnBottom(friction), 0.0, rpm);
      // Answered at rest at the friction before (its friction walks the contacts around the hole):
      // the equilibrium at rest does not depend on the friction, and neither does the answer.
      if (!on_bottom_at_rest_.empty()) {
        notes_.push_back(on_bottom_at_rest_);
        point.on_bottom_torque = ReadSurface(model_, *on_bottom_, drilling).surface_torque;
        return;
      }
      const std::size_t noted = notes_.size();
      on_bottom_ = on_bottom_ ? Solve(drilling, &*on_bottom_, "on bottom") : OnBottomCold(drilling);
      if (notes_.size() > noted) on_bottom_at_rest_ = notes_.back();
      point.on_bottom_torque = ReadSurface(model_, *on_bottom_, drilling).surface_torque;
    });
    for (const std::string& note : notes_) point.message += (point.message.empty() ? "" : "; ") + note;
    return point;
  }

 private:
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
  const analyses::RoadmapSettings& settings_;
  analyses::StaticSettings static_settings_;
  std::optional<VecX> rest_, pick_up_, slack_off_, rotating_, on_bottom_;
  std::string on_bottom_failure_;  // why the first on-bottom run failed at this depth
  std::vector<std::string> notes_;  // the warnings of the point's runs
  std::string on_bottom_at_rest_;   // the warning of an on-bottom run answered at rest
};

RoadmapPoint FailedPoint(double md, double friction, const std::string& message) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {md, friction, nan, nan, nan, nan, nan, message};
}

}  // namespace

std::vector<RoadmapPoint> RunRoadmapDepth(const io::Case& c, const analyses::RoadmapSettings& settings, double bit_md) {
  const profile::Scope scope("roadmap: a depth");
  std::vector<RoadmapPoint> points(settings.friction.size());
  std::vector<std::size_t> order(settings.friction.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return settings.friction[a] < settings.friction[b]; });
  std::optional<DepthRuns> runs;
  try {
    io::Case at = CaseAtDepth(c, bit_md);
    at.input.supports.clear();  // the rig's: the hook at the top, the bit at the hole's centre on bottom
    runs.emplace(at, settings);
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
