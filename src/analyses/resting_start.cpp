#include "analyses/resting_start.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/error.hpp"
#include "core/profile.hpp"
#include "core/so3.hpp"
#include "model/node_kinematics.hpp"
#include "model/spring_elements.hpp"
#include "model/wall_contact.hpp"
#include "well/hole.hpp"

namespace drillflex::analyses {
namespace {

// Half a standard drill-pipe joint spacing (30 ft, API RP 7G): the reach of a tool joint or
// blade holding the string off the wall, and the length over which the offset ramps up from the bit.
constexpr double kSupportReach = 4.572;
// Added to the least clearance of each station, m: where the line touches the wall, the contact
// starts (just) closed.
constexpr double kStartPenetration = 1e-6;

struct NodeStation {
  Index body = 0;
  Index node = 0;
  double s = 0.0;   // from the bit, m
  double md = 0.0;  // m
  Vec3 position = Vec3::Zero();  // reference, global
  double clearance = 0.0;        // R_h − R_c, m
  Vec3 direction = Vec3::Zero(); // unit lateral load direction, or zero
  double tension = 0.0;          // soft-string axial force, N (tension positive)
};

std::vector<NodeStation> Stations(const model::ModelInput& input, const model::SystemModel& system) {
  const well::Trajectory& trajectory = input.well->trajectory;
  const well::HoleProfile& hole = input.well->hole;
  std::vector<NodeStation> stations;
  for (Index b = 0; b < std::ssize(system.bodies()); ++b) {
    const model::Body& body = system.bodies()[b];
    for (Index k = 0; k < body.node_count(); ++k) {
      NodeStation station;
      station.body = b;
      station.node = k;
      station.s = body.NodeS(k);
      station.position = model::NodeReferencePosition(body, k);
      station.md = trajectory.ClosestMd(station.position, input.bit_md - station.s);
      const double contact_radius = 0.5 * model::ContactDiameterAt(input.string, station.s);
      station.clearance = std::max(0.5 * hole.Diameter(station.md) - contact_radius, 0.0);
      stations.push_back(station);
    }
  }
  return stations;
}

// The compression above which a pipe of bending rigidity EI, lateral weight w⊥ per length (N/m) and
// radial clearance r (m) lies on the wall as a helix: Chen, Lin & Cheatham (1990),
// F_hel = 2√2 F_sin with Dawson & Paslay's F_sin = 2 √(EI w⊥ / r); zero without lateral weight (a
// vertical hole: any compression buckles the pipe).
double HelicalBucklingLoad(double bending_rigidity, double lateral_weight, double clearance) {
  return 2.0 * std::sqrt(2.0) * 2.0 * std::sqrt(bending_rigidity * lateral_weight / clearance);
}

// Soft-string axial force and lateral load direction at every station, from the bit upward; where
// the compression exceeds the helical buckling load, the direction of a helix on the wall with
// Lubinski's pitch P = π √(8 EI / F) (static-solver.md §4), so that the start lies near the branch
// the string buckles onto instead of on the low side (or, in a vertical hole, on the axis).
void AddLoadDirections(const model::ModelInput& input, const model::SystemModel& system,
                       std::vector<NodeStation>& stations) {
  const well::Trajectory& trajectory = input.well->trajectory;
  const Vec3 down = Vec3::UnitZ();  // gravity along global +z (TVD)
  double tension = -input.operation.weight_on_bit;
  double previous_s = 0.0;
  double helix_phase = 0.0, helix_s = 0.0;  // the helix's angle from the low side at helix_s
  bool in_helix = false;
  Vec3 previous_direction = Vec3::Zero();
  for (NodeStation& station : stations) {
    const double weight = model::BuoyedWeightPerLength(system.bodies()[station.body], input);
    const Vec3 t = trajectory.Tangent(station.md);
    tension += weight * t.dot(down) * (station.s - previous_s);  // dT/ds = w_b cos I
    previous_s = station.s;
    station.tension = tension;
    const Vec3 lateral = weight * (down - down.dot(t) * t) + tension * trajectory.Curvature(station.md);
    if (lateral.norm() > 1e-6 * std::max(std::abs(weight), 1e-9)) station.direction = lateral.normalized();
    // Compressed beyond the helical buckling load: the direction turns around the hole with
    // Lubinski's pitch (below).
    const double compression = -tension;
    const model::Body& body = system.bodies()[station.body];
    const double bending = body.bending_rigidity;
    const double lateral_weight = std::abs(weight) * (down - down.dot(t) * t).norm();
    if (compression > 0.0 && station.clearance > 0.0 &&
        compression > HelicalBucklingLoad(bending, lateral_weight, station.clearance)) {
      const double pitch = kPi * std::sqrt(8.0 * bending / compression);  // Lubinski, Althouse & Logan 1962
      const well::PathFrame frame = well::HighSideFrame(t);
      if (!in_helix) {
        // The helix starts where the string lies below it (its lateral load's direction), so that
        // the line does not turn at once where the compression first exceeds the helical load.
        const Vec3 below = previous_direction.squaredNorm() > 0.0 ? previous_direction : station.direction;
        helix_phase = below.squaredNorm() > 0.0 ? std::atan2(below.dot(frame.right), -below.dot(frame.high_side)) : 0.0;
      } else {
        helix_phase += 2.0 * kPi * (station.s - helix_s) / pitch;
      }
      station.direction = std::cos(helix_phase) * (-frame.high_side) + std::sin(helix_phase) * frame.right;
      in_helix = true;
    } else {
      in_helix = false;
    }
    helix_s = station.s;
    previous_direction = station.direction;
  }
}

// The offset of each station: the least clearance within kSupportReach along the lateral load,
// averaged as a vector over half that reach, so that the line bends smoothly where the contact
// diameter changes (a collar meets drill pipe) or the load turns or vanishes (tension through a
// kick-off: on the inside of the bend below, centred in the vertical hole above). A step there
// would kink the line by up to ~0.3 rad and start the couplings strained by ~1e8 N. Every least
// clearance in the averaging window covers the window itself, so the offset anywhere is at most the
// least clearance within half a reach of it: a node laid a few centimetres from its station (the
// chain's slide) does not start in the wall. Ramped from zero at the bit.
std::vector<Vec3> Offsets(const std::vector<NodeStation>& stations) {
  const std::size_t n = stations.size();
  std::vector<double> least(n, 0.0);
  std::size_t first = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (stations[first].s < stations[i].s - kSupportReach) ++first;
    double clearance = stations[i].clearance;
    for (std::size_t j = first; j < n && stations[j].s <= stations[i].s + kSupportReach; ++j) {
      clearance = std::min(clearance, stations[j].clearance);
    }
    least[i] = clearance + kStartPenetration;
  }
  std::vector<Vec3> offsets(n, Vec3::Zero());
  const double average_reach = 0.5 * kSupportReach;
  first = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (stations[first].s < stations[i].s - average_reach) ++first;
    Vec3 sum = Vec3::Zero();
    int count = 0;
    for (std::size_t j = first; j < n && stations[j].s <= stations[i].s + average_reach; ++j, ++count) {
      sum += least[j] * stations[j].direction;
    }
    const double ramp = std::min(1.0, stations[i].s / kSupportReach);
    offsets[i] = ramp * sum / count;
  }
  return offsets;
}

