#include "analyses/vibration_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <exception>
#include <map>
#include <memory>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <fmt/format.h>

#include "analyses/critical_speeds.hpp"
#include "analyses/response_solver.hpp"
#include "analyses/string_stations.hpp"
#include "core/error.hpp"
#include "model/node_kinematics.hpp"
#include "model/wall_contact.hpp"
#include "solvers/projected_harmonic.hpp"
#include "solvers/spectrum_count.hpp"

namespace drillflex::analyses {
namespace {

using Complex = std::complex<double>;
using ComplexVec = Eigen::VectorXcd;

#ifdef _OPENMP
int MaxThreads() { return omp_get_max_threads(); }
int ThreadIndex() { return omp_get_thread_num(); }
#else
int MaxThreads() { return 1; }
int ThreadIndex() { return 0; }
#endif

// The largest |u(t)| of u(t) = Re(U e^{iωt}) for a complex vector U = a + i b: the major
// semi-axis of the orbit, max over t of |a cos ωt − b sin ωt| =
// sqrt((|a|² + |b|²)/2 + sqrt(((|a|² − |b|²)/2)² + (a·b)²)).
double OrbitSemiMajorAxis(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double half_sum = 0.5 * (a.squaredNorm() + b.squaredNorm());
  const double half_difference = 0.5 * (a.squaredNorm() - b.squaredNorm());
  const double ab = a.dot(b);
  return std::sqrt(half_sum + std::sqrt(half_difference * half_difference + ab * ab));
}

// A station's lateral translation (string frame y, z) as rows acting on its body's velocity block:
// rows y, z of [Fᵀ, Fᵀ A (−ũ_k), Fᵀ A Φ_k], F the string frame (model/node_kinematics.hpp ComputeStringFrameNodeRates).
struct StationMap {
  Index v_offset = 0;
  // Two fixed rows: the products below stay on the stack (a dynamic 2-row result was a heap
  // allocation per station and response).
  Eigen::Matrix<double, 2, Eigen::Dynamic> lateral;  // 2 × (6 + n_f)
  double clearance = -1.0;  // radial clearance at q with an open wall contact, m; < 0: none
  double s = 0.0;
};

// An FE element's curvature rows (body frame bending y, z) on η, and E·OD/2.
struct ElementMap {
  Index eta_offset = 0;
  Eigen::Matrix<double, 2, Eigen::Dynamic> curvature;  // 2 × n_f: (Ψ_{k+1} − Ψ_k)_{y,z} / ℓ
  double stress_per_curvature = 0.0;
};

// A contact closed at q: n ᵀ L_k (global radial direction on the body block) and k_n.
struct ContactMap {
  Index v_offset = 0;
  VecX radial;  // 6 + n_f
  double stiffness = 0.0;
};

// Open-contact clearances and closed contacts at q, by (body, node).
struct WallState {
  std::map<std::pair<Index, Index>, double> clearance;  // open contacts: R_h − R_c − ρ, m
  std::vector<ContactMap> closed;
};

WallState ReadWall(const model::BuiltModel& built, const std::vector<model::BodyPose>& poses) {
  WallState wall;
  const model::SystemModel& model = built.system;
  const VecX v = VecX::Zero(model.num_velocities());
  for (const auto handle : built.contacts) {
    const model::WallContactElement* contact = &model.Get(handle);
    const model::Body* body = contact->bodies().front();
    const Index b = model.IndexOf(body);
    const model::WallContactResult result = contact->Result(model.StateOf(*contact, poses, v, 0.0, 1.0));
    if (result.in_contact) {
      ContactMap map;
      map.v_offset = body->v_offset;
      const MatX jacobian = model::NodeTranslationJacobian(*body, poses[b], contact->node());
      map.radial = (result.normal.transpose() * jacobian).transpose();
      map.stiffness = contact->parameters().normal_stiffness;
      wall.closed.push_back(std::move(map));
    } else {
      wall.clearance[{b, contact->node()}] = -result.penetration;
    }
  }
  return wall;
}

std::vector<StationMap> MapStations(const model::SystemModel& model, const std::vector<model::BodyPose>& poses,
                                    const WallState& wall) {
  std::vector<StationMap> maps;
  for (const Station& station : StringStations(model)) {
    const model::Body& body = model.bodies()[station.body];
    const Mat3 frame = body.reference_orientation.toRotationMatrix();
    StationMap map;
    map.v_offset = body.v_offset;
    map.s = station.s;
    const MatX jacobian = model::NodeTranslationJacobian(body, poses[station.body], station.node);
    map.lateral = (frame.transpose() * jacobian).bottomRows<2>();
    const auto found = wall.clearance.find({station.body, station.node});
    if (found != wall.clearance.end()) map.clearance = found->second;
    maps.push_back(std::move(map));
  }
  return maps;
}

std::vector<ElementMap> MapElements(const model::SystemModel& model) {
  std::vector<ElementMap> maps;
  for (const model::Body& body : model.bodies()) {
    const auto& spec = body.reduced->spec;
    for (Index k = 0; k + 1 < body.node_count(); ++k) {
      const double length = body.reduced->node_positions[k + 1].x() - body.reduced->node_positions[k].x();
      ElementMap map;
      map.eta_offset = body.v_offset + 6;
      map.curvature =
          (body.reduced->node_rotation_modes[k + 1] - body.reduced->node_rotation_modes[k]).bottomRows<2>() / length;
      // σ = E c κ with c = OD/2 (the bending stress of static_analysis.hpp: M c / I, M = E I κ).
      map.stress_per_curvature = spec.material.youngs_modulus * 0.5 * spec.section.outer_diameter;
      maps.push_back(std::move(map));
    }
  }
  return maps;
}

// The generalized force of a force f and moment m (string frame at the node, complex amplitudes)
// at node k: Q = [F; u_k × AᵀF + AᵀM; Φ_kᵀAᵀF + Ψ_kᵀAᵀM] with F, M global (model/node_force.hpp).
ComplexVec NodeLoad(const model::SystemModel& model, const std::vector<model::BodyPose>& poses, double s,
                    const Eigen::Vector3cd& force_string, const Eigen::Vector3cd& moment_string) {
  const auto [b, node] = model.NodeAt(s);
  const model::Body& body = model.bodies()[b];
  const model::BodyPose& pose = poses[b];
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  const Eigen::Vector3cd force_body = (pose.A.transpose() * frame).cast<Complex>() * force_string;
  const Eigen::Vector3cd moment_body = (pose.A.transpose() * frame).cast<Complex>() * moment_string;
  const Eigen::Vector3cd offset = pose.NodeOffset(body, node).cast<Complex>();
  ComplexVec load = ComplexVec::Zero(model.num_velocities());
  load.segment<3>(body.v_offset) = frame.cast<Complex>() * force_string;
  load.segment<3>(body.v_offset + 3) = offset.cross(force_body) + moment_body;
  load.segment(body.v_offset + 6, body.flexible_count) =
      body.reduced->node_translation_modes[node].transpose().cast<Complex>() * force_body +
      body.reduced->node_rotation_modes[node].transpose().cast<Complex>() * moment_body;
  return load;
}

// Lateral force rotating forward (y toward z): Re((e_y − i e_z) e^{iωt}) = cos ωt e_y + sin ωt e_z.
Eigen::Vector3cd RotatingLateral(double amplitude) { return Eigen::Vector3cd(0.0, amplitude, Complex(0.0, -amplitude)); }

// The middle of the string's first motor, m from the bit; NaN without one.
double MotorMiddle(const model::StringConfig& string) {
  double s = 0.0;
  for (const model::Component& component : string.components) {
    const double span = component.length * component.count;
    if (component.type == model::ComponentType::Motor) return s + 0.5 * span;
    s += span;
  }
  return std::nan("");
}

const model::Component* FirstMotor(const model::StringConfig& string) {
  for (const model::Component& component : string.components) {
    if (component.type == model::ComponentType::Motor) return &component;
  }
  return nullptr;
}

// The load amplitude of an excitation at rotary speed Ω (the imbalance grows with Ω²).
ComplexVec ExcitationLoad(const model::SystemModel& model, const std::vector<model::BodyPose>& poses,
                          const model::ModelInput& input, const Excitation& excitation, double rotary_speed) {
  const Eigen::Vector3cd none = Eigen::Vector3cd::Zero();
  switch (excitation.type) {
    case ExcitationType::Imbalance:
      return NodeLoad(model, poses, excitation.at, RotatingLateral(excitation.imbalance * rotary_speed * rotary_speed),
                      none);
    case ExcitationType::Bit: {
      Eigen::Vector3cd force = RotatingLateral(excitation.lateral);
      force.x() = excitation.axial;
      return NodeLoad(model, poses, 0.0, force, Eigen::Vector3cd(excitation.torsional, 0.0, 0.0));
    }
    case ExcitationType::Motor: {
      const double at = excitation.at >= 0.0 ? excitation.at : MotorMiddle(input.string);
      return NodeLoad(model, poses, at, RotatingLateral(excitation.lateral), none);
    }
  }
  throw LogicError("ExcitationLoad: unknown excitation type");
}

}  // namespace

std::string ExcitationName(const Excitation& excitation) {
  switch (excitation.type) {
    case ExcitationType::Imbalance: return "imbalance 1×";
    case ExcitationType::Bit: return fmt::format("bit {}×", excitation.harmonic);
    case ExcitationType::Motor: return "motor";
  }
  throw LogicError("ExcitationName: unknown excitation type");
}

double ExcitationFrequency(const Excitation& excitation, double rotary_speed, double motor_speed) {
  switch (excitation.type) {
    case ExcitationType::Imbalance: return rotary_speed;
    case ExcitationType::Bit: return excitation.harmonic * rotary_speed;
    case ExcitationType::Motor: return excitation.lobes * motor_speed;
  }
  throw LogicError("ExcitationFrequency: unknown excitation type");
}

double MotorSpeed(const Excitation& excitation, const model::ModelInput& input, Index index) {
  if (excitation.type != ExcitationType::Motor) return 0.0;
  const std::string key = fmt::format("analyses.vibration.excitations[{}]", index);
  const model::Component* motor = FirstMotor(input.string);
  if (excitation.lobes < 1 && !(motor && motor->lobes)) {
    throw InputError({"", excitation.source_line, 0}, key + ".lobes",
                     "a motor excitation needs 'lobes' (here or on the string's motor)");
  }
  if (excitation.at < 0.0 && !motor) {
    throw InputError({"", excitation.source_line, 0}, key + ".at", "no motor in the string: give 'at'");
  }
  if (excitation.motor_speed) return *excitation.motor_speed;
  if (motor && motor->speed_per_flow && input.operation.flow_rate) {
    return *motor->speed_per_flow * *input.operation.flow_rate;  // rad/m³ × m³/s
  }
  throw InputError({"", excitation.source_line, 0}, key + ".speed",
                   "a motor excitation needs the motor speed: 'speed', or the motor's rev_per_volume and "
                   "operation.flow_rate");
}

namespace {

// Excitations with the motor's lobes and rotor speed filled in.
struct ResolvedExcitation {
  Excitation excitation;
  double motor_speed = 0.0;  // rad/s
};

std::vector<ResolvedExcitation> Resolve(const VibrationSettings& settings, const model::ModelInput& input) {
  std::vector<ResolvedExcitation> resolved;
  for (Index i = 0; i < std::ssize(settings.excitations); ++i) {
    ResolvedExcitation item{settings.excitations[i], 0.0};
    item.motor_speed = MotorSpeed(item.excitation, input, i);
    if (item.excitation.type == ExcitationType::Motor && item.excitation.lobes < 1) {
      item.excitation.lobes = *FirstMotor(input.string)->lobes;
    }
    resolved.push_back(item);
  }
  return resolved;
}

// Sums the amplitudes of one response X into the per-station, per-element, per-contact totals.
// by_excitation: per excitation, the largest station displacement of the response at its frequency
// (the one that drives a peak of the sum).
struct Amplitudes {
  std::vector<double> displacement, stress, contact, by_excitation;

