// Minimum curvature trajectory: textbook cases, the arc between stations against an independent
// numerical integration of the slerp tangent, derivatives by central differences, frames, and
// the closest-point query.
#include "well/trajectory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace drillflex::well {
namespace trajectory_test {

constexpr double kFoot = 0.3048;

std::string Scientific(double value) {
  std::ostringstream text;
  text << std::scientific << value;
  return text.str();
}

// The tangent written out here, independently of TangentFromAngles.
Vec3 UnitTangent(double inclination, double azimuth) {
  return Vec3(std::sin(inclination) * std::cos(azimuth), std::sin(inclination) * std::sin(azimuth),
              std::cos(inclination));
}

SurveyStation StationFromTangent(double md, const Vec3& t) {
  double azimuth = std::atan2(t.y(), t.x());
  if (azimuth < 0.0) azimuth += 2.0 * kPi;
  return {md, std::acos(std::clamp(t.z(), -1.0, 1.0)), azimuth};
}

// A random 3-D survey: stations 20–60 m apart, doglegs up to `max_dls` (rad/m) about a random
// axis, one exactly straight segment and one sharp dogleg (25° over 10 m), starting at MD 100 m
// with the given inclination (5°: a near-vertical start; 85°: the path wanders past horizontal,
// which the tests that use it assert).
std::vector<SurveyStation> RandomSurvey(std::mt19937& rng, int segments, double max_dls,
                                        double start_inclination) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<SurveyStation> stations{{100.0, start_inclination, 40.0 * kDegree}};
  Vec3 t = UnitTangent(stations[0].inclination, stations[0].azimuth);
  for (int i = 0; i < segments; ++i) {
    double length = 20.0 + 40.0 * unit(rng);
    double dogleg = max_dls * length * unit(rng);
    if (i == 3) dogleg = 0.0;                              // straight
    if (i == segments / 2) { length = 10.0; dogleg = 25.0 * kDegree; }  // sharp
    // Rotate t about a random axis normal to it.
    const Vec3 random_axis = Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
    Vec3 axis = random_axis - random_axis.dot(t) * t;
    axis.normalize();
    const Vec3 next = Eigen::AngleAxisd(dogleg, axis) * t;
    const SurveyStation station = StationFromTangent(stations.back().md + length, next);
    t = UnitTangent(station.inclination, station.azimuth);
    stations.push_back(station);
  }
  return stations;
}

double MaxInclination(const std::vector<SurveyStation>& stations) {
  double largest = 0.0;
  for (const SurveyStation& s : stations) largest = std::max(largest, s.inclination);
  return largest;
}

// Position at md integrated independently: Simpson's rule on the slerp tangent
// t(u) = (sin((1 − u/L)β) t1 + sin((u/L)β) t2)/sin β, segment by segment from the origin.
Vec3 IntegratedPosition(const std::vector<SurveyStation>& stations, double md, int steps) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i + 1 < stations.size() && md > stations[i].md; ++i) {
    const Vec3 t1 = UnitTangent(stations[i].inclination, stations[i].azimuth);
    const Vec3 t2 = UnitTangent(stations[i + 1].inclination, stations[i + 1].azimuth);
    const double length = stations[i + 1].md - stations[i].md;
    const double beta = std::acos(std::clamp(t1.dot(t2), -1.0, 1.0));
    auto tangent = [&](double u) -> Vec3 {
      if (beta < 1e-12) return t1;
      return (std::sin((1.0 - u / length) * beta) * t1 + std::sin(u / length * beta) * t2) / std::sin(beta);
    };
    const double span = std::min(md, stations[i + 1].md) - stations[i].md;
    const double h = span / steps;
    Vec3 sum = tangent(0.0) + tangent(span);
    for (int k = 1; k < steps; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * tangent(k * h);
    p += sum * h / 3.0;
  }
  return p;
}

// ---- Textbook cases ----

TEST(Trajectory, TextbookMinimumCurvatureStep) {
  // 3500 → 3600 ft, I 15 → 25°, A 20 → 45°: ΔN 27.218 ft, ΔE 19.451 ft, ΔTVD 94.012 ft,
  // DLS 12.95°/100 ft (the classic worked example of the minimum curvature method).
  const Trajectory path({{3500 * kFoot, 15 * kDegree, 20 * kDegree}, {3600 * kFoot, 25 * kDegree, 45 * kDegree}},
                        Vec3(1.0, 2.0, 3.0));
  const Vec3 delta = (path.Position(3600 * kFoot) - Vec3(1.0, 2.0, 3.0)) / kFoot;
  EXPECT_NEAR(delta.x(), 27.218, 5e-4);
  EXPECT_NEAR(delta.y(), 19.451, 5e-4);
  EXPECT_NEAR(delta.z(), 94.012, 5e-4);
  const double dls_deg_per_100ft = path.DoglegSeverity(3550 * kFoot) / kDegree * 100.0 * kFoot;
  EXPECT_NEAR(dls_deg_per_100ft, 12.95, 5e-3);
  EXPECT_LT((path.station_positions().back() - path.Position(3600 * kFoot)).norm(), 1e-12);
}