// The resting line: where the chain of bodies is laid, as a function of u, the distance from the
// bit along the hole axis (MD = bit_md − u): the hole axis plus the stations' offsets, linear in u
// between stations (the bit's offset is zero; beyond the last station the last offset holds).
class RestingLine {
 public:
  RestingLine(const model::ModelInput& input, const std::vector<NodeStation>& stations, const std::vector<Vec3>& offsets)
      : trajectory_(input.well->trajectory), bit_md_(input.bit_md) {
    for (Index i = 0; i < std::ssize(stations); ++i) {
      const double u = bit_md_ - stations[i].md;
      if (!u_.empty() && u <= u_.back()) continue;  // a joint's second node, or a station out of order
      u_.push_back(u);
      offsets_.push_back(offsets[i]);
    }
  }

  // Above the first survey station (a string whose top hangs at the surface and is stretched above
  // it) the hole axis goes on straight along its first tangent (Trajectory clamps there).
  Vec3 At(double u) const {
    const double md = bit_md_ - u, start = trajectory_.start_md();
    const Vec3 axis = md >= start ? trajectory_.Position(md)
                                  : trajectory_.Position(start) + (md - start) * trajectory_.Tangent(start);
    return axis + Offset(u);
  }

  // The u > u_start whose point lies `chord` from `from` (the chord of a straight body), by the
  // secant method from u_start + chord; the line is nearly straight over a body, so two or three
  // steps reach 1e-12 m.
  double Along(const Vec3& from, double u_start, double chord) const {
    auto miss = [&](double u) { return (At(u) - from).norm() - chord; };
    double u0 = u_start + chord, u1 = u_start + 1.01 * chord;
    double f0 = miss(u0), f1 = miss(u1);
    for (int iteration = 0; iteration < 30 && std::abs(f1) > 1e-12 * std::max(chord, 1.0); ++iteration) {
      if (f1 == f0) break;
      const double u2 = u1 - f1 * (u1 - u0) / (f1 - f0);
      u0 = u1;
      f0 = f1;
      u1 = u2;
      f1 = miss(u1);
    }
    return u1;
  }

