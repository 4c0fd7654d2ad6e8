// Minimum curvature well path: station positions, the circular arcs between them, frames and the
// closest-point query. References: Sawaryn & Thorogood, SPE 84246 (2005); API Bulletin D20.
#include "well/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace drillflex::well {
namespace {

// Doglegs closer than this to π are rejected: the arc normal n = (t2 − t1 cos β)/sin β is then
// determined by a vector of length ~ (π − β), and its direction error ε/(π − β) would reach 1e-10.
constexpr double kMinPiMinusDogleg = 1e-6;
// Below this sin I the hole counts as vertical for the high-side convention.
constexpr double kVerticalSine = 1e-9;

// sin(x)/x with its Taylor series near 0 (truncation error < x⁶/5040).
double Sinc(double x) {
  if (std::abs(x) < 1e-4) {
    const double x2 = x * x;
    return 1.0 - x2 / 6.0 * (1.0 - x2 / 20.0);
  }
  return std::sin(x) / x;
}

// (1 − cos x)/x = (x/2)·sinc²(x/2) (from 1 − cos x = 2 sin²(x/2)), exact to rounding at any x.
double OneMinusCosOverX(double x) {
  const double s = Sinc(0.5 * x);
  return 0.5 * x * s * s;
}

// Ratio factor RF = (2/β) tan(β/2) = tan(y)/y, y = β/2, with its series near 0.
double RatioFactor(double dogleg) {
  const double y = 0.5 * dogleg;
  if (y < 1e-4) {
    const double y2 = y * y;
    return 1.0 + y2 / 3.0 + 2.0 * y2 * y2 / 15.0;
  }
  return std::tan(y) / y;
}

std::string StationText(const SurveyStation& s) {
  std::string text = "MD ";
  text.append(std::to_string(s.md)).append(" m");
  return text;
}

void CheckStations(const std::vector<SurveyStation>& stations) {
  if (stations.empty()) throw LogicError("Trajectory: the survey has no stations");
  for (std::size_t i = 0; i < stations.size(); ++i) {
    const SurveyStation& s = stations[i];
    if (!std::isfinite(s.md) || !std::isfinite(s.inclination) || !std::isfinite(s.azimuth)) {
      throw LogicError("Trajectory: a survey station has a non-finite value");
    }
    if (s.inclination < 0.0 || s.inclination > kPi + 1e-12) {
      std::string message = "Trajectory: inclination outside [0, pi] at ";
      throw LogicError(message.append(StationText(s)));
    }
    if (i > 0 && !(s.md > stations[i - 1].md)) {
      std::string message = "Trajectory: survey MD does not strictly increase at ";
      throw LogicError(message.append(StationText(s)));
    }
  }
}

}  // namespace

Vec3 TangentFromAngles(double inclination, double azimuth) {
  const double si = std::sin(inclination);
  return Vec3(si * std::cos(azimuth), si * std::sin(azimuth), std::cos(inclination));
}

PathFrame HighSideFrame(const Vec3& tangent) {
  PathFrame frame;
  frame.tangent = tangent;
  const double horizontal = std::hypot(tangent.x(), tangent.y());  // sin I, accurate near 0
  if (horizontal > kVerticalSine) {
    // ∂t/∂I = (cos I cos A, cos I sin A, −sin I) with cos A = t_x / sin I, sin A = t_y / sin I.
    frame.high_side = Vec3(tangent.z() * tangent.x() / horizontal,
                           tangent.z() * tangent.y() / horizontal, -horizontal);
  } else {
    // Vertical (down or up): north, made normal to the tangent.
    frame.high_side = (Vec3::UnitX() - tangent.x() * tangent).normalized();
  }
  frame.right = tangent.cross(frame.high_side);
  return frame;
}

Trajectory::Trajectory(std::vector<SurveyStation> stations, const Vec3& origin)
    : stations_(std::move(stations)) {
  CheckStations(stations_);
  const std::size_t n = stations_.size();
  station_tangents_.reserve(n);
  for (const SurveyStation& s : stations_) {
    station_tangents_.push_back(TangentFromAngles(s.inclination, s.azimuth));
  }
  station_positions_.reserve(n);
  station_positions_.push_back(origin);
  arcs_.reserve(n > 0 ? n - 1 : 0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Vec3& t1 = station_tangents_[i];
    const Vec3& t2 = station_tangents_[i + 1];
    Arc arc;
    arc.md0 = stations_[i].md;
    arc.length = stations_[i + 1].md - stations_[i].md;
    arc.start = station_positions_[i];
    arc.t1 = t1;
    // β = atan2(|t1 × t2|, t1·t2): accurate at every angle (acos loses half the digits near 0).
    arc.dogleg = std::atan2(t1.cross(t2).norm(), t1.dot(t2));
    if (kPi - arc.dogleg < kMinPiMinusDogleg) {
      std::string message = "Trajectory: dogleg of nearly 180 deg between ";
      message.append(StationText(stations_[i])).append(" and ").append(StationText(stations_[i + 1]));
      throw LogicError(message.append(": the minimum curvature arc is not unique"));
    }
    arc.curvature = arc.dogleg / arc.length;
    arc.normal = Vec3::Zero();
    const Vec3 across = t2 - t1.dot(t2) * t1;  // (t2 − t1 cos β), length sin β
    if (arc.dogleg > 0.0 && across.norm() > 0.0) {
      Vec3 normal = across.normalized();
      normal -= normal.dot(t1) * t1;  // re-orthogonalize (matters for tiny β)
      arc.normal = normal.normalized();
    } else {
      arc.dogleg = 0.0;
      arc.curvature = 0.0;
    }
    arc.cos_dogleg = std::cos(arc.dogleg);
    arc.sin_dogleg = std::sin(arc.dogleg);
    arc.chord_along = arc.length * Sinc(arc.dogleg);
    arcs_.push_back(arc);
    // Minimum curvature: ΔP = (ΔMD/2)·RF·(t1 + t2) (SPE 84246, eq. 1).
    station_positions_.push_back(station_positions_[i] +
                                 0.5 * arc.length * RatioFactor(arc.dogleg) * (t1 + t2));
  }
}