TEST(Trajectory, QuarterCircleBuild) {
  // I 0 → 90° due north over 900 ft: radius R = 900·2/π ft; ΔN = ΔTVD = R = 572.958 ft, and
  // in between p(u) = (R(1 − cos(u/R)), 0, R sin(u/R)).
  const double length = 900 * kFoot;
  const Trajectory path({{0.0, 0.0, 0.0}, {length, 90 * kDegree, 0.0}});
  const double radius = 2.0 * length / kPi;
  const Vec3 end = path.Position(length);
  EXPECT_NEAR(end.x() / kFoot, 572.958, 5e-4);
  EXPECT_NEAR(end.z() / kFoot, 572.958, 5e-4);
  EXPECT_NEAR(end.x(), radius, 1e-12 * radius);
  EXPECT_NEAR(end.z(), radius, 1e-12 * radius);
  EXPECT_NEAR(end.y(), 0.0, 1e-12);
  for (double u : {1e-6, 0.1, 10.0, 100.0, 137.0, 270.0}) {
    const Vec3 expected(radius * (1.0 - std::cos(u / radius)), 0.0, radius * std::sin(u / radius));
    EXPECT_LT((path.Position(u) - expected).norm(), 1e-12 * radius) << "u = " << u;
    EXPECT_NEAR(path.Curvature(u).norm(), 1.0 / radius, 1e-15);
    EXPECT_NEAR(path.Inclination(u), u / radius, 1e-13);
  }
}

TEST(Trajectory, GentleLongArc) {
  // β = 0.01 rad over 10 km (R = 1e6 m): the small-angle series of sinc and (1 − cos x)/x near
  // κu = 1e-4 against p(u) = (2R sin²(u/2R), 0, R sin(u/R)) (written without cancellation).
  const double length = 1e4, beta = 0.01, radius = length / beta;
  const Trajectory path({{0.0, 0.0, 0.0}, {length, beta, 0.0}});
  for (double u : {1.0, 50.0, 99.0, 100.0, 101.0, 150.0, 5000.0, 1e4}) {
    const double half = std::sin(0.5 * u / radius);
    const Vec3 expected(2.0 * radius * half * half, 0.0, radius * std::sin(u / radius));
    EXPECT_LT((path.Position(u) - expected).norm(), 1e-12 * std::max(1.0, u)) << "u = " << u;
  }
}

TEST(Trajectory, StraightAndTinyDoglegs) {
  // β = 0: a straight line. β = 1e-9 rad: RF = 1 + β²/12, so ΔP = (L/2)(t1 + t2) to 1e-19.
  const Trajectory straight({{0.0, 30 * kDegree, 60 * kDegree}, {100.0, 30 * kDegree, 60 * kDegree}});
  const Vec3 t = UnitTangent(30 * kDegree, 60 * kDegree);
  EXPECT_LT((straight.Position(37.0) - 37.0 * t).norm(), 1e-13);
  EXPECT_EQ(straight.Curvature(37.0).norm(), 0.0);
  EXPECT_EQ(straight.DoglegSeverity(37.0), 0.0);

  const double tiny = 1e-9;
  const Trajectory path({{0.0, 30 * kDegree, 60 * kDegree}, {100.0, 30 * kDegree + tiny, 60 * kDegree}});
  const Vec3 t2 = UnitTangent(30 * kDegree + tiny, 60 * kDegree);
  EXPECT_LT((path.Position(100.0) - 50.0 * (t + t2)).norm(), 1e-13);
  EXPECT_NEAR(path.DoglegSeverity(50.0), tiny / 100.0, 1e-6 * tiny / 100.0);
  // Half arc by the standard formula with the half-way tangent (t1 + t2)/|t1 + t2|.
  const Vec3 mid = (t + t2).normalized();
  EXPECT_LT((path.Position(50.0) - 25.0 * (t + mid)).norm(), 1e-13);
  EXPECT_LT((path.Tangent(50.0) - mid).norm(), 1e-15);
}

