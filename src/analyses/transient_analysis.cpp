#include "analyses/transient_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "analyses/modes_analysis.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/string_stations.hpp"
#include "analyses/wall_offsets.hpp"
#include "core/error.hpp"
#include "model/drive_elements.hpp"
#include "model/dynamic_problem.hpp"
#include "model/lateral_fluid.hpp"
#include "model/node_kinematics.hpp"
#include "model/wall_contact.hpp"

namespace drillflex::analyses {
namespace {

// What one probe reads: a string station and the wall contact element at its node, if any.
struct Probe {
  Index station = 0;
  std::optional<model::ElementHandle<model::WallContactElement>> contact;
};

Index NearestStation(const std::vector<Station>& stations, double s) {
  Index best = 0;
  for (Index i = 0; i < std::ssize(stations); ++i) {
    if (std::abs(stations[i].s - s) < std::abs(stations[best].s - s)) best = i;
  }
  return best;
}

std::optional<model::ElementHandle<model::WallContactElement>> ContactAt(const model::BuiltModel& built,
                                                                          const Station& station) {
  const model::Body& body = built.system.bodies()[station.body];
  for (const auto handle : built.contacts) {
    const model::WallContactElement& contact = built.Get(handle);
    if (contact.bodies()[0] == &body && contact.node() == station.node) return handle;
  }
  return std::nullopt;
}

// The spin rate of a station's node, clockwise looking down-hole (−ω_x of the string frame), rad/s.
double SpinRate(const model::SystemModel& model, const std::vector<model::BodyPose>& poses, const VecX& v,
                const Station& station) {
  const model::Body& body = model.bodies()[station.body];
  return -model::ComputeStringFrameNodeRates(body, poses[station.body], v, station.node).rotation.x();
}

// The direction of a lateral offset (y right, z high side) from the high side toward the right, [0, 2π).
double HighSideAngle(double right, double high_side) {
  const double angle = std::atan2(right, high_side);
  const double wrapped = angle < 0.0 ? angle + 2.0 * kPi : angle;
  return wrapped >= 2.0 * kPi ? 0.0 : wrapped;  // −0 and tiny negative angles round to 2π
}

TransientSample Sample(const model::BuiltModel& built, const std::vector<Station>& stations,
                       const std::vector<Probe>& probes, double time, const VecX& q, const VecX& v) {
  const model::SystemModel& model = built.system;
  // Only the stations read: the bit, the top, then the probes (a whole string's forces and wall
  // offsets took ~1 ms a sample, a tenth of the bundled example's run at 100 samples a second).
  std::vector<Index> read = {0, std::ssize(stations) - 1};
  for (const Probe& probe : probes) read.push_back(probe.station);
  std::vector<StaticNodeResult> nodes = StaticNodeResults(built, q, 1.0, read);
  AddWallOffsets(built, q, nodes, read);
  const auto poses = model.Poses(q);
  TransientSample sample;
  sample.time = time;
  const StaticNodeResult& bit = nodes[0];
  const StaticNodeResult& top = nodes[1];
  sample.surface_speed = SpinRate(model, poses, v, stations.back());
  sample.bit_speed = SpinRate(model, poses, v, stations.front());
  // The section torque M_x is what the string above exerts about +x (up-hole): the torque turning
  // the string below clockwise (looking down-hole) is −M_x.
  sample.surface_torque = -top.torque;
  sample.hook_load = top.axial_force;
  sample.weight_on_bit = -bit.axial_force;
  sample.torque_on_bit = -bit.torque;
  // What the drives deliver, when they hold the top: the force on the top node itself (the top
  // element's elastic force is that of the section half an element in, and with a few modes a body
  // its end strain is off by tens of % under distributed inertia loads). The springs are stiff (a
  // support's), so their force carries k times the positions' Newton error: ~1e-3 × tolerance × 1e-3
  // rad or m (transient_analysis.cpp, TransientIntegratorOptions), e.g. 3 N·m for 5 in pipe at the
  // default tolerance.
  if (built.top_drive) {
    const model::TopDriveElement& drive = model.Get(*built.top_drive);
    sample.surface_torque = drive.Torque(model.StateOf(drive, poses, v, time, 1.0));
  }
  if (built.block) {
    const model::BlockElement& block = model.Get(*built.block);
    sample.hook_load = block.HookLoad(model.StateOf(block, poses, v, time, 1.0));
  }
  // With a bottom contact the WOB is what it carries (0 while the bit is off bottom).
  if (built.bit_bottom) {
    const model::BitBottomElement& bottom = model.Get(*built.bit_bottom);
    sample.weight_on_bit = bottom.ContactForce(model.StateOf(bottom, poses, v, time, 1.0));
  }
  const model::Energies energies = model.ComputeEnergies(q, v, 1.0);
  sample.kinetic_energy = energies.kinetic;
  sample.potential_energy = energies.elastic + energies.potential;
  for (Index i = 0; i < std::ssize(probes); ++i) {
    const Probe& probe = probes[i];
    const StaticNodeResult& node = nodes[2 + i];
    ProbeSample out;
    out.lateral_y = node.displacement.y();
    out.lateral_z = node.displacement.z();
    out.whirl_angle = node.has_wall ? node.offset_high_side_angle : HighSideAngle(out.lateral_y, out.lateral_z);
    out.bending_moment = node.bending_moment;
    if (probe.contact) {
      const model::WallContactElement& contact = model.Get(*probe.contact);
      const model::WallContactResult state = contact.Result(model.StateOf(contact, poses, v, time, 1.0));
      out.contact_force = state.in_contact ? state.normal_force : 0.0;
    }
    sample.probes.push_back(out);
  }
  return sample;
}

// Whether output sample k of 0..last keeps the whole state (TransientResult::frame_q): every
// stride-th from t = 0, stride = ⌈last / (frames − 1)⌉, and the last, so at most `frames`
// (floor(last / stride) + 1 ≤ frames, one fewer when the last is not a multiple); one frame: the last.
bool KeepsFrame(long k, long last, int frames) {
  if (frames <= 0) return false;
  if (k == last) return true;
  if (frames == 1) return false;
  const long stride = (last + frames - 2) / (frames - 1);
  return k % stride == 0;
}

// max |E(t) − E(0)| over the samples relative to the largest kinetic energy reached (the energy in
// motion; the potential's zero is arbitrary under gravity). 0 when nothing moves.
double EnergyDrift(const std::vector<TransientSample>& samples) {
  double largest_kinetic = 0.0, largest_change = 0.0;
  const double start = samples.front().kinetic_energy + samples.front().potential_energy;
  for (const TransientSample& s : samples) {
    largest_kinetic = std::max(largest_kinetic, s.kinetic_energy);
    largest_change = std::max(largest_change, std::abs(s.kinetic_energy + s.potential_energy - start));
  }
  return largest_kinetic > 0.0 ? largest_change / largest_kinetic : 0.0;
}

}  // namespace

solvers::GeneralizedAlphaOptions TransientIntegratorOptions(const TransientSettings& settings) {
  solvers::GeneralizedAlphaOptions options;
  options.rho_infinity = settings.rho_infinity;
  options.relative_tolerance = settings.tolerance;
  // The absolute part: the tolerance times 1 mm (or 1 mrad, or a modal coordinate of that size), so
  // that one setting tightens both, and coordinates that barely move are not held to less.
  options.absolute_tolerance = 1e-3 * settings.tolerance;
  if (settings.time_step) {
    options.adaptive = false;
    options.initial_step = *settings.time_step;
    options.min_step = std::min(options.min_step, 1e-6 * *settings.time_step);
  } else {
    options.initial_step = std::min(settings.output_interval, 1e-4);
  }
  return options;
}

model::ModelInput TransientModelInput(const model::ModelInput& input, const TransientSettings& settings,
                                      double fluid_frequency) {
  model::ModelInput transient = input;
  if (input.fluid) transient.transient_fluid_frequency = fluid_frequency;
  transient.static_sliding.reset();
  transient.initial_loads.clear();  // they act in the start only
  transient.top_drive = settings.top_drive;
  transient.block = settings.block;
  // operation.hook_load is the hook's at the surface: the model's top carries it less the string
  // above it (model/builder.hpp StringAboveWeight; 0 when the model reaches the surface).
  if (transient.block && transient.block->at_surface) transient.block->setting.target -= model::StringAboveWeight(input);
  transient.bit_rock = settings.bit_rock;  // the builder then leaves out the bit loads the law replaces
  transient.imbalances = settings.imbalances;
  return transient;
}

double TransientFluidFrequency(const model::ModelInput& input, const model::BuiltModel& at_rest, const VecX& q0,
                               const TransientSettings& transient) {
  if (!input.fluid) return 0.0;
  if (transient.fluid_frequency) return *transient.fluid_frequency;
  const model::LateralFluid fluid = model::MakeLateralFluid(input, at_rest.system);
  if (!fluid.frequency_dependent()) return 0.0;
  ModesSettings settings;
  settings.count = 1;
  settings.kind = ModeKind::Lateral;
  const ModesResult modes = RunModes(at_rest, q0, settings, &fluid);
  const ModeResult* first = FirstLateralMode(modes);
  if (!first) {
    throw SolverError("transient: the linearized model has no lateral mode to take the fluid's damping at; "
                      "give the transient's fluid_frequency");
  }
  return 2.0 * kPi * first->frequency_hz;
}

VecX TransientStartPositions(const model::ModelInput& input, const model::BuiltModel& built,
                             const TransientSettings& settings, const StaticSettings& static_settings) {
  if (settings.start == TransientStart::Reference) return built.system.ReferencePositions();
  if (settings.initial_loads.size() != input.initial_loads.size()) {
    throw LogicError("transient: the case's model does not carry the transient's initial loads");
  }
  // The string at rest (no sliding friction) on bottom under the case's WOB and TOB, with the
  // initial loads switched on: the case's model under another parameter block.
  model::LoadParameters start;
  start.initial_load_factor = 1.0;
  start.sliding_mode = model::SlidingMode::kVelocities;
  return RunStaticInWell(input, built, static_settings, start).q;
}

TransientResult RunTransient(const model::BuiltModel& built, const VecX& q0, const TransientSettings& settings,
                             const TransientProgress& progress, const TransientSampleObserver& on_sample) {
  if (!(settings.duration > 0.0) || !(settings.output_interval > 0.0)) {
    throw LogicError("RunTransient: the duration and the output interval must be positive");
  }
  if (settings.state_frames < 0) throw LogicError("RunTransient: state_frames must not be negative");
  const model::SystemModel& model = built.system;
  const std::vector<Station> stations = StringStations(model);
  TransientResult result;
  std::vector<Probe> probes;
  for (const double s : settings.probes) {
    Probe probe;
    probe.station = NearestStation(stations, s);
    probe.contact = ContactAt(built, stations[probe.station]);
    probes.push_back(probe);
    result.probe_s.push_back(stations[probe.station].s);
  }
  const model::DynamicModelProblem problem(model);
  const solvers::GeneralizedAlphaOptions options = TransientIntegratorOptions(settings);
  solvers::GeneralizedAlphaIntegrator integrator(problem, options);
  if (progress) {
    integrator.on_step = [&](const solvers::GeneralizedAlphaState& s) { progress(s.time, settings.duration); };
  }
  integrator.Initialize(0.0, q0, VecX::Zero(model.num_velocities()));
  result.samples.push_back(Sample(built, stations, probes, 0.0, q0, integrator.state().v));
  if (on_sample) on_sample(0.0, q0, integrator.state().v);
  // Sample times k·Δt, the last one the duration itself (a shorter last interval if need be).
  const long intervals = std::max(1L, static_cast<long>(std::ceil(settings.duration / settings.output_interval - 1e-9)));
  auto keep_frame = [&](long k, double time, const VecX& q) {
    if (!KeepsFrame(k, intervals, settings.state_frames)) return;
    result.frame_times.push_back(time);
    result.frame_q.push_back(q);
  };
  keep_frame(0, 0.0, q0);
  for (long k = 1; k <= intervals; ++k) {
    const double time = k == intervals ? settings.duration : static_cast<double>(k) * settings.output_interval;
    integrator.AdvanceTo(time);
    const auto& state = integrator.state();
    result.samples.push_back(Sample(built, stations, probes, time, state.q, state.v));
    if (on_sample) on_sample(time, state.q, state.v);
    keep_frame(k, time, state.q);
  }
  result.final_q = integrator.state().q;
  result.final_v = integrator.state().v;
  result.statistics = integrator.statistics();
  result.energy_drift = EnergyDrift(result.samples);
  result.rho_infinity = settings.rho_infinity;
  return result;
}

}  // namespace drillflex::analyses
