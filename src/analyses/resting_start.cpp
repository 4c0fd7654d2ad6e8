#include "analyses/resting_start.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "model/wall_contact.hpp"
#include "well/hole.hpp"

namespace drillflex::analyses {
namespace {

// Half a standard drill-pipe joint spacing (30 ft, API RP 7G): the reach of a tool joint or
// blade holding the string off the wall, and the length over which the offset ramps up from the bit.
constexpr double kSupportReach = 4.572;
// Penetration given to the node with the least clearance, m: its contact starts closed.
constexpr double kStartPenetration = 1e-6;

struct NodeStation {
  int body = 0;
  int node = 0;
  double s = 0.0;   // from the bit, m
  double md = 0.0;  // m
  Vec3 position = Vec3::Zero();  // reference, global
  double clearance = 0.0;        // R_h − R_c, m
  Vec3 direction = Vec3::Zero(); // unit lateral load direction, or zero
};

std::vector<NodeStation> Stations(const model::ModelInput& input, const model::SystemModel& system) {
  const well::Trajectory& trajectory = *input.trajectory;
  const well::HoleProfile hole(input.hole);
  std::vector<NodeStation> stations;
  for (int b = 0; b < static_cast<int>(system.bodies().size()); ++b) {
    const model::Body& body = system.bodies()[b];
    const Mat3 frame = body.reference_orientation.toRotationMatrix();
    for (int k = 0; k < body.node_count(); ++k) {
      NodeStation station;
      station.body = b;
      station.node = k;
      const Vec3& rho = body.reduced->node_positions[k];
      station.s = body.s_start + rho.x();
      station.position = body.reference_position + frame * rho;
      station.md = trajectory.ClosestMd(station.position, input.bit_md - station.s);
      const double contact_radius = 0.5 * model::ContactDiameterAt(input.string, station.s);
      station.clearance = std::max(0.5 * hole.Diameter(station.md) - contact_radius, 0.0);
      stations.push_back(station);
    }
  }
  return stations;
}

// Soft-string axial force and lateral load direction at every station, from the bit upward.
void AddLoadDirections(const model::ModelInput& input, const model::SystemModel& system,
                       std::vector<NodeStation>& stations) {
  const well::Trajectory& trajectory = *input.trajectory;
  const Vec3 down = Vec3::UnitZ();  // gravity along global +z (TVD)
  double tension = -input.operation.weight_on_bit;
  double previous_s = 0.0;
  for (NodeStation& station : stations) {
    const double weight = model::BuoyedWeightPerLength(system.bodies()[station.body], input);
    const Vec3 t = trajectory.Tangent(station.md);
    tension += weight * t.dot(down) * (station.s - previous_s);  // dT/ds = w_b cos I
    previous_s = station.s;
    const Vec3 lateral = weight * (down - down.dot(t) * t) + tension * trajectory.Curvature(station.md);
    if (lateral.norm() > 1e-6 * std::max(std::abs(weight), 1e-9)) station.direction = lateral.normalized();
  }
}

// The offset of each station: the least clearance within kSupportReach, ramped from the bit.
std::vector<Vec3> Offsets(const std::vector<NodeStation>& stations) {
  std::vector<Vec3> offsets(stations.size(), Vec3::Zero());
  std::size_t first = 0;
  for (std::size_t i = 0; i < stations.size(); ++i) {
    while (stations[first].s < stations[i].s - kSupportReach) ++first;
    double clearance = stations[i].clearance;
    for (std::size_t j = first; j < stations.size() && stations[j].s <= stations[i].s + kSupportReach; ++j) {
      clearance = std::min(clearance, stations[j].clearance);
    }
    const double ramp = std::min(1.0, stations[i].s / kSupportReach);
    offsets[i] = ramp * (clearance + kStartPenetration) * stations[i].direction;
  }
  return offsets;
}

}  // namespace

VecX RestingStart(const model::ModelInput& input, const model::BuiltModel& built) {
  if (!input.trajectory || input.hole.empty()) throw LogicError("RestingStart: the string is not in a hole");
  const model::SystemModel& system = built.system;
  std::vector<NodeStation> stations = Stations(input, system);
  AddLoadDirections(input, system, stations);
  const std::vector<Vec3> offsets = Offsets(stations);

  VecX q = system.ReferencePositions();
  std::size_t index = 0;
  Vec3 start = Vec3::Zero();
  if (!stations.empty()) start = stations.front().position + offsets.front();
  for (const model::Body& body : system.bodies()) {
    const std::size_t end = index + static_cast<std::size_t>(body.node_count()) - 1;
    const Vec3 target = stations[end].position + offsets[end];
    const Mat3 reference = body.reference_orientation.toRotationMatrix();
    // The smallest rotation taking the reference axis onto the chord to the moved end node.
    const Quat turn = Quat::FromTwoVectors(reference.col(0), target - start);
    Quat orientation = turn * body.reference_orientation;
    orientation.normalize();
    q.segment<3>(body.q_offset) = start - orientation.toRotationMatrix() * body.reduced->node_positions.front();
    q.segment<4>(body.q_offset + 3) << orientation.w(), orientation.x(), orientation.y(), orientation.z();
    start = q.segment<3>(body.q_offset) + orientation.toRotationMatrix() * body.reduced->node_positions.back();
    index = end + 1;
  }
  // The chain of rigid chords keeps each body's length, so its top end drifts (second order in the
  // offsets) from where the hook holds it axially: slide the whole chain along the bit's axis (the
  // bit is axially free; a shift with a lateral part at the bit would load its stiff lateral
  // support) until the top's axial place is right. Skipped when the string turns by more than 60°.
  if (!stations.empty()) {
    const Vec3 drift = stations.back().position + offsets.back() - start;
    const auto axis = [&](const model::Body& body) {
      return Quat(q[body.q_offset + 3], q[body.q_offset + 4], q[body.q_offset + 5], q[body.q_offset + 6])
          .toRotationMatrix()
          .col(0);
    };
    const Vec3 bit_axis = axis(system.bodies().front()), top_axis = axis(system.bodies().back());
    const double alignment = bit_axis.dot(top_axis);
    if (alignment > 0.5) {
      const Vec3 shift = (drift.dot(top_axis) / alignment) * bit_axis;
      for (const model::Body& body : system.bodies()) q.segment<3>(body.q_offset) += shift;
    }
  }
  return q;
}

void TwistUnderTorque(const model::ModelInput& input, const model::BuiltModel& built, VecX& q) {
  const auto& bodies = built.system.bodies();
  // The torque each body carries: the torque on bit plus, when the string rotates, the wall
  // friction μ_t N R_c of the contacts below (N as they are at q).
  std::vector<double> friction_torque(bodies.size(), 0.0);
  if (input.static_sliding && input.static_sliding->rotary_speed != 0.0) {
    const auto poses = built.system.Poses(q);
    const VecX rest = VecX::Zero(built.system.num_velocities());
    for (const int index : built.contact_elements) {
      const auto& contact = static_cast<const model::WallContactElement&>(*built.system.elements()[index]);
      const model::WallContactResult state = contact.Result(built.system.StateOf(contact, poses, rest, 0.0, 1.0));
      const int body = built.system.IndexOf(contact.bodies()[0]);
      // A rotating pipe climbs the wall until the friction balances the lateral load, which then
      // splits into N and μN: N = F⊥/√(1 + μ²) of the frictionless N = F⊥.
      const double mu = contact.parameters().tangential_friction;
      friction_torque[body] += mu * state.normal_force / std::sqrt(1.0 + mu * mu) * contact.parameters().contact_radius;
    }
  }
  std::vector<double> torque(bodies.size(), 0.0);
  double below = input.operation.torque_on_bit;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    torque[b] = below + 0.5 * friction_torque[b];
    below += friction_torque[b];
  }
  double twist_above = 0.0;  // ∫ T ds/GJ over the bodies above, rad
  for (std::size_t b = bodies.size(); b-- > 0;) {
    const double compliance = bodies[b].length() / bodies[b].torsional_rigidity;
    const double twist = twist_above + 0.5 * torque[b] * compliance;
    if (twist != 0.0) model::TwistKeepingShape(bodies[b], twist, q);
    twist_above += torque[b] * compliance;
  }
}

}  // namespace drillflex::analyses