// ---- Between stations: the exact arc ----

TEST(Trajectory, PointsBetweenStationsLieOnTheArc) {
  std::mt19937 rng(20240611);
  const auto stations = RandomSurvey(rng, 24, 10 * kDegree / (100 * kFoot), 85 * kDegree);
  ASSERT_GT(MaxInclination(stations), 95 * kDegree);  // the path passes horizontal
  const Trajectory path(stations);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int q = 0; q < 60; ++q) {
    const double md = stations.front().md + unit(rng) * (stations.back().md - stations.front().md);
    const Vec3 expected = IntegratedPosition(stations, md, 20000);
    const double error = (path.Position(md) - expected).norm();
    worst = std::max(worst, error / std::max(1.0, md - stations.front().md));
    EXPECT_LT(error, 1e-9 * std::max(1.0, md - stations.front().md)) << "md = " << md;
  }
  RecordProperty("worst_relative_error", Scientific(worst));
}

TEST(Trajectory, StationsAndHalfArcsMatchTheStandardFormula) {
  // Station i+1 = station i + (L/2)·RF·(t1 + t2); the point half-way along an arc is reached by
  // the same formula over L/2 with dogleg β/2 and end tangent (t1 + t2)/|t1 + t2|.
  std::mt19937 rng(5);
  const auto stations = RandomSurvey(rng, 20, 10 * kDegree / (100 * kFoot), 5 * kDegree);
  const Trajectory path(stations, Vec3(10.0, -20.0, 30.0));
  auto step = [](double length, const Vec3& a, const Vec3& b) -> Vec3 {
    const double beta = std::atan2(a.cross(b).norm(), a.dot(b));
    const double rf = beta < 1e-8 ? 1.0 : 2.0 / beta * std::tan(beta / 2.0);
    return 0.5 * length * rf * (a + b);
  };
  Vec3 p = Vec3(10.0, -20.0, 30.0);
  for (std::size_t i = 0; i + 1 < stations.size(); ++i) {
    const Vec3 t1 = UnitTangent(stations[i].inclination, stations[i].azimuth);
    const Vec3 t2 = UnitTangent(stations[i + 1].inclination, stations[i + 1].azimuth);
    const double length = stations[i + 1].md - stations[i].md;
    const Vec3 mid = (t1 + t2).normalized();
    EXPECT_LT((path.Position(stations[i].md + 0.5 * length) - (p + step(0.5 * length, t1, mid))).norm(), 1e-11);
    EXPECT_LT((path.Tangent(stations[i].md + 0.5 * length) - mid).norm(), 1e-14);
    p += step(length, t1, t2);
    EXPECT_LT((path.station_positions()[i + 1] - p).norm(), 1e-11);
    // The arc ends on the next station (left limit) with the next station's tangent.
    const double end = std::nextafter(stations[i + 1].md, 0.0);
    EXPECT_LT((path.Position(end) - p).norm(), 1e-11);
    EXPECT_LT((path.Tangent(end) - t2).norm(), 1e-12);
    EXPECT_LT((path.Tangent(stations[i].md) - t1).norm(), 1e-15);
  }
}

TEST(Trajectory, InclinationAndAzimuthAtStations) {
  std::mt19937 rng(9);
  const auto stations = RandomSurvey(rng, 15, 10 * kDegree / (100 * kFoot), 5 * kDegree);
  const Trajectory path(stations);
  for (const SurveyStation& s : stations) {
    EXPECT_NEAR(path.Inclination(s.md), s.inclination, 1e-12);
    EXPECT_NEAR(path.Azimuth(s.md), s.azimuth, 1e-12);
    EXPECT_GE(path.Azimuth(s.md), 0.0);
    EXPECT_LT(path.Azimuth(s.md), 2.0 * kPi);
  }
  // Azimuth just west of north wraps into [0, 2π).
  const Trajectory west({{0.0, 45 * kDegree, 359.5 * kDegree}, {30.0, 45 * kDegree, 359.5 * kDegree}});
  EXPECT_NEAR(west.Azimuth(15.0), 359.5 * kDegree, 1e-12);
}