  // Returns the largest station displacement of x alone.
  double Add(const ComplexVec& x, const std::vector<StationMap>& stations, const std::vector<ElementMap>& elements,
             const std::vector<ContactMap>& contacts) {
    const VecX re = x.real(), im = x.imag();
    double largest = 0.0;
    for (Index i = 0; i < std::ssize(stations); ++i) {
      const StationMap& map = stations[i];
      const Eigen::Index n = map.lateral.cols();
      const double amplitude =
          OrbitSemiMajorAxis(map.lateral * re.segment(map.v_offset, n), map.lateral * im.segment(map.v_offset, n));
      displacement[i] += amplitude;
      largest = std::max(largest, amplitude);
    }
    for (Index e = 0; e < std::ssize(elements); ++e) {
      const ElementMap& map = elements[e];
      const Eigen::Index n = map.curvature.cols();
      stress[e] += map.stress_per_curvature * OrbitSemiMajorAxis(map.curvature * re.segment(map.eta_offset, n),
                                                                 map.curvature * im.segment(map.eta_offset, n));
    }
    for (Index c = 0; c < std::ssize(contacts); ++c) {
      const ContactMap& map = contacts[c];
      const Eigen::Index n = map.radial.size();
      const double a = map.radial.dot(re.segment(map.v_offset, n)), b = map.radial.dot(im.segment(map.v_offset, n));
      contact[c] += map.stiffness * std::sqrt(a * a + b * b);
    }
    return largest;
  }