 private:
  Vec3 Offset(double u) const {
    if (u_.empty() || u <= u_.front()) return offsets_.empty() ? Vec3::Zero() : offsets_.front();
    if (u >= u_.back()) return offsets_.back();
    const Index i = std::upper_bound(u_.begin(), u_.end(), u) - u_.begin();
    const double w = (u - u_[i - 1]) / (u_[i] - u_[i - 1]);
    return (1.0 - w) * offsets_[i - 1] + w * offsets_[i];
  }

  const well::Trajectory& trajectory_;
  double bit_md_ = 0.0;
  std::vector<double> u_;
  std::vector<Vec3> offsets_;
};

// Lays the bodies as straight chords (η = 0) end to end along the resting line from `bit`, the
// bit's first node, at u = shift; returns the top node's position. `ends` gets the u of each
// body's last node.
//
// Orientations: the top body's is its reference frame turned (by the smallest rotation) onto its
// chord, since the hook holds the top in torsion; each body below takes the frame of the body
// above turned onto its own chord (parallel transport: no roll between neighbours). The bodies'
// reference frames point z to the high side, which rolls with the azimuth and jumps where the hole
// leaves the vertical (there the vertical's "high side" is north): taking the chords' rolls from
// those frames would start the couplings twisted by up to π (a kick-off toward the south), the
// one strain Newton resolves worst (a twist turns the bending held in body coordinates).
Vec3 LayChain(const model::SystemModel& system, const RestingLine& line, const std::vector<double>& stretches,
              const std::vector<double>& gaps, const Vec3& bit, double shift, VecX& q, std::vector<double>& ends) {
  const auto& bodies = system.bodies();
  double u = shift;
  std::vector<Vec3> starts;
  Vec3 start = bit;
  ends.clear();
  for (Index b = 0; b < std::ssize(bodies); ++b) {
    const model::Body& body = bodies[b];
    const Vec3 first = body.reduced->node_positions.front(), last = body.reduced->node_positions.back();
    u = line.Along(start, u, (last - first).norm() + stretches[b]);
    starts.push_back(start);
    ends.push_back(u);
    // The next body starts `gaps[b]` beyond this one's end (before it in compression), so that the
    // coupling carries the axial force; u is the arc length along the line to ~1e-6 of a gap.
    if (b + 1 < std::ssize(bodies)) u += gaps[b];
    start = line.At(u);
  }
  starts.push_back(start);
  Mat3 above = Mat3::Identity();
  for (std::size_t b = bodies.size(); b-- > 0;) {
    const model::Body& body = bodies[b];
    const Vec3 first = body.reduced->node_positions.front(), last = body.reduced->node_positions.back();
    const Vec3 chord = line.At(ends[b]) - starts[b];
    const Mat3 reference = body.reference_orientation.toRotationMatrix();
    const Mat3 from = b + 1 == bodies.size() ? reference : above;
    // `from`'s axis is the body's reference chord direction ρ_last − ρ_first (along x).
    const Mat3 frame = Quat::FromTwoVectors(from * (last - first), chord).toRotationMatrix() * from;
    Quat orientation(frame);
    orientation.normalize();
    q.segment<3>(body.q_offset) = starts[b] - orientation.toRotationMatrix() * first - body.reference_position;
    q.segment<4>(body.q_offset + 3) << orientation.w(), orientation.x(), orientation.y(), orientation.z();
    above = orientation.toRotationMatrix();
  }
  return start;
}

// The elongation of each body under the soft-string axial force at its middle, T ℓ/(EA) (a
// 3 km string hanging in tension stretches by about a metre: left to Newton, that slide along a
// curved hole comes with lateral moves of ~0.1 m in the linearized step).
std::vector<double> Stretches(const model::SystemModel& system, const std::vector<NodeStation>& stations) {
  std::vector<double> stretches;
  Index index = 0;
  for (const model::Body& body : system.bodies()) {
    const Index last = index + body.node_count() - 1;
    const double tension = 0.5 * (stations[index].tension + stations[last].tension);
    stretches.push_back(tension * body.length() / body.axial_rigidity);
    index = last + 1;
  }
  return stretches;
}