TEST(Trajectory, ExtrapolationAndClamping) {
  const Trajectory path({{100.0, 0.0, 0.0}, {400.0, 60 * kDegree, 90 * kDegree}});
  const Vec3 end = path.Position(400.0);
  const Vec3 t_end = UnitTangent(60 * kDegree, 90 * kDegree);
  EXPECT_LT((path.Position(425.0) - (end + 25.0 * t_end)).norm(), 1e-12);
  EXPECT_LT((path.Tangent(425.0) - t_end).norm(), 1e-15);
  EXPECT_EQ(path.Curvature(425.0).norm(), 0.0);
  EXPECT_EQ(path.DoglegSeverity(425.0), 0.0);
  EXPECT_LT(path.Position(50.0).norm(), 1e-15);  // clamped to the first station at the origin
  EXPECT_NEAR(path.DoglegSeverity(50.0), 60 * kDegree / 300.0, 1e-15);
  EXPECT_NEAR(path.DoglegSeverity(400.0), 60 * kDegree / 300.0, 1e-15);
}

// ---- Derivatives ----

TEST(Trajectory, TangentAndCurvatureAreDerivatives) {
  std::mt19937 rng(17);
  const auto stations = RandomSurvey(rng, 20, 10 * kDegree / (100 * kFoot), 5 * kDegree);
  const Trajectory path(stations);
  const double h = 1e-3;
  for (std::size_t i = 0; i + 1 < stations.size(); ++i) {
    for (double fraction : {0.1, 0.5, 0.9}) {
      const double md = stations[i].md + fraction * (stations[i + 1].md - stations[i].md);
      // Central differences: truncation κ²h²/6 (position) and κ³h²/6 (tangent), rounding
      // ~ε|p|/h ≈ 3e-10 and ε/h ≈ 1e-13.
      const Vec3 dp = (path.Position(md + h) - path.Position(md - h)) / (2.0 * h);
      const Vec3 dt = (path.Tangent(md + h) - path.Tangent(md - h)) / (2.0 * h);
      EXPECT_LT((dp - path.Tangent(md)).norm(), 2e-9) << "md = " << md;
      EXPECT_LT((dt - path.Curvature(md)).norm(), 1e-9) << "md = " << md;
      EXPECT_NEAR(path.Tangent(md).norm(), 1.0, 1e-15);
      EXPECT_NEAR(path.Curvature(md).dot(path.Tangent(md)), 0.0, 1e-16);
      EXPECT_NEAR(path.Curvature(md).norm(), path.DoglegSeverity(md), 1e-15);
    }
  }
}

// ---- Frames ----

TEST(Trajectory, FramesAreOrthonormalRightHandedAndHighSideIsUp) {
  std::mt19937 rng(23);
  const auto stations = RandomSurvey(rng, 25, 10 * kDegree / (100 * kFoot), 85 * kDegree);
  ASSERT_GT(MaxInclination(stations), 95 * kDegree);  // the path passes horizontal
  const Trajectory path(stations);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int q = 0; q < 200; ++q) {
    const double md = stations.front().md + unit(rng) * (stations.back().md - stations.front().md);
    const PathFrame f = path.Frame(md);
    Mat3 m;
    m << f.tangent, f.high_side, f.right;
    EXPECT_LT((m.transpose() * m - Mat3::Identity()).norm(), 1e-14);
    EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
    EXPECT_LT((f.tangent.cross(f.high_side) - f.right).norm(), 1e-15);
    // High side = ∂t/∂I: in the vertical plane of t, upward.
    const double inc = path.Inclination(md), az = path.Azimuth(md);
    const Vec3 d_dI(std::cos(inc) * std::cos(az), std::cos(inc) * std::sin(az), -std::sin(inc));
    EXPECT_LT((f.high_side - d_dI).norm(), 1e-12);
    EXPECT_LT(f.high_side.z(), 0.0);
    EXPECT_NEAR(f.high_side.dot(Vec3::UnitZ().cross(f.tangent)), 0.0, 1e-14);
    EXPECT_LT((f.tangent - path.Tangent(md)).norm(), 1e-15);
  }
}