  void Accumulate(const Amplitudes& other) {
    for (auto [mine, theirs] : {std::pair{&displacement, &other.displacement}, std::pair{&stress, &other.stress},
                                std::pair{&contact, &other.contact}, std::pair{&by_excitation, &other.by_excitation}}) {
      for (std::size_t i = 0; i < mine->size(); ++i) (*mine)[i] += (*theirs)[i];
    }
  }
};

// The critical RPMs (the peaks of the severity curve), each with the excitation that drives it: the
// one (following the rotary speed) whose response is largest there; ranked, most severe first.
void FindCriticalSpeeds(const VibrationSettings& settings, const std::vector<ResolvedExcitation>& excitations,
                        const std::vector<Amplitudes>& sums, VibrationResult& result) {
  const bool ratio = !result.max_clearance_ratio.empty();
  const std::vector<double>& curve = ratio ? result.max_clearance_ratio : result.max_lateral_displacement;
  for (const std::size_t i : FindProminentPeaks(curve, kCriticalPeakProminence)) {
    result.critical_rotary_speeds.push_back(result.rotary_speeds[i]);
    CriticalSpeed critical;
    critical.rotary_speed = result.rotary_speeds[i];
    critical.severity = curve[i];
    critical.displacement = result.max_lateral_displacement[i];
    critical.bending_stress = result.max_bending_stress[i];
    double driving = -1.0;
    for (Index e = 0; e < std::ssize(excitations); ++e) {
      if (excitations[e].excitation.type == ExcitationType::Motor || sums[i].by_excitation[e] <= driving) continue;
      driving = sums[i].by_excitation[e];
      critical.excitation = e;
      critical.frequency = ExcitationFrequency(excitations[e].excitation, result.rotary_speeds[i], excitations[e].motor_speed);
    }
    result.critical_speeds.push_back(critical);
  }
  std::stable_sort(result.critical_speeds.begin(), result.critical_speeds.end(),
                   [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.severity > b.severity; });
  std::vector<bool> ok(result.rotary_speeds.size());
  for (Index i = 0; i < std::ssize(ok); ++i) {
    ok[i] = result.max_bending_stress[i] <= settings.stress_limit &&
            (!ratio || result.max_clearance_ratio[i] <= settings.clearance_fraction);
  }
  for (const IndexRange& run : FindRuns(ok)) result.safe_windows.push_back({result.rotary_speeds[run.first], result.rotary_speeds[run.last]});
  // The quietest ranges: severity within kQuietFactor of the sweep's least.
  const double least = *std::min_element(curve.begin(), curve.end());
  std::vector<bool> quiet(curve.size());
  for (Index i = 0; i < std::ssize(quiet); ++i) quiet[i] = curve[i] <= kQuietFactor * least;
  for (const IndexRange& run : FindRuns(quiet)) {
    result.quietest_windows.push_back({result.rotary_speeds[run.first], result.rotary_speeds[run.last]});
  }
}

// One excitation at one sweep point: its frequency there.
struct SweepTask {
  double frequency = 0.0;  // rad/s
  Index point = 0;         // RPM index
  Index excitation = 0;
};

// The load of an excitation is its unit load (at Ω = 1 rad/s) times this: the imbalance's m e Ω².
double LoadScale(const Excitation& excitation, double rotary_speed) {
  return excitation.type == ExcitationType::Imbalance ? rotary_speed * rotary_speed : 1.0;
}

struct FrequencyGroup {
  std::size_t begin = 0, end = 0;  // tasks at one frequency (sorted by point inside)
};

// Sorts the tasks by frequency (those within 1e-9 relative are one frequency: a bit at 3× 20 rpm and
// an imbalance at 60 rpm; a motor's fixed frequency once for the whole sweep) and by point inside.
std::vector<FrequencyGroup> GroupByFrequency(std::vector<SweepTask>& tasks) {
  std::stable_sort(tasks.begin(), tasks.end(), [](const SweepTask& a, const SweepTask& b) { return a.frequency < b.frequency; });
  std::vector<FrequencyGroup> groups;
  for (std::size_t begin = 0; begin < tasks.size();) {
    std::size_t end = begin;
    while (end < tasks.size() && tasks[end].frequency <= tasks[begin].frequency * (1.0 + 1e-9)) ++end;
    std::stable_sort(tasks.begin() + static_cast<std::ptrdiff_t>(begin), tasks.begin() + static_cast<std::ptrdiff_t>(end),
                     [](const SweepTask& a, const SweepTask& b) { return a.point < b.point; });
    groups.push_back({begin, end});
    begin = end;
  }
  return groups;
}

struct SweepMaps {
  const std::vector<StationMap>& stations;
  const std::vector<ElementMap>& elements;
  const std::vector<ContactMap>& contacts;
};

// One frequency: one factorization, the unit response of each excitation at it a right-hand side,
// scaled and superposed per sweep point into `sums`.
void SolveFrequency(const std::vector<SweepTask>& tasks, const FrequencyGroup& group,
                    const std::vector<ComplexVec>& unit_loads, const std::vector<ResolvedExcitation>& excitations,
                    const std::vector<double>& speeds, ResponseSolver& solver, const SweepMaps& maps,
                    std::vector<Amplitudes>& sums) {
  std::vector<Index> columns(unit_loads.size(), -1);
  std::vector<Index> used;
  for (std::size_t t = group.begin; t < group.end; ++t) {
    if (columns[tasks[t].excitation] < 0) {
      columns[tasks[t].excitation] = std::ssize(used);
      used.push_back(tasks[t].excitation);
    }
  }
  solvers::ComplexMat loads(unit_loads.front().size(), std::ssize(used));
  for (Index c = 0; c < std::ssize(used); ++c) loads.col(c) = unit_loads[used[c]];
  const solvers::ComplexMat response = solver.Solve(tasks[group.begin].frequency, loads);
  for (std::size_t t = group.begin; t < group.end;) {
    const Index point = tasks[t].point;
    const std::size_t first = t;
    ComplexVec x = ComplexVec::Zero(response.rows());
    for (; t < group.end && tasks[t].point == point; ++t) {
      const Index e = tasks[t].excitation;
      x += LoadScale(excitations[e].excitation, speeds[point]) * response.col(columns[e]);
    }
    const double largest = sums[point].Add(x, maps.stations, maps.elements, maps.contacts);
    for (std::size_t k = first; k < t; ++k) sums[point].by_excitation[tasks[k].excitation] = largest;
  }
}

// Every sweep point's amplitudes, the frequencies shared out among the solvers (one per OpenMP
// thread, each with its own sums, added up at the end).
std::vector<Amplitudes> SolveSweep(std::vector<SweepTask> tasks, const std::vector<ComplexVec>& unit_loads,
                                   const std::vector<ResolvedExcitation>& excitations, const std::vector<double>& speeds,
                                   std::vector<std::unique_ptr<ResponseSolver>>& solvers, const Amplitudes& zero,
                                   const SweepMaps& maps) {
  const std::vector<FrequencyGroup> groups = GroupByFrequency(tasks);
  const Index threads = std::ssize(solvers);
  std::vector<std::vector<Amplitudes>> sums(threads, std::vector<Amplitudes>(speeds.size(), zero));
  std::exception_ptr failure;
  const auto count = static_cast<std::ptrdiff_t>(groups.size());
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (std::ptrdiff_t g = 0; g < count; ++g) {
    const int thread = ThreadIndex();
    try {
      SolveFrequency(tasks, groups[g], unit_loads, excitations, speeds, *solvers[thread], maps, sums[thread]);
    } catch (...) {
#pragma omp critical
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  for (int thread = 1; thread < threads; ++thread) {
    for (Index point = 0; point < std::ssize(speeds); ++point) sums[0][point].Accumulate(sums[thread][point]);
  }
  return std::move(sums[0]);
}

// The largest relative error ‖X_r − X‖/‖X‖ of the reduced solve against the direct one at
// kReducedCheckPoints frequencies spread evenly over the sweep's sorted task frequencies, for the
// load patterns (columns 2e, 2e + 1) of the excitations e the sweep solves at that frequency: the
// basis expands each excitation's loads over its own band only, so a load is checked where it acts.
double CheckReducedSolver(const SweepSystem& sweep, const solvers::ProjectedHarmonicSolver& reduced,
                          std::vector<SweepTask> tasks, const MatX& patterns) {
  std::stable_sort(tasks.begin(), tasks.end(), [](const SweepTask& a, const SweepTask& b) { return a.frequency < b.frequency; });
  solvers::HarmonicSolver direct(sweep.system, sweep.terms, sweep.options);
  double largest = 0.0, previous = -1.0;
  for (int k = 0; k < kReducedCheckPoints; ++k) {
    const Index at = std::lround(std::floor((k + 0.5) / kReducedCheckPoints * std::ssize(tasks)));
    const double frequency = tasks[std::min(at, std::ssize(tasks) - 1)].frequency;
    // A frequency many tasks share (a motor's) can be picked twice: checked once.
    if (frequency == previous) continue;
    previous = frequency;
    std::vector<Eigen::Index> columns;
    for (const SweepTask& task : tasks) {
      if (std::abs(task.frequency - frequency) > 1e-9 * frequency) continue;
      for (const Eigen::Index c : {2 * task.excitation, 2 * task.excitation + 1}) {
        if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
      }
    }
    const solvers::ComplexMat loads = MatX(patterns(Eigen::all, columns)).cast<std::complex<double>>();
    const std::vector<solvers::FrequencyTermCoefficients> coefficients = SweepTermCoefficients(sweep, frequency);
    const solvers::ComplexMat reference = direct.Solve(frequency, loads, 0.0, coefficients);
    const solvers::ComplexMat approximation = reduced.Solve(frequency, loads, 0.0, coefficients);
    for (Eigen::Index c = 0; c < loads.cols(); ++c) {
      const double size = reference.col(c).norm();
      if (size > 0.0) largest = std::max(largest, (approximation.col(c) - reference.col(c)).norm() / size);
    }
  }
  return largest;
}

// One direct solver a thread.
std::vector<std::unique_ptr<ResponseSolver>> MakeDirectSolvers(const std::shared_ptr<const SweepSystem>& sweep,
                                                               Index threads) {
  std::vector<std::unique_ptr<ResponseSolver>> solvers(threads);
  for (auto& solver : solvers) solver = std::make_unique<ResponseSolver>(sweep);
  return solvers;
}

// The solvers of the sweep, one a thread; reduced: one projection shared by all, checked against
// the direct solve at a few frequencies (the sweep is solved directly when it misses).
std::vector<std::unique_ptr<ResponseSolver>> MakeSolvers(const model::SystemModel& model, const model::LateralFluid& fluid,
                                                         const VecX& q, const VibrationSettings& settings,
                                                         const std::vector<ComplexVec>& unit_loads,
                                                         const std::vector<SweepTask>& tasks, Index threads,
                                                         VibrationResult& result) {
  auto sweep = std::make_shared<const SweepSystem>(AssembleSweepSystem(model, fluid, q));
  std::shared_ptr<const solvers::ProjectedHarmonicSolver> reduced;
  result.method = settings.method;
  if (settings.method == VibrationMethod::Reduced) {
    double lowest = tasks.front().frequency, highest = lowest;
    for (const SweepTask& task : tasks) lowest = std::min(lowest, task.frequency), highest = std::max(highest, task.frequency);
    MatX patterns(model.num_velocities(), 2 * std::ssize(unit_loads));
    for (Index e = 0; e < std::ssize(unit_loads); ++e) {
      patterns.col(2 * e) = unit_loads[e].real();
      patterns.col(2 * e + 1) = unit_loads[e].imag();
    }
    solvers::KrylovBasisOptions options;
    options.lowest_frequency = lowest;
    options.highest_frequency = std::max(highest, 1e-3);
    options.shifts = settings.basis_shifts;
    options.depth = settings.basis_depth;
    // Each excitation's two patterns only over its own band of frequencies (a motor's one frequency).
    options.pattern_bands.assign(patterns.cols(), {1e300, -1e300});
    for (const SweepTask& task : tasks) {
      for (const Eigen::Index c : {2 * task.excitation, 2 * task.excitation + 1}) {
        solvers::FrequencyBand& band = options.pattern_bands[c];
        band.lowest = std::min(band.lowest, task.frequency);
        band.highest = std::max(band.highest, task.frequency);
      }
    }
    // A fixed frequency (a motor's): its exact damped response, real and imaginary parts, in the
    // basis (the undamped shift at that frequency alone missed the direct solve by 23 % there).
    std::vector<Eigen::Index> fixed;
    for (Index c = 0; c < std::ssize(options.pattern_bands); ++c) {
      if (!(options.pattern_bands[c].highest > options.pattern_bands[c].lowest)) fixed.push_back(c);
    }
    // The annulus of the basis at the geometric mean of the band (the solve takes each ω's own).
    const double reference = std::sqrt(std::max(lowest, 1e-3 * options.highest_frequency) * options.highest_frequency);
    const SparseMat reference_mass = ReferenceMass(*sweep, reference);
    // Every resonance the sweep crosses needs a basis vector of its own, and a basis holds at most
    // the static block, `depth` blocks at each expansion frequency (the shifts and the bands' tops)
    // and the fixed frequencies' responses. When the band holds more undamped modes than that
    // (Sylvester's count, solvers/spectrum_count.hpp; a long string's dense lateral spectrum: 3 km
    // of pipe has over a thousand below 12.5 Hz) the basis cannot follow the sweep: it, its check
    // and the check's direct solves are skipped.
    const Index loads_count = patterns.cols();
    const Index capacity = loads_count * (1 + options.depth * (options.shifts + loads_count)) + 2 * std::ssize(fixed);
    result.band_modes = solvers::CountEigenvaluesBetween(sweep->system.stiffness, reference_mass, lowest * lowest,
                                                         highest * highest);
    if (result.band_modes > capacity) {
      result.method = VibrationMethod::Direct;
      result.method_note = fmt::format("{} undamped modes lie in the sweep's band, more than a reduced basis of at most "
                                       "{} vectors can follow: solved directly", result.band_modes, capacity);
      return MakeDirectSolvers(sweep, threads);
    }
    for (Index k = 0; k < std::ssize(fixed); k += 2) {
      const double frequency = options.pattern_bands[fixed[k]].lowest;
      solvers::HarmonicSolver direct(sweep->system, sweep->terms, sweep->options);
      const std::vector<Eigen::Index> pair{fixed[k], fixed[std::min(k + 1, std::ssize(fixed) - 1)]};
      const solvers::ComplexMat response = direct.Solve(frequency, MatX(patterns(Eigen::all, pair)).cast<std::complex<double>>(),
                                                        0.0, SweepTermCoefficients(*sweep, frequency));
      const Eigen::Index old = options.extra_vectors.cols();
      options.extra_vectors.conservativeResize(patterns.rows(), old + 2 * response.cols());
      options.extra_vectors.middleCols(old, response.cols()) = response.real();
      options.extra_vectors.middleCols(old + response.cols(), response.cols()) = response.imag();
    }
    solvers::KrylovBasis basis = solvers::BuildKrylovBasis(sweep->system.stiffness, reference_mass, patterns, options);
    result.basis_size = basis.vectors.cols();
    reduced = std::make_shared<const solvers::ProjectedHarmonicSolver>(sweep->system, sweep->terms, std::move(basis.vectors),
                                                                        SweepTermCoefficients(*sweep, reference));
    result.reduced_check_error = CheckReducedSolver(*sweep, *reduced, tasks, patterns);
    if (result.reduced_check_error > kReducedCheckTolerance) {
      reduced.reset();
      result.method = VibrationMethod::Direct;
      result.method_note = fmt::format("the reduced basis missed the direct solve by {:.3g} % at a check frequency "
                                       "(tolerance {:.3g} %): solved directly",
                                       100.0 * result.reduced_check_error, 100.0 * kReducedCheckTolerance);
    }
  }
  if (!reduced) return MakeDirectSolvers(sweep, threads);
  std::vector<std::unique_ptr<ResponseSolver>> solvers(threads);
  for (auto& solver : solvers) solver = std::make_unique<ResponseSolver>(sweep, reduced);
  return solvers;
}

}  // namespace

std::vector<Excitation> DefaultExcitations(const model::StringConfig& string) {
  // Where the imbalance goes: the first MWD or LWD's middle, else the BHA's.
  double s = 0.0, bha_end = -1.0, imbalance_at = -1.0;
  for (const model::Component& component : string.components) {
    const double span = component.length * component.count;
    const bool pipe = component.type == model::ComponentType::Pipe || component.type == model::ComponentType::Hwdp;
    if (pipe && bha_end < 0.0) bha_end = s;
    const bool sensor = component.type == model::ComponentType::Mwd || component.type == model::ComponentType::Lwd;
    if (sensor && imbalance_at < 0.0 && bha_end < 0.0) imbalance_at = s + 0.5 * span;
    s += span;
  }
  if (bha_end <= 0.0) bha_end = s;
  if (imbalance_at < 0.0) imbalance_at = 0.5 * bha_end;
  Excitation imbalance;
  imbalance.type = ExcitationType::Imbalance;
  imbalance.at = imbalance_at;
  imbalance.imbalance = kDefaultImbalance;
  Excitation bit;
  bit.type = ExcitationType::Bit;
  bit.harmonic = 3;
  bit.lateral = kDefaultBitLateral;
  bit.axial = kDefaultBitAxial;
  bit.torsional = kDefaultBitTorsional;
  return {imbalance, bit};
}

VibrationResult RunVibration(const model::BuiltModel& built, const model::ModelInput& input,
                             const model::LateralFluid& fluid, const VecX& q, const VibrationSettings& settings) {
  const model::SystemModel& model = built.system;
  const std::vector<ResolvedExcitation> excitations = Resolve(settings, input);
  if (excitations.empty()) throw InputError({}, "analyses.vibration.excitations", "the vibration analysis needs excitations");
  const auto poses = model.Poses(q);
  const WallState wall = ReadWall(built, poses);
  const std::vector<StationMap> stations = MapStations(model, poses, wall);
  const std::vector<ElementMap> elements = MapElements(model);
  const Index count =
      std::lround(std::floor((settings.speed_to - settings.speed_from) / settings.speed_step + 1e-9)) + 1;
  VibrationResult result;
  result.clearance_fraction = settings.clearance_fraction;
  result.stress_limit = settings.stress_limit;
  result.closed_contacts = std::ssize(wall.closed);
  std::vector<SweepTask> tasks;
  std::vector<ComplexVec> unit_loads;
  for (const ResolvedExcitation& item : excitations) {
    unit_loads.push_back(ExcitationLoad(model, poses, input, item.excitation, 1.0));
    result.excitation_frequencies.push_back(ExcitationFrequency(item.excitation, settings.speed_from, item.motor_speed));
  }
  for (Index j = 0; j < count; ++j) {
    result.rotary_speeds.push_back(settings.speed_from + j * settings.speed_step);
    for (Index e = 0; e < std::ssize(excitations); ++e) {
      const double frequency = ExcitationFrequency(excitations[e].excitation, result.rotary_speeds.back(), excitations[e].motor_speed);
      tasks.push_back({frequency, j, e});
    }
  }
  // One solver a thread, at most one per RPM value.
  std::vector<std::unique_ptr<ResponseSolver>> solvers =
      MakeSolvers(model, fluid, q, settings, unit_loads, tasks, std::clamp<Index>(MaxThreads(), 1, count), result);
  const Amplitudes zero{std::vector<double>(stations.size(), 0.0), std::vector<double>(elements.size(), 0.0),
                        std::vector<double>(wall.closed.size(), 0.0), std::vector<double>(excitations.size(), 0.0)};
  const std::vector<Amplitudes> sums =
      SolveSweep(std::move(tasks), unit_loads, excitations, result.rotary_speeds, solvers, zero, {stations, elements, wall.closed});
  const bool with_clearance = std::any_of(stations.begin(), stations.end(), [](const StationMap& m) { return m.clearance > 0.0; });
  for (const Amplitudes& point : sums) {
    const auto widest = std::max_element(point.displacement.begin(), point.displacement.end());
    result.max_lateral_displacement.push_back(*widest);
    result.s_max_displacement.push_back(stations[widest - point.displacement.begin()].s);
    if (with_clearance) {
      double ratio = 0.0;
      for (Index i = 0; i < std::ssize(stations); ++i) {
        if (stations[i].clearance > 0.0) ratio = std::max(ratio, point.displacement[i] / stations[i].clearance);
      }
      result.max_clearance_ratio.push_back(ratio);
    }
    result.max_bending_stress.push_back(point.stress.empty() ? 0.0 : *std::max_element(point.stress.begin(), point.stress.end()));
    result.max_contact_force.push_back(point.contact.empty() ? 0.0 : *std::max_element(point.contact.begin(), point.contact.end()));
  }
  result.excitation_displacement.assign(excitations.size(), std::vector<double>(sums.size(), 0.0));
  for (Index i = 0; i < std::ssize(sums); ++i) {
    for (Index e = 0; e < std::ssize(excitations); ++e) result.excitation_displacement[e][i] = sums[i].by_excitation[e];
  }
  FindCriticalSpeeds(settings, excitations, sums, result);
  return result;
}

}  // namespace drillflex::analyses
