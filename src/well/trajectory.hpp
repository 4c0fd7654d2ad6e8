// The well path by the minimum curvature method: between consecutive survey stations the path is
// a circular arc (or a straight line when the dogleg is zero), so position, tangent and the
// curvature vector are exact at any MD. Frames: global x = north, y = east, z = down (TVD).
// Reference: API Bulletin D20 / Sawaryn & Thorogood, SPE 84246 (2005), "A compendium of
// directional calculations based on the minimum curvature method".
//
// All queries are const and keep no cache, so one Trajectory may be shared by threads.
#pragma once

#include <cstddef>
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

// The answer of a closest-point query (see Trajectory::FindClosest).
struct ClosestPoint {
  double md = 0.0;            // s*, clamped to [start_md, end_md]
  int segments_visited = 0;   // arcs examined: 1 or 2 for a warm start along a string
  bool clamped = false;       // true when the normal plane through the point lies beyond an end
};

class Trajectory {
 public:
  // Builds the path from stations whose MD strictly increases (throws LogicError otherwise:
  // the case reader validates first and reports the file position). The first station sits at
  // `origin` (default: the global origin). Also throws LogicError for an empty survey, a
  // non-finite value, an inclination outside [0, π], or a dogleg within 1e-6 rad of π between
  // two stations (opposite tangents: the circular arc is not unique).
  explicit Trajectory(std::vector<SurveyStation> stations, const Vec3& origin = Vec3::Zero());

  const std::vector<SurveyStation>& stations() const { return stations_; }
  // Positions of the stations by the standard minimum curvature formula
  // ΔP = (ΔMD/2)·RF·(t1 + t2), RF = (2/β) tan(β/2).
  const std::vector<Vec3>& station_positions() const { return station_positions_; }
  std::size_t segment_count() const { return arcs_.size(); }
  double start_md() const;
  double end_md() const;

  // Geometry at any MD in [start_md, end_md] (MD outside is clamped; beyond the last station the
  // path continues straight along the last tangent for extrapolation queries).
  Vec3 Position(double md) const;
  Vec3 Tangent(double md) const;
  PathFrame Frame(double md) const;
  // Curvature vector dt/ds (1/m): its norm is the curvature, its direction toward the arc centre.
  Vec3 Curvature(double md) const;
  // The three at once (one arc lookup, one sine and cosine): what Position, Tangent and Curvature give.
  struct PathPoint {
    Vec3 position;
    Vec3 tangent;
    Vec3 curvature;
  };
  PathPoint Evaluate(double md) const;
  // Dogleg severity (rad/m) of the arc that contains md.
  double DoglegSeverity(double md) const;
  double Inclination(double md) const;  // rad
  double Azimuth(double md) const;      // rad, in [0, 2π)

  // The MD whose normal plane contains `point`: (point - p(s))·t(s) = 0, found by Newton from
  // `md_guess` (warm start: walking along a string costs O(1) per query). The result is clamped
  // to [start_md, end_md].
  // (Implementation: on a circular arc the root is closed-form, so the "Newton" step is exact;
  // see FindClosest.)
  double ClosestMd(const Vec3& point, double md_guess) const;

  // ClosestMd with its diagnostics. Starting on the arc that contains md_guess, the root on an
  // arc is exact: the normal plane at arc angle θ contains the arc centre c, so θ* is the polar
  // angle of the point about c, θ* = atan2(a κ, 1 − b κ) with a = (x − p1)·t1, b = (x − p1)·n.
  // When θ* leaves the arc the search steps to the neighbouring arc in the direction of the sign
  // of f(s) = (x − p(s))·t(s) (monotone, so it ends after at most segment_count() arcs).
  ClosestPoint FindClosest(const Vec3& point, double md_guess) const;

 private:
  // One segment between stations: p(u) = start + u·sinc(κu)·t1 + u·((1 − cos κu)/(κu))·normal,
  // t(u) = cos(κu)·t1 + sin(κu)·normal, for u = md − md0 in [0, length].
  struct Arc {
    double md0 = 0.0;
    double length = 0.0;
    double dogleg = 0.0;     // β (rad)
    double curvature = 0.0;  // κ = β / length (1/m)
    double cos_dogleg = 1.0;
    double sin_dogleg = 0.0;
    double chord_along = 0.0;  // L·sinc β = (p(L) − p(0))·t1
    Vec3 start;
    Vec3 t1;
    Vec3 normal;             // unit, toward the arc centre; zero on a straight segment
  };

  std::size_t SegmentIndex(double md) const;
  static PathPoint EvaluateArc(const Arc& arc, double u);

  std::vector<SurveyStation> stations_;
  std::vector<Vec3> station_positions_;
  std::vector<Vec3> station_tangents_;
  std::vector<Arc> arcs_;  // arcs_[i] joins stations i and i+1
};

// Unit tangent of an inclination and azimuth (rad): (sin I cos A, sin I sin A, cos I).
Vec3 TangentFromAngles(double inclination, double azimuth);

// The high-side frame of a unit tangent: high side = ∂t/∂I = (cos I cos A, cos I sin A, −sin I)
// (upward, in the vertical plane of t); when the hole is vertical (sin I < 1e-9, down or up) the
// high side is north projected normal to t. right = tangent × high_side.
PathFrame HighSideFrame(const Vec3& tangent);

}  // namespace drillflex::well