TEST(Trajectory, FrameConventions) {
  // Horizontal due north: high side up (−z), right east (+y).
  PathFrame f = HighSideFrame(Vec3::UnitX());
  EXPECT_LT((f.high_side - Vec3(0, 0, -1)).norm(), 1e-15);
  EXPECT_LT((f.right - Vec3(0, 1, 0)).norm(), 1e-15);
  // 45° heading east: high side (0, √½, −√½), right = south.
  f = HighSideFrame(UnitTangent(45 * kDegree, 90 * kDegree));
  EXPECT_LT((f.high_side - Vec3(0, std::sqrt(0.5), -std::sqrt(0.5))).norm(), 1e-15);
  EXPECT_LT((f.right - Vec3(-1, 0, 0)).norm(), 1e-15);
  // Vertical down: high side north, right east. Straight up: high side north, right west.
  f = HighSideFrame(Vec3::UnitZ());
  EXPECT_LT((f.high_side - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_LT((f.right - Vec3::UnitY()).norm(), 1e-15);
  f = HighSideFrame(-Vec3::UnitZ());
  EXPECT_LT((f.high_side - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_LT((f.right + Vec3::UnitY()).norm(), 1e-15);
  // A vertical trajectory gives the same, at every MD.
  const Trajectory vertical({{0.0, 0.0, 0.0}, {500.0, 0.0, 123 * kDegree}});
  f = vertical.Frame(250.0);
  EXPECT_LT((f.high_side - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_LT((f.right - Vec3::UnitY()).norm(), 1e-15);
  // Slightly inclined (1e-6 rad) toward east: the high side follows the azimuth, still upward.
  f = HighSideFrame(UnitTangent(1e-6, 90 * kDegree));
  EXPECT_LT((f.high_side - Vec3(0, std::cos(1e-6), -std::sin(1e-6))).norm(), 1e-15);
  EXPECT_LT(f.high_side.z(), 0.0);
}

// ---- Closest point ----

class ClosestPointTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::mt19937 rng(31);
    stations_ = RandomSurvey(rng, 40, 10 * kDegree / (100 * kFoot), 85 * kDegree);
    ASSERT_GT(MaxInclination(stations_), 95 * kDegree);  // the path passes horizontal
  }
  // A point off the path at md, at distance `offset` in the normal plane: its normal-plane MD is
  // md itself (the root is unique this close to the path).
  static Vec3 PointNear(const Trajectory& path, double md, double offset, double angle) {
    const PathFrame f = path.Frame(md);
    return path.Position(md) + offset * (std::cos(angle) * f.high_side + std::sin(angle) * f.right);
  }
  std::vector<SurveyStation> stations_;
};

TEST_F(ClosestPointTest, ColdStartFindsTheNormalPlane) {
  const Trajectory path(stations_);
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst_residual = 0.0;
  for (int q = 0; q < 2000; ++q) {
    const double md = path.start_md() + unit(rng) * (path.end_md() - path.start_md());
    const Vec3 x = PointNear(path, md, 3.0 * unit(rng), 2.0 * kPi * unit(rng));
    const double guess = md + 100.0 * (unit(rng) - 0.5);
    const ClosestPoint found = path.FindClosest(x, guess);
    const Vec3 gap = x - path.Position(found.md);
    const double residual = std::abs(gap.dot(path.Tangent(found.md))) / (gap.norm() + 1.0);
    worst_residual = std::max(worst_residual, residual);
    EXPECT_LT(residual, 1e-9);
    EXPECT_NEAR(found.md, md, 1e-8) << "guess " << guess;
    EXPECT_FALSE(found.clamped);
  }
  RecordProperty("worst_residual", Scientific(worst_residual));
}

TEST_F(ClosestPointTest, WarmStartAlongAWalkTakesOneOrTwoArcs) {
  // Walking down the path in steps shorter than any arc, from the previous answer: at most two
  // arcs examined per query (one, plus one when a station is crossed).
  const Trajectory path(stations_);
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double previous = path.start_md();
  long visits = 0, queries = 0;
  for (double md = path.start_md() + 0.5; md < path.end_md() - 0.5; md += 0.3 + 2.0 * unit(rng)) {
    const Vec3 x = PointNear(path, md, 2.0 * unit(rng), 2.0 * kPi * unit(rng));
    const ClosestPoint found = path.FindClosest(x, previous);
    EXPECT_LE(found.segments_visited, 2);
    EXPECT_NEAR(found.md, md, 1e-8);
    visits += found.segments_visited;
    ++queries;
    previous = found.md;
  }
  EXPECT_LT(static_cast<double>(visits) / queries, 1.2);
  EXPECT_GT(queries, 500);
}

TEST_F(ClosestPointTest, PointsWithAnAxialOffsetStillSatisfyTheNormalPlane) {
  const Trajectory path(stations_);
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int q = 0; q < 1000; ++q) {
    const double md = path.start_md() + 10.0 + unit(rng) * (path.end_md() - path.start_md() - 20.0);
    const Vec3 x = PointNear(path, md, 3.0 * unit(rng), 2.0 * kPi * unit(rng)) +
                   Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) * 4.0;
    const double found = path.ClosestMd(x, md);
    const Vec3 gap = x - path.Position(found);
    EXPECT_LT(std::abs(gap.dot(path.Tangent(found))), 1e-9 * (gap.norm() + 1.0));
    EXPECT_LT(std::abs(found - md), 5.0);
  }
}

TEST_F(ClosestPointTest, BeyondTheEndsIsClamped) {
  const Trajectory path(stations_);
  const Vec3 below = path.Position(path.end_md() + 20.0) + 0.5 * path.Frame(path.end_md()).right;
  ClosestPoint found = path.FindClosest(below, path.start_md());
  EXPECT_EQ(found.md, path.end_md());
  EXPECT_TRUE(found.clamped);
  const Vec3 above = path.Position(path.start_md()) - 20.0 * path.Tangent(path.start_md());
  found = path.FindClosest(above, path.end_md());
  EXPECT_EQ(found.md, path.start_md());
  EXPECT_TRUE(found.clamped);
  // A station exactly: its own MD.
  const double md = stations_[7].md;
  EXPECT_NEAR(path.ClosestMd(PointNear(path, md, 1.0, 0.3), md - 30.0), md, 1e-9);
}

TEST(Trajectory, ClosestMdOnACircleIsThePolarAngle) {
  // Quarter circle of radius R about the centre c = (R, 0, 0): a point at polar angle φ from
  // c (measured from −x toward +z) has s* = Rφ, inside or outside the circle and off its plane.
  const double radius = 300.0;
  const Trajectory path({{0.0, 0.0, 0.0}, {radius * kPi / 2.0, 90 * kDegree, 0.0}});
  const Vec3 centre(radius, 0.0, 0.0);
  for (double phi : {0.05, 0.4, 1.0, 1.5}) {
    for (double distance : {radius - 5.0, radius, radius + 5.0, 0.5 * radius}) {
      const Vec3 x = centre + distance * Vec3(-std::cos(phi), 0.0, std::sin(phi)) + Vec3(0, 2.0, 0);
      EXPECT_NEAR(path.ClosestMd(x, 0.0), radius * phi, 1e-10 * radius);
    }
  }
}

// ---- Invalid input ----

TEST(Trajectory, RejectsInvalidSurveys) {
  EXPECT_THROW(Trajectory({}), LogicError);
  EXPECT_THROW(Trajectory({{0.0, 0.0, 0.0}, {0.0, 0.1, 0.0}}), LogicError);
  EXPECT_THROW(Trajectory({{10.0, 0.0, 0.0}, {5.0, 0.1, 0.0}}), LogicError);
  EXPECT_THROW(Trajectory({{0.0, -0.1, 0.0}, {5.0, 0.1, 0.0}}), LogicError);
  EXPECT_THROW(Trajectory({{0.0, 0.1, 0.0}, {5.0, std::nan(""), 0.0}}), LogicError);
  // Opposite tangents: no unique arc.
  EXPECT_THROW(Trajectory({{0.0, 0.0, 0.0}, {10.0, kPi, 0.0}}), LogicError);
  EXPECT_THROW(Trajectory({{0.0, 0.0, 0.0}, {10.0, kPi - 1e-7, 0.0}}), LogicError);
  EXPECT_THROW(Trajectory({{0.0, 90 * kDegree, 0.0}, {10.0, 90 * kDegree, kPi}}), LogicError);
  // 179.4°: a genuine (if absurd) arc.
  const Trajectory u_turn({{0.0, 0.0, 0.0}, {10.0, kPi - 0.01, 0.0}});
  // End of an arc of radius R = L/β from vertical: z = R sin β, x = R (1 − cos β).
  const double r = 10.0 / (kPi - 0.01);
  EXPECT_NEAR(u_turn.Position(10.0).z(), r * std::sin(0.01), 1e-12);
  EXPECT_NEAR(u_turn.Position(10.0).x(), r * (1.0 + std::cos(0.01)), 1e-12);
}

TEST(Trajectory, SingleStationIsAStraightRay) {
  const Trajectory path({{50.0, 30 * kDegree, 0.0}}, Vec3(0, 0, 10));
  EXPECT_EQ(path.start_md(), 50.0);
  EXPECT_EQ(path.end_md(), 50.0);
  EXPECT_LT((path.Position(60.0) - (Vec3(0, 0, 10) + 10.0 * UnitTangent(30 * kDegree, 0.0))).norm(), 1e-14);
  EXPECT_EQ(path.ClosestMd(Vec3(5, 0, 30), 0.0), 50.0);
}

}  // namespace trajectory_test
}  // namespace drillflex::well
