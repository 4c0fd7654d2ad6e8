#include "analyses/tendency_hole.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace drillflex::analyses {
namespace {

constexpr double kStationSpacing = 10.0;  // m: at most this between the arc's stations

well::SurveyStation StationOf(double md, const Vec3& tangent) {
  const double inclination = std::atan2(std::hypot(tangent.x(), tangent.y()), tangent.z());
  double azimuth = std::atan2(tangent.y(), tangent.x());
  if (azimuth < 0.0) azimuth += 2.0 * kPi;
  return {md, inclination, azimuth};
}

}  // namespace

HoleCurvature CurvatureAtBit(const well::Trajectory& path, double bit_md) {
  const well::PathFrame frame = path.Frame(bit_md);
  // Just above the bit: the arc the bit is on (at a station, the curvature of the arc ending there).
  const Vec3 curvature = path.Curvature(std::max(path.start_md(), bit_md - 1e-6));
  return {curvature.dot(frame.high_side), curvature.dot(frame.right)};
}

well::Trajectory ConstantCurvatureHole(const well::Trajectory& path, double bit_md, double top_md, double arc_length,
                                       HoleCurvature curvature) {
  if (!(arc_length > 0.0) || !(top_md >= 0.0) || !(top_md < bit_md)) {
    throw LogicError("ConstantCurvatureHole: the arc needs a positive length and 0 <= top MD < bit MD");
  }
  const well::PathFrame bit = path.Frame(bit_md);
  const Vec3 kappa = curvature.build * bit.high_side + curvature.right * bit.right;
  const double k = kappa.norm();
  const Vec3 normal = k > 0.0 ? Vec3(kappa / k) : Vec3::Zero();
  const double arc = std::min(arc_length, bit_md - top_md);
  if (k * arc >= kPi - 1e-6) throw LogicError("ConstantCurvatureHole: the arc turns by π or more");
  // Up the hole from the bit by σ along the circle through the bit with tangent t and curvature
  // vector κ (toward the centre): t(σ) = cos kσ t − sin kσ n, p(σ) = p_b − (sin kσ / k) t + ((1 − cos kσ)/k) n.
  const auto tangent_at = [&](double sigma) -> Vec3 {
    return std::cos(k * sigma) * bit.tangent - std::sin(k * sigma) * normal;
  };
  const auto offset_at = [&](double sigma) -> Vec3 {  // p(σ) − p_b
    if (k * sigma < 1e-8) return -sigma * bit.tangent + 0.5 * k * sigma * sigma * normal;
    return -(std::sin(k * sigma) / k) * bit.tangent + ((1.0 - std::cos(k * sigma)) / k) * normal;
  };
  std::vector<well::SurveyStation> stations;
  const Vec3 top_tangent = tangent_at(arc);
  const double straight = bit_md - arc - top_md;  // above the arc, along its top tangent
  if (straight > 0.0) stations.push_back(StationOf(top_md, top_tangent));
  const Index pieces = std::max<Index>(1, std::lround(std::ceil(arc / kStationSpacing)));
  for (Index i = pieces; i >= 0; --i) {
    const double sigma = arc * static_cast<double>(i) / pieces;
    stations.push_back(StationOf(bit_md - sigma, tangent_at(sigma)));
  }
  const Vec3 origin = path.Position(bit_md) + offset_at(arc) - straight * top_tangent;
  return well::Trajectory(std::move(stations), origin);
}

VecX CarryIntoHole(const model::SystemModel& from_model, const VecX& q, const model::SystemModel& to_model,
                   double bit_md, const well::Trajectory& from, const well::Trajectory& to) {
  const std::vector<model::Body>& bodies = from_model.bodies();
  if (bodies.size() != to_model.bodies().size() || q.size() != to_model.num_positions()) {
    throw LogicError("CarryIntoHole: the two models do not have the same bodies");
  }
  const auto poses = from_model.Poses(q);
  // A point x at the hole's cross-section of MD m: p'(m) + T(m) (x − p(m)), T the least turn from
  // the one hole's tangent at m to the other's.
  const auto carry = [&](const Vec3& x, double md_guess) {
    const double md = from.ClosestMd(x, md_guess);
    const well::Trajectory::PathPoint before = from.Evaluate(md), after = to.Evaluate(md);
    return Vec3(after.position + Quat::FromTwoVectors(before.tangent, after.tangent) * (x - before.position));
  };
  VecX carried = q;
  for (Index b = 0; b < std::ssize(bodies); ++b) {
    const model::Body& body = bodies[b];
    const model::BodyPose& pose = poses[b];
    const int qo = body.q_offset, last = body.node_count() - 1;
    // Node 0 (the frame's origin) and the last node where the hole carries them: joints and the bit's
    // support keep their places in the hole, only the strain of the two holes' different bending is left.
    const Vec3 origin = carry(pose.r, bit_md - body.s_start);
    const Vec3 end = pose.NodePosition(body, last);
    const Vec3 carried_end = carry(end, bit_md - body.s_start - body.length());
    // Turned first as its placement turns from the one hole to the other (so that its twist against the
    // hole's high side, which the rotary table and the couplings hold, is kept), then by the least
    // rotation that lays its chord where the hole carried its ends.
    const Quat placed = (to_model.bodies()[b].reference_orientation * body.reference_orientation.conjugate()).normalized();
    const Quat turn = Quat::FromTwoVectors(placed * (end - pose.r), carried_end - origin) * placed;
    carried.segment<3>(qo) = origin - to_model.bodies()[b].reference_position;
    const Quat rotation = (turn * pose.rotation).normalized();
    carried.segment<4>(qo + 3) << rotation.w(), rotation.x(), rotation.y(), rotation.z();
  }
  return carried;
}

}  // namespace drillflex::analyses
