// The well path by the minimum curvature method: between consecutive survey stations the path is
// a circular arc (or a straight line when the dogleg is zero), so position, tangent and the
// curvature vector are exact at any MD. Frames: global x = north, y = east, z = down (TVD).
// Reference: API Bulletin D20 / Sawaryn & Thorogood, SPE 84246 (2005), "A compendium of
// directional calculations based on the minimum curvature method".
#pragma once

#include <vector>

#include "core/types.hpp"
#include "well/survey.hpp"

namespace drillflex::well {

// Orthonormal frame along the path: tangent (down the hole), high side, and right (looking
// down-hole), with right = tangent × high_side. In a vertical hole high side is taken toward north.
struct PathFrame {
  Vec3 tangent;
  Vec3 high_side;
  Vec3 right;
};

class Trajectory {
 public:
  // Builds the path from stations whose MD strictly increases (throws LogicError otherwise:
  // the case reader validates first and reports the file position). The first station sits at
  // `origin` (default: the global origin).
  explicit Trajectory(std::vector<SurveyStation> stations, const Vec3& origin = Vec3::Zero());

  const std::vector<SurveyStation>& stations() const { return stations_; }
  double start_md() const;
  double end_md() const;

  // Geometry at any MD in [start_md, end_md] (MD outside is clamped; beyond the last station the
  // path continues straight along the last tangent for extrapolation queries).
  Vec3 Position(double md) const;
  Vec3 Tangent(double md) const;
  PathFrame Frame(double md) const;
  // Curvature vector dt/ds (1/m): its norm is the curvature, its direction toward the arc centre.
  Vec3 Curvature(double md) const;
  // Dogleg severity (rad/m) of the arc that contains md.
  double DoglegSeverity(double md) const;
  double Inclination(double md) const;  // rad
  double Azimuth(double md) const;      // rad, in [0, 2π)

  // The MD whose normal plane contains `point`: (point - p(s))·t(s) = 0, found by Newton from
  // `md_guess` (warm start: walking along a string costs O(1) per query). The result is clamped
  // to [start_md, end_md].
  double ClosestMd(const Vec3& point, double md_guess) const;

 private:
  struct Arc;  // one segment between stations
  std::size_t SegmentIndex(double md) const;

  std::vector<SurveyStation> stations_;
  std::vector<Vec3> station_positions_;
  std::vector<Vec3> station_tangents_;
  std::vector<double> doglegs_;  // dogleg angle (rad) of each segment
};

// Unit tangent of an inclination and azimuth (rad): (sin I cos A, sin I sin A, cos I).
Vec3 TangentFromAngles(double inclination, double azimuth);

}  // namespace drillflex::well
