#include "pipeline/depth_runs.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analyses/resting_start.hpp"
#include "analyses/soft_string.hpp"
#include "analyses/static_minimum.hpp"
#include "analyses/static_solve.hpp"
#include "core/error.hpp"
#include "model/spring_elements.hpp"

namespace drillflex::pipeline {
namespace {

// Newton iterations of the first rotating run at the full friction before the continuation takes over.
constexpr int kDirectIterations = 20;
// Elements of the soft string above the stiff model: at most a joint (pipeline/roadmap_soft.cpp).
constexpr double kSoftElementLength = model::kDefaultJointSpacing;

void SetFriction(model::LoadParameters& parameters, const HoleFrictionFactors& friction) {
  parameters.open_hole_friction = model::WallFriction{friction.open_hole, friction.open_hole};
  if (friction.cased_hole) parameters.cased_hole_friction = model::WallFriction{*friction.cased_hole, *friction.cased_hole};
}

// The parameter block of a run off bottom: the bit free (the hook's support holds the string), no
// WOB or torque on bit.
model::LoadParameters OffBottom(const HoleFrictionFactors& friction) {
  model::LoadParameters parameters;
  parameters.bit_support_factor = 0.0;
  parameters.weight_on_bit = 0.0;
  parameters.torque_on_bit = 0.0;
  SetFriction(parameters, friction);
  return parameters;
}

// On bottom: the bit held at the hole centre, the WOB and torque on bit (none: the case's).
model::LoadParameters OnBottom(const HoleFrictionFactors& friction, const TdRunLoads& loads) {
  model::LoadParameters parameters;
  SetFriction(parameters, friction);
  parameters.weight_on_bit = loads.weight_on_bit;
  parameters.torque_on_bit = loads.torque_on_bit;
  return parameters;
}

model::LoadParameters Sliding(model::LoadParameters parameters, double axial_speed, double rotary_speed) {
  parameters.sliding_mode = model::SlidingMode::kPrescribed;
  parameters.sliding = {axial_speed, rotary_speed};
  return parameters;
}

// The pipe above the stiff model to the surface: the depth case's top component continued from the
// model's top (its MD the "bit" of a soft string whose bottom carries the model's top tension and
// torque). Empty when the model reaches the surface.
std::optional<model::ModelInput> PipeAbove(const model::ModelInput& input) {
  const double top_md = input.bit_md - model::StringLength(input.string);
  if (!input.well || top_md <= input.well->trajectory.start_md() + 1e-6) return std::nullopt;
  model::ModelInput above = input;
  above.bit_md = top_md;
  model::Component pipe = input.string.components.back();
  pipe.count = 1;
  above.string.components = {pipe};
  return above;
}

analyses::SoftStringMotion MotionOf(TdRun run) {
  switch (run) {
    case TdRun::kPickUp: return analyses::SoftStringMotion::PickUp;
    case TdRun::kSlackOff: return analyses::SoftStringMotion::SlackOff;
    case TdRun::kRotatingOffBottom:
    case TdRun::kOnBottom: return analyses::SoftStringMotion::Rotating;
  }
  throw LogicError("DepthRuns: unknown run");
}

}  // namespace

const char* TdRunName(TdRun run) {
  switch (run) {
    case TdRun::kPickUp: return "pulling out";
    case TdRun::kSlackOff: return "running in";
    case TdRun::kRotatingOffBottom: return "rotating off bottom";
    case TdRun::kOnBottom: return "on bottom";
  }
  return "?";
}

SurfaceReading SoftSurfaceReading(const model::ModelInput& at_depth, TdRun run, const HoleFrictionFactors& friction,
                                  const TdRunLoads& loads) {
  analyses::SoftStringOperation operation;
  operation.motion = MotionOf(run);
  operation.axial_friction = operation.tangential_friction = friction.open_hole;
  if (friction.cased_hole) operation.cased_friction = model::WallFriction{*friction.cased_hole, *friction.cased_hole};
  if (run == TdRun::kOnBottom) {
    operation.weight_on_bit = loads.weight_on_bit.value_or(at_depth.operation.weight_on_bit);
    operation.torque_on_bit = loads.torque_on_bit.value_or(at_depth.operation.torque_on_bit);
  }
  operation.max_element_length = kSoftElementLength;
  const analyses::SoftStringResult soft = analyses::ComputeSoftString(at_depth, operation);
  return {soft.hook_load, soft.surface_torque};
}

DepthRuns::DepthRuns(const io::Case& at, const std::function<void(const std::string&)>& log)
    : model_(BuildCaseModel(at)), above_(PipeAbove(at.input)),
      static_settings_(at.analyses.static_analysis.value_or(analyses::StaticSettings{})), log_(log) {
  static_settings_.log = nullptr;
  if (log_) static_settings_.log = [this](const std::string& line) { log_(prefix_ + line); };
}

void DepthRuns::SolveAtRest() {
  const HoleFrictionFactors none{0.0, 0.0};
  Label(none, "at rest off bottom");
  model::LoadParameters parameters = OffBottom(none);
  parameters.sliding_mode = model::SlidingMode::kVelocities;
  rest_ = Solve(parameters, nullptr, "at rest off bottom");
}

SurfaceReading DepthRuns::Run(TdRun run, const HoleFrictionFactors& friction, const TdRunLoads& loads) {
  if (!rest_) throw LogicError("DepthRuns::Run before SolveAtRest");
  const char* name = TdRunName(run);
  Label(friction, name);
  switch (run) {
    case TdRun::kPickUp:
    case TdRun::kSlackOff: {
      const double speed = run == TdRun::kPickUp ? loads.trip_speed : -loads.trip_speed;
      const model::LoadParameters parameters = Sliding(OffBottom(friction), speed, 0.0);
      std::optional<VecX>& state = run == TdRun::kPickUp ? pick_up_ : slack_off_;
      state = Solve(parameters, state ? &*state : &*rest_, name);
      solved_[static_cast<std::size_t>(run)] = Solved{parameters, friction};
      return ReadSurface(*state, parameters, run, friction);
    }
    case TdRun::kRotatingOffBottom: {
      const model::LoadParameters parameters = Sliding(OffBottom(friction), 0.0, loads.rotary_speed);
      rotating_ = rotating_ ? Solve(parameters, &*rotating_, name) : FromRest(parameters);
      solved_[static_cast<std::size_t>(run)] = Solved{parameters, friction};
      return ReadSurface(*rotating_, parameters, run, friction);
    }
    case TdRun::kOnBottom: {
      // The string at rest on bottom does not depend on the friction: a depth where its energy's
      // minimum was not found is not solved again at every friction.
      if (!on_bottom_ && !on_bottom_failure_.empty()) throw SolverError(on_bottom_failure_);
      const model::LoadParameters parameters = Sliding(OnBottom(friction, loads), 0.0, loads.rotary_speed);
      // Answered at rest at the friction before (its friction walks the contacts around the hole):
      // the equilibrium at rest does not depend on the friction, and neither does the answer, as long
      // as the WOB and torque on bit are the same.
      const bool same_loads = on_bottom_loads_ && on_bottom_loads_->weight_on_bit == loads.weight_on_bit &&
                              on_bottom_loads_->torque_on_bit == loads.torque_on_bit;
      if (!on_bottom_at_rest_.empty() && same_loads) {
        notes_.push_back(on_bottom_at_rest_);
        solved_[static_cast<std::size_t>(run)] = Solved{parameters, friction};
        return ReadSurface(*on_bottom_, parameters, run, friction);
      }
      const std::size_t noted = notes_.size();
      on_bottom_ = on_bottom_ ? Solve(parameters, &*on_bottom_, name) : OnBottomCold(parameters);
      on_bottom_loads_ = loads;
      on_bottom_at_rest_ = notes_.size() > noted ? notes_.back() : std::string();
      solved_[static_cast<std::size_t>(run)] = Solved{parameters, friction};
      return ReadSurface(*on_bottom_, parameters, run, friction);
    }
  }
  throw LogicError("DepthRuns: unknown run");
}

void DepthRuns::Label(const HoleFrictionFactors& friction, const char* run) {
  if (!log_) return;
  const std::string cased = friction.cased_hole ? fmt::format(", cased {:g}", *friction.cased_hole) : std::string();
  prefix_ = fmt::format("{:.6g} m, friction {:g}{}, {}: ", model_.input.bit_md, friction.open_hole, cased, run);
}

VecX DepthRuns::Solve(const model::LoadParameters& parameters, const VecX* start, const char* run) {
  const analyses::StaticOutcome outcome =
      analyses::SolveStaticEquilibrium(model_.input, model_.built, static_settings_, parameters, start);
  if (!outcome.converged) throw SolverError(fmt::format("{}: {}", run, outcome.failure));
  for (const std::string& warning : outcome.warnings) notes_.push_back(fmt::format("{}: {}", run, warning));
  return outcome.q;
}

// The first rotating run: from the string at rest twisted by the friction torque it will carry,
// Newton at the full friction; else the friction continued from rest, else the whole chain.
VecX DepthRuns::FromRest(const model::LoadParameters& parameters) {
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
VecX DepthRuns::OnBottomCold(const model::LoadParameters& parameters) {
  try {
    return Solve(parameters, nullptr, "on bottom");
  } catch (const SolverError& error) {
    on_bottom_failure_ = error.what();
    throw;
  }
}

// The model's top and the pipe above of an equilibrium q: the hook's reaction at the model's top (the
// string frame: x up the hole) is the tension there, its moment about x the torque; the soft string above
// (Johancsik with the rotating string's climb, as the stiff model has it) carries them to the surface
// under the run's motion and friction.
DepthRuns::Above DepthRuns::CarryToSurface(const VecX& q, const model::LoadParameters& parameters, TdRun run,
                                           const HoleFrictionFactors& friction) const {
  const model::SystemModel& system = model_.built.system;
  const auto poses = system.Poses(q);
  const VecX rest = VecX::Zero(system.num_velocities());
  for (const auto handle : model_.built.supports) {
    const model::SupportElement& support = system.Get(handle);
    if (support.holds_bit()) continue;
    const Vec6 reaction = support.Reaction(system.StateOf(support, poses, rest, 0.0, parameters));
    // The support's moment about x resists the drive's clockwise turn.
    Above above{{reaction.x(), -reaction[3]}, std::nullopt};
    if (!above_) return above;
    analyses::SoftStringOperation operation;
    operation.motion = MotionOf(run);
    operation.axial_friction = operation.tangential_friction = friction.open_hole;
    if (friction.cased_hole) operation.cased_friction = model::WallFriction{*friction.cased_hole, *friction.cased_hole};
    operation.weight_on_bit = -above.at_top.hook_load;  // the model's top pulls the pipe above down
    operation.torque_on_bit = above.at_top.surface_torque;
    operation.max_element_length = kSoftElementLength;
    operation.wall_climb = true;
    above.soft = analyses::ComputeSoftString(*above_, operation);
    return above;
  }
  throw LogicError("DepthRuns: the model has no hook support at its top");
}

// The reading at the surface of an equilibrium q: the model's top carried there (CarryToSurface).
SurfaceReading DepthRuns::ReadSurface(const VecX& q, const model::LoadParameters& parameters, TdRun run,
                                      const HoleFrictionFactors& friction) const {
  const Above above = CarryToSurface(q, parameters, run, friction);
  return above.soft ? SurfaceReading{above.soft->hook_load, above.soft->surface_torque} : above.at_top;
}

std::vector<analyses::StaticNodeResult> DepthRuns::Stations(TdRun run) const {
  const std::optional<Solved>& solved = solved_[static_cast<std::size_t>(run)];
  const std::optional<VecX>& q = run == TdRun::kPickUp             ? pick_up_
                                 : run == TdRun::kSlackOff          ? slack_off_
                                 : run == TdRun::kRotatingOffBottom ? rotating_
                                                                    : on_bottom_;
  if (!solved || !q) throw LogicError(fmt::format("DepthRuns::Stations before a run {}", TdRunName(run)));
  std::vector<analyses::StaticNodeResult> stations =
      analyses::StaticNodeResults(model_.built, *q, solved->parameters);
  const Above above = CarryToSurface(*q, solved->parameters, run, solved->friction);
  if (!above.soft) return stations;
  const double top = model::StringLength(model_.input.string);  // s of the model's top, m
  for (const analyses::SoftStringStation& station : above.soft->stations) {
    if (station.s <= 0.0) continue;  // the model's top: its own station
    analyses::StaticNodeResult node;
    node.s = top + station.s;
    node.has_wall = true;
    node.md = station.md;
    node.axial_force = station.axial_force;
    node.torque = station.torque;
    stations.push_back(node);
  }
  return stations;
}

}  // namespace drillflex::pipeline