// The axial opening of each coupling (between body b and b + 1) that carries the soft-string
// axial force at the joint, T / k_x (tension opens it). Laid closed, the couplings would carry
// nothing at the start while the bodies are stretched: the top of a long string hanging in a
// vertical hole would have no lateral stiffness from its tension in the first linearization (a
// cantilever's 3EI/L³ alone, ~1 N/m over 200 m of drill pipe), and Newton's first steps there moved it
// by metres (the 3 km bench case: 20 m, then a thousand trust-radius-limited steps).
std::vector<double> CouplingGaps(const model::BuiltModel& built, const std::vector<NodeStation>& stations) {
  const auto& bodies = built.system.bodies();
  std::vector<double> gaps(bodies.size(), 0.0);
  std::vector<Index> last_station(bodies.size(), 0);
  for (Index i = 0; i < std::ssize(stations); ++i) last_station[stations[i].body] = i;
  for (const auto handle : built.couplings) {
    const model::CouplingElement& coupling = built.Get(handle);
    const Index lower = built.system.IndexOf(coupling.bodies()[0]);
    const double axial = coupling.stiffness()[0];
    if (lower + 1 < std::ssize(bodies) && axial > 0.0) gaps[lower] = stations[last_station[lower]].tension / axial;
  }
  return gaps;
}

Quat BodyOrientation(const model::Body& body, const VecX& q) {
  return Quat(q[body.q_offset + 3], q[body.q_offset + 4], q[body.q_offset + 5], q[body.q_offset + 6]);
}

// Bends each straight chord of LayChain into the resting line's curve. The chords meet at kinks
// (the turn of the hole over a body, ~1e-3 rad) that the stiff couplings resist with moments of
// ~c·EI/ℓ·kink (1e8 N·m at c = 10 for a 13 in collar: a start far from any equilibrium). Each body
// gets the small frame motion (δr, δθ, body frame) and the modal coordinates η that keep its end
// nodes where they are and turn them to the joint frames R_j: the chord frame of the body below
// turned onto the line's tangent at the joint (one frame shared by both bodies of a joint, so the
// coupling starts unstrained). Per body, with ρ_k, Φ_k, Ψ_k the node rows of its modes (k: the
// two end nodes; model/body_dynamics.hpp):
//   δr + δθ × ρ_k + Φ_k η = d_k,   δθ + Ψ_k η = log(A_bᵀ R_j),
// d_k = 0 at the first node and (Δℓ, 0, 0) at the last (the body's stretch, Stretches; the chord
// it was laid on is that much longer than the body),
// 12 equations for 6 + n_f unknowns, solved for the least strain energy (the frame motion free).
void BendAlongLine(const model::SystemModel& system, const RestingLine& line, const std::vector<double>& stretches,
                   double shift, const std::vector<double>& ends, VecX& q) {
  const auto& bodies = system.bodies();
  constexpr double kHalfSpan = 0.005;  // m, central difference of the line's tangent
  auto tangent = [&](double u) { return (line.At(u + kHalfSpan) - line.At(u - kHalfSpan)).normalized(); };
  auto joint_frame = [&](const Mat3& chord, double u) -> Mat3 {
    return Quat::FromTwoVectors(chord.col(0), tangent(u)).toRotationMatrix() * chord;
  };
  std::vector<Mat3> chords;
  for (const model::Body& body : bodies) chords.push_back(BodyOrientation(body, q).toRotationMatrix());
  std::vector<Mat3> joints;  // joints[b]: the frame at body b's first node; joints[n]: the top's
  joints.push_back(joint_frame(chords.front(), shift));
  for (Index b = 0; b < std::ssize(bodies); ++b) joints.push_back(joint_frame(chords[b], ends[b]));
  constexpr double kFrameWeight = 1e3;  // frame columns scaled up: their motion counts as free
  for (Index b = 0; b < std::ssize(bodies); ++b) {
    const model::Body& body = bodies[b];
    const Index nf = body.flexible_count;
    const Index last = body.node_count() - 1;
    // Modal columns scaled by 1/ω_j: the least |ζ| with η_j = ζ_j/ω_j is the least strain energy
    // ½ Σ ω_j² η_j², i.e. the static shape of the body under its end conditions. (The least |η|
    // of the mass-normalised modes instead took shear-dominated shapes of the short Timoshenko
    // elements: a third of the bend with the end rotations met, and tool joints 3–5 mm in the wall.)
    const VecX compliance = body.reduced->natural_frequencies.cwiseInverse();
    MatX a = MatX::Zero(12, 6 + nf);
    for (int end = 0; end < 2; ++end) {
      const Index k = end == 0 ? 0 : last;
      const Vec3& rho = body.reduced->node_positions[k];
      a.block<3, 3>(6 * end, 0) = kFrameWeight * Mat3::Identity();
      a.block<3, 3>(6 * end, 3) = -kFrameWeight * so3::Skew(rho);
      a.block(6 * end, 6, 3, nf) = body.reduced->node_translation_modes[k] * compliance.asDiagonal();
      a.block<3, 3>(6 * end + 3, 3) = kFrameWeight * Mat3::Identity();
      a.block(6 * end + 3, 6, 3, nf) = body.reduced->node_rotation_modes[k] * compliance.asDiagonal();
    }
    const Eigen::CompleteOrthogonalDecomposition<MatX> fit(a);
    // Targets: the chord ends (the last one moved by the stretch) and the joint frames.
    const model::BodyPose chord_pose = model::PoseOf(body, q);
    const Vec3 targets[2] = {chord_pose.NodePosition(body, 0),
                             chord_pose.NodePosition(body, last) + stretches[b] * chords[b].col(0)};
    // The equations are linear in the small motions; a second pass removes their second-order
    // error (δθ·η ~ 1e-6 m at the end nodes where the hole bends most: ~1e6 N in a coupling).
    for (int pass = 0; pass < 2; ++pass) {
      const model::BodyPose pose = model::PoseOf(body, q);
      VecX rhs = VecX::Zero(12);
      for (int end = 0; end < 2; ++end) {
        const Index k = end == 0 ? 0 : last;
        rhs.segment<3>(6 * end) = pose.A.transpose() * (targets[end] - pose.NodePosition(body, k));
        const Mat3 node_frame = pose.A * so3::ExpMap(pose.NodeRotation(body, k));
        rhs.segment<3>(6 * end + 3) = so3::LogMap(node_frame.transpose() * joints[b + end]);
      }
      const VecX x = fit.solve(rhs);
      q.segment<3>(body.q_offset) += pose.A * (kFrameWeight * x.head<3>());
      const Quat bent = so3::Compose(BodyOrientation(body, q), kFrameWeight * x.segment<3>(3));
      q.segment<4>(body.q_offset + 3) << bent.w(), bent.x(), bent.y(), bent.z();
      q.segment(body.q_offset + 7, nf) += compliance.asDiagonal() * x.tail(nf);
    }
  }
}

}  // namespace

