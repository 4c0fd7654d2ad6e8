#include "model/placement.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace drillflex::model {

Mat3 StringFrame(const Vec3& up, const well::PathFrame& hole_frame) {
  // z: the high side made perpendicular to the axis; y = z × x completes the right-handed frame
  // (x = −tangent, so y = high_side × (−tangent) = tangent × high_side = right).
  const Vec3 x = up.normalized();
  Vec3 z = hole_frame.high_side - hole_frame.high_side.dot(x) * x;
  if (z.norm() < 1e-9) z = hole_frame.right.cross(x);
  z.normalize();
  Mat3 frame;
  frame.col(0) = x;
  frame.col(1) = z.cross(x);
  frame.col(2) = z;
  return frame;
}

namespace {

// The MD above `md_start` whose centreline point lies at distance `chord` from `start`: the
// chord of an arc is shorter than the arc, so the MD step is slightly more than the chord.
double MdAtChordLength(const well::Trajectory& trajectory, const Vec3& start, double md_start, double chord) {
  double md = md_start - chord;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Vec3 point = trajectory.Position(md);
    const double distance = (point - start).norm();
    // d|p − start|/d(md) = −t·(p − start)/|p − start| going up (md decreasing): Newton on md.
    const double slope = trajectory.Tangent(md).dot(point - start) / std::max(distance, 1e-12);
    if (std::abs(slope) < 1e-12) break;
    const double step = (distance - chord) / slope;
    md -= step;
    if (std::abs(step) < 1e-13 * (1.0 + std::abs(md))) break;
  }
  return md;
}

}  // namespace

void PlaceAlongWell(std::vector<Body>& bodies, const well::Trajectory& trajectory, double bit_md) {
  double md = bit_md;
  Vec3 start = trajectory.Position(md);
  for (Body& body : bodies) {
    const double length = body.length();
    const double md_end = MdAtChordLength(trajectory, start, md, length);
    if (md_end < trajectory.start_md() - 1e-6) {
      throw InputError({}, "string", fmt::format("the string reaches above the top of the well ({:.6g} m MD)",
                                                  trajectory.start_md()));
    }
    const Vec3 end = trajectory.Position(md_end);
    const Mat3 frame = StringFrame(end - start, trajectory.Frame(0.5 * (md + md_end)));
    body.reference_position = start;
    body.reference_orientation = Quat(frame);
    body.reference_orientation.normalize();
    start = start + frame.col(0) * length;  // exactly on the end node of this body
    md = md_end;
  }
}

}  // namespace drillflex::model