double Trajectory::start_md() const { return stations_.front().md; }
double Trajectory::end_md() const { return stations_.back().md; }

std::size_t Trajectory::SegmentIndex(double md) const {
  // Arc i covers [md_i, md_{i+1}); the last arc also holds its end. Binary search: O(log n).
  const auto upper = std::upper_bound(stations_.begin(), stations_.end(), md,
                                      [](double value, const SurveyStation& s) { return value < s.md; });
  const std::ptrdiff_t index = (upper - stations_.begin()) - 1;
  const std::ptrdiff_t last = static_cast<std::ptrdiff_t>(arcs_.size()) - 1;
  return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(index, 0, last));
}

Trajectory::PathPoint Trajectory::EvaluateArc(const Arc& arc, double u) {
  // Circular arc of curvature κ from arc.start with initial tangent t1, bending toward `normal`:
  // p(u) = p1 + u·sinc(κu)·t1 + u·(1 − cos κu)/(κu)·n = p1 + R[sin(u/R) t1 + (1 − cos(u/R)) n].
  const double theta = arc.curvature * u;
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  PathPoint point;
  point.position = arc.start + u * Sinc(theta) * arc.t1 + u * OneMinusCosOverX(theta) * arc.normal;
  point.tangent = c * arc.t1 + s * arc.normal;
  point.curvature = arc.curvature * (c * arc.normal - s * arc.t1);  // dt/du
  return point;
}

Trajectory::PathPoint Trajectory::Evaluate(double md) const {
  md = std::max(md, start_md());
  if (md > end_md() || arcs_.empty()) {
    // Straight extrapolation along the last tangent.
    return {station_positions_.back() + (md - end_md()) * station_tangents_.back(),
            station_tangents_.back(), Vec3::Zero()};
  }
  const Arc& arc = arcs_[SegmentIndex(md)];
  return EvaluateArc(arc, md - arc.md0);
}

Vec3 Trajectory::Position(double md) const { return Evaluate(md).position; }
Vec3 Trajectory::Tangent(double md) const { return Evaluate(md).tangent; }
Vec3 Trajectory::Curvature(double md) const { return Evaluate(md).curvature; }
PathFrame Trajectory::Frame(double md) const { return HighSideFrame(Tangent(md)); }

double Trajectory::DoglegSeverity(double md) const {
  if (arcs_.empty() || md > end_md()) return 0.0;
  return arcs_[SegmentIndex(md)].curvature;
}

double Trajectory::Inclination(double md) const {
  const Vec3 t = Tangent(md);
  return std::atan2(std::hypot(t.x(), t.y()), t.z());
}

double Trajectory::Azimuth(double md) const {
  const Vec3 t = Tangent(md);
  double azimuth = std::atan2(t.y(), t.x());
  if (azimuth < 0.0) azimuth += 2.0 * kPi;
  if (azimuth >= 2.0 * kPi) azimuth = 0.0;  // −tiny + 2π rounds to 2π
  return azimuth;
}

double Trajectory::ClosestMd(const Vec3& point, double md_guess) const {
  return FindClosest(point, md_guess).md;
}

ClosestPoint Trajectory::FindClosest(const Vec3& point, double md_guess) const {
  ClosestPoint result;
  if (arcs_.empty()) {  // a single station: the path is one straight ray, clamped to its start
    result.segments_visited = 1;
    result.md = start_md();
    result.clamped = (point - station_positions_.front()).dot(station_tangents_.front()) != 0.0;
    return result;
  }
  std::size_t k = SegmentIndex(std::clamp(md_guess, start_md(), end_md()));
  int direction = 0;  // +1 after a step down the hole, −1 after a step up
  for (;;) {
    ++result.segments_visited;
    const Arc& arc = arcs_[k];
    const Vec3 d = point - arc.start;
    const double a = d.dot(arc.t1);
    const double b = d.dot(arc.normal);
    // f(u) = (x − p(u))·t(u) = a cos θ + b sin θ − R sin θ with θ = κu, R = 1/κ, so
    // f(0) = a and f(L) = a cos β + b sin β − L sinc β.
    const double f_start = a;
    const double f_end = a * arc.cos_dogleg + b * arc.sin_dogleg - arc.chord_along;
    if (f_start < 0.0) {  // the normal plane through the point lies above this arc
      if (k == 0 || direction > 0) {  // the top of the path, or a rounding tie at a station
        result.md = arc.md0;
        result.clamped = (k == 0);
        return result;
      }
      --k;
      direction = -1;
      continue;
    }
    if (f_end > 0.0) {  // below this arc
      if (k + 1 == arcs_.size() || direction < 0) {
        result.md = arc.md0 + arc.length;
        result.clamped = (k + 1 == arcs_.size());
        return result;
      }
      ++k;
      direction = +1;
      continue;
    }
    // f(0) ≥ 0 ≥ f(L): f = ρ sin(θ* − θ), so the root is θ* = atan2(aκ, 1 − bκ) (the polar
    // angle of the point about the arc centre); u = θ*/κ, and u = a on a straight segment.
    double u = a;
    if (arc.curvature > 0.0) {
      u = std::atan2(a * arc.curvature, 1.0 - b * arc.curvature) / arc.curvature;
    }
    result.md = arc.md0 + std::clamp(u, 0.0, arc.length);
    return result;
  }
}

}  // namespace drillflex::well