VecX RestingStart(const model::ModelInput& input, const model::BuiltModel& built) {
  const profile::Scope scope("static: resting start");
  if (!input.well || input.well->hole.empty()) throw LogicError("RestingStart: the string is not in a hole");
  const model::SystemModel& system = built.system;
  std::vector<NodeStation> stations = Stations(input, system);
  AddLoadDirections(input, system, stations);
  const std::vector<Vec3> offsets = Offsets(stations);
  VecX q = system.ReferencePositions();
  if (stations.empty()) return q;
  const RestingLine line(input, stations, offsets);
  const std::vector<double> stretches = Stretches(system, stations);
  const std::vector<double> gaps = CouplingGaps(built, stations);
  // The chain laid on the offset line is longer or shorter along the hole than the string on the
  // hole axis (the offsets and the stretch change its path length), so its top would miss the
  // hook, which holds the top axially along the top body's reference axis, by centimetres (e.g.
  // 7.7 cm on 300 m through a 75° turn; ~1e10 N in the hook's stiff spring). The bit is axially
  // free but held very stiffly across (a micrometre is ~1e4 N): slide the chain along the bit's
  // reference axis until the top lands (the miss is nearly linear in the shift: two or three passes).
  const model::Body& bit_body = system.bodies().front();
  const model::Body& top_body = system.bodies().back();
  const Vec3 bit_axis = bit_body.reference_orientation.toRotationMatrix().col(0);
  const Vec3 top_axis = top_body.reference_orientation.toRotationMatrix().col(0);
  const Vec3 bit_reference = bit_body.reference_position +
                             bit_body.reference_orientation.toRotationMatrix() * bit_body.reduced->node_positions.front();
  const Vec3 top_reference = top_body.reference_position +
                             top_body.reference_orientation.toRotationMatrix() * top_body.reduced->node_positions.back();
  // The hook's spring stretched by the tension it carries, T/k_x: the top lands that far below its
  // reference (the couplings below are opened likewise, CouplingGaps).
  double hook_stretch = 0.0;
  for (const auto handle : built.supports) {
    const model::SupportElement& support = system.Get(handle);
    if (support.bodies()[0] != &top_body || support.node() != top_body.node_count() - 1) continue;
    if (support.stiffness()[0] > 0.0) hook_stretch = stations.back().tension / support.stiffness()[0];
  }
  double shift = 0.0;  // m up the hole along the bit's axis
  std::vector<double> ends;
  constexpr int kPasses = 5;
  for (int pass = 0; pass < kPasses; ++pass) {
    const Vec3 top = LayChain(system, line, stretches, gaps, bit_reference + shift * bit_axis, shift, q, ends);
    const double miss = (top - top_reference).dot(top_axis) + hook_stretch;
    if (std::abs(miss) < 1e-10 || pass + 1 == kPasses) break;  // q and ends belong to `shift`
    shift -= miss;
  }
  BendAlongLine(system, line, stretches, shift, ends, q);
  return q;
}

void TwistUnderTorque(const model::ModelInput& input, const model::BuiltModel& built, VecX& q,
                      const model::LoadParameters& parameters) {
  const auto& bodies = built.system.bodies();
  // The torque each body carries: the torque on bit plus, when the string rotates, the wall
  // friction μ_t N R_c of the contacts below (N as they are at q).
  std::vector<double> friction_torque(bodies.size(), 0.0);
  const bool as_built = parameters.sliding_mode == model::SlidingMode::kAsBuilt;
  const std::optional<model::PrescribedSliding> sliding =
      as_built ? input.static_sliding
               : (parameters.sliding_mode == model::SlidingMode::kPrescribed ? std::optional(parameters.sliding)
                                                                             : std::nullopt);
  if (sliding && sliding->rotary_speed != 0.0) {
    const auto poses = built.system.Poses(q);
    const VecX rest = VecX::Zero(built.system.num_velocities());
    for (const auto handle : built.contacts) {
      const model::WallContactElement& contact = built.Get(handle);
      const model::WallContactResult state =
          contact.Result(built.system.StateOf(contact, poses, rest, 0.0, parameters));
      const Index body = built.system.IndexOf(contact.bodies()[0]);
      // A rotating pipe climbs the wall until the friction balances the lateral load, which then
      // splits into N and μN: N = F⊥/√(1 + μ²) of the frictionless N = F⊥.
      const model::WallContactParameters effective = contact.EffectiveParameters(parameters);
      const double mu = effective.tangential_friction;
      friction_torque[body] += mu * state.normal_force / std::sqrt(1.0 + mu * mu) * effective.contact_radius;
    }
  }
  std::vector<double> torque(bodies.size(), 0.0);
  double below = input.operation.torque_on_bit;
  for (Index b = 0; b < std::ssize(bodies); ++b) {
    torque[b] = below + 0.5 * friction_torque[b];
    below += friction_torque[b];
  }
  // The torsional stiffness of the coupling below each body (to the body under it).
  std::vector<double> joint_stiffness(bodies.size(), 0.0);
  for (const auto handle : built.couplings) {
    const model::CouplingElement& coupling = built.Get(handle);
    const Index upper = built.system.IndexOf(coupling.bodies()[1]);
    if (upper >= 0) joint_stiffness[upper] = coupling.stiffness()[3];
  }
  // θ(s) = ∫_s^top T ds'/GJ: each body turned by θ at its middle and twisted inside by dθ/ds =
  // −T/GJ (x up the hole), each coupling by T/k_θ (without the inner twist the couplings carried
  // the turn T ℓ/GJ of a whole body: c ℓ/ℓ_e ≈ 100 times the torque on 3 km of pipe, |R| 2.6e8).
  double twist_above = 0.0;  // rad: the turn at the bottom of the body above
  for (std::size_t b = bodies.size(); b-- > 0;) {
    const double compliance = bodies[b].length() / bodies[b].torsional_rigidity;
    const double twist = twist_above + 0.5 * torque[b] * compliance;
    if (twist != 0.0) model::TwistKeepingShape(bodies[b], twist, q, -torque[b] / bodies[b].torsional_rigidity);
    twist_above += torque[b] * compliance;
    const double joint_torque = torque[b] - 0.5 * friction_torque[b];  // at the body's bottom
    if (joint_stiffness[b] > 0.0) twist_above += joint_torque / joint_stiffness[b];
  }
}

}  // namespace drillflex::analyses
