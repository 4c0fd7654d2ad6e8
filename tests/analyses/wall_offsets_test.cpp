// Where the string sits in the hole (analyses/wall_offsets.hpp) and the bit's tendency at the
// equilibrium of a bit and pipe in a straight horizontal hole: the offsets against the geometry of a
// straight hole (the undeformed string lies on its axis, so the offset from the axis is the lateral
// displacement and the MD of a node's cross-section is bit MD − s − u_x), the clearance against the
// contact law, the bit's build force against beam theory of a pendulum (a uniform string).
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>

#include "analyses/bit_tendency.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/string_stations.hpp"
#include "analyses/wall_offsets.hpp"
#include "analyses_test_support.hpp"

namespace drillflex::analyses {
namespace wall_offsets_test {

constexpr double kHoleDiameter = 0.2;           // m
constexpr double kPipeOd = 0.127, kPipeId = 0.1086;  // m
constexpr double kBitOd = kHoleDiameter, kBitId = 0.18;  // m: the bit fills the hole (thin-walled: moderate EI)
constexpr double kBitLength = 1.0, kPipeLength = 30.0;  // m
constexpr double kBitMd = 200.0;                // m
constexpr double kContactStiffness = 1e8;       // N/m per metre of pipe
constexpr double kInclination = 90.0 * kDegree, kAzimuth = 30.0 * kDegree;

// A 1 m bit (OD × ID) under 30 m of pipe (11 bodies × 10 elements) at MD 200 m of a straight
// horizontal hole (azimuth 30°: no axial weight), pinned at the hole centre at the bit (x, y, z and
// torsion; tilt free) and held laterally at the top: the pipe sags onto the low side between them
// (tests/model/wall_contact_test.cpp).
model::ModelInput HorizontalHoleInput(double bit_od = kBitOd, double bit_id = kBitId) {
  model::ModelInput input;
  model::Component bit;
  bit.type = model::ComponentType::Bit;
  bit.name = "bit";
  bit.outer_diameter = bit_od;
  bit.inner_diameter = bit_id;
  bit.length = kBitLength;
  model::Component pipe;
  pipe.type = model::ComponentType::Collar;
  pipe.name = "pipe";
  pipe.outer_diameter = kPipeOd;
  pipe.inner_diameter = kPipeId;
  pipe.length = kPipeLength;
  input.string.components = {bit, pipe};
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.settings.body_length = 3.0 + 1e-9;
  input.settings.elements_per_body = 10;
  input.settings.modes_per_body = 6;
  input.settings.contact.stiffness = kContactStiffness;
  input.gravity = 9.81;
  input.well = model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{{0.0, kInclination, kAzimuth},
                                                                                     {500.0, kInclination, kAzimuth}}),
                                   std::vector<well::HoleSection>{well::HoleSection{{}, kHoleDiameter, {}}});
  input.bit_md = kBitMd;
  model::Support bottom = testing::SupportAt(0.0, {model::kX, model::kY, model::kZ, model::kRx});
  model::Support top = testing::SupportAt(kBitLength + kPipeLength, {model::kY, model::kZ});
  input.supports = {bottom, top};
  return input;
}

struct Solved {
  cms::ReductionCache cache;
  model::BuiltModel built;
  StaticResult result;
  Solved(const model::ModelInput& input, const char* label)
      : built(model::BuildSystemModel(input, cache)), result(RunStatic(built, StaticSettings{})) {
    std::printf("[ measure  ] %s: %zu nodes, %zu contacts carry force, %d iterations, |R| = %.2e N\n", label,
                result.nodes.size(), result.contacts.size(), result.iterations, result.residual_norm);
  }
};

const Solved& HorizontalHole() {
  static const Solved solved(HorizontalHoleInput(), "horizontal hole");
  return solved;
}

// The same hole with a "bit" of the pipe's section: a uniform string.
const Solved& UniformStringInHorizontalHole() {
  static const Solved solved(HorizontalHoleInput(kPipeOd, kPipeId), "uniform string in the horizontal hole");
  return solved;
}

// The bit's nodes below the joint carry no wall contact (the bit cuts its hole).
bool InBit(const StaticNodeResult& node) { return node.s < kBitLength - 1e-9; }
// The contact circle is the bit's below the joint with the pipe and the pipe's from the joint up
// (model::ContactDiameterAt: on top of the bit the upper component touches; the bit's gauge is at
// its bottom).
double ContactRadius(const StaticNodeResult& node) { return 0.5 * (InBit(node) ? kBitOd : kPipeOd); }

TEST(WallOffsets, ClearanceAndOffsetAddUpToTheRadialGap) {
  const Solved& s = HorizontalHole();
  ASSERT_TRUE(s.result.converged);
  ASSERT_EQ(s.result.nodes.size(), StringStations(s.built.system).size());
  double worst = 0.0;
  for (const auto& node : s.result.nodes) {
    ASSERT_TRUE(node.has_wall) << node.s;
    // The bit carries no wall contact (it cuts its hole); every other node does.
    EXPECT_EQ(node.wall_contact, !InBit(node)) << node.s;
    EXPECT_EQ(node.hole_diameter, kHoleDiameter) << node.s;
    const double gap = 0.5 * kHoleDiameter - ContactRadius(node);
    worst = std::max(worst, std::abs(node.clearance + node.hole_offset - gap));
    EXPECT_NEAR(node.clearance + node.hole_offset, gap, 1e-12) << node.s;
  }
  std::printf("[ measure  ] |clearance + offset − (R_h − R_c)| ≤ %.1e m\n", worst);
}

// In a straight hole the undeformed string lies on the axis: the offset from the axis is the
// lateral displacement, its direction atan2(u_y, u_z) (y right, z high side), and the cross-section
// through the node lies at MD = bit MD − s − u_x (x up-hole).
TEST(WallOffsets, MatchTheDisplacementInAStraightHole) {
  const Solved& s = HorizontalHole();
  double offset_error = 0.0, md_error = 0.0, angle_error = 0.0;
  int off_axis = 0;
  for (const auto& node : s.result.nodes) {
    const Vec3& u = node.displacement;
    offset_error = std::max(offset_error, std::abs(node.hole_offset - node.lateral_offset));
    md_error = std::max(md_error, std::abs(node.md - (kBitMd - node.s - u.x())));
    if (node.hole_offset < 1e-3) continue;  // the direction of a tiny offset is round-off
    ++off_axis;
    double expected = std::atan2(u.y(), u.z());
    if (expected < 0.0) expected += 2.0 * kPi;
    angle_error = std::max(angle_error, std::abs(node.offset_high_side_angle - expected));
    // Gravity acts in the vertical plane through the axis: the string sags toward the low side.
    EXPECT_NEAR(node.offset_high_side_angle, kPi, 1e-6) << node.s;
  }
  std::printf("[ measure  ] straight hole: offset vs lateral displacement %.1e m, MD %.1e m, angle %.1e rad "
              "(%d nodes off the axis by > 1 mm)\n",
              offset_error, md_error, angle_error, off_axis);
  EXPECT_GT(off_axis, 20);
  EXPECT_LT(offset_error, 1e-9);
  EXPECT_LT(md_error, 1e-9);
  EXPECT_LT(angle_error, 1e-9);
}

// A node pressed into the wall carries N = k_n δ (no damping at rest), so its clearance is −N/k_n;
// every node the contact reports leave out is off the wall (clearance ≥ 0).
// The spacing of the contact nodes around s (m): half-way to the neighbours on each side.
double NodeSpacingAt(const Solved& solved, double s) {
  std::vector<double> positions;
  for (const auto& node : solved.result.nodes) {
    if (node.wall_contact) positions.push_back(node.s);
  }
  const auto it = std::find_if(positions.begin(), positions.end(), [s](double p) { return std::abs(p - s) < 1e-9; });
  if (it == positions.end() || it == positions.begin() || it + 1 == positions.end()) return 0.0;
  return 0.5 * (*(it + 1) - *(it - 1));
}

TEST(WallOffsets, ClearanceOfAPressedNodeIsMinusForceOverStiffness) {
  const Solved& s = HorizontalHole();
  ASSERT_FALSE(s.result.contacts.empty());
  double worst = 0.0;
  std::size_t pressed = 0;
  for (const auto& node : s.result.nodes) {
    const ContactReport* report = nullptr;
    for (const auto& contact : s.result.contacts) {
      if (std::abs(contact.s - node.s) < 1e-9) report = &contact;
    }
    if (!report) {
      if (node.wall_contact) {
        EXPECT_GE(node.clearance, 0.0) << node.s;
      }
      continue;
    }
    ++pressed;
    // The wall's stiffness per metre × the length of pipe the node stands for (its node spacing).
    const double expected = -report->normal_force / (kContactStiffness * NodeSpacingAt(s, node.s));
    EXPECT_LT(node.clearance, 0.0) << node.s;
    EXPECT_NEAR(node.clearance / expected, 1.0, 1e-6) << node.s;
    worst = std::max(worst, std::abs(node.clearance / expected - 1.0));
  }
  EXPECT_EQ(pressed, s.result.contacts.size());
  // Beam theory: the free spans from the supports are ~8 m long (tests/model/wall_contact_test.cpp).
  for (const auto& node : s.result.nodes) {
    if (node.s >= 12.0 && node.s <= 20.0) {
      EXPECT_LT(node.clearance, 0.0) << node.s;
    }
  }
  std::printf("[ measure  ] %zu pressed nodes: clearance vs −N/k_n relative error ≤ %.1e\n", pressed, worst);
}

double BendingRigidity(double od, double id) { return 2.1e11 * kPi * (std::pow(od, 4) - std::pow(id, 4)) / 64.0; }
double WeightPerLength(double od, double id) { return 7850.0 * 9.81 * kPi * (od * od - id * id) / 4.0; }

// Beam theory of a slick (uniform) string, the pendulum: the bit end is pinned at the hole centre
// (lateral held, tilt free) and the string lies on the low side at the radial gap r = R_h − R_p
// beyond its tangency point at x = L from the bit. With y the lateral deflection toward the high side
// and w the weight per length, EI y'''' = −w on 0 < x < L with y(0) = 0, y''(0) = 0 (pin: no moment),
// y(L) = −r, y'(L) = 0, y''(L) = 0 (tangent to the straight wall, on which the string carries no
// moment). y = −w x⁴/(24 EI) + a x³ + b x² + c x: y''(0) = 0 gives b = 0; y''(L) = 0 gives
// a = w L/(12 EI); y'(L) = 0 gives c = −w L³/(12 EI); then y(L) = −w L⁴/(24 EI) = −r, so
// L⁴ = 24 EI r / w. Moments about the tangency point of the span (no moment at either end): the pin
// holds the string up with R = w L/2 (= EI y'''(0) = 6 a EI). The bit pushes the formation the
// other way, toward the low side: build force −w L/2 (case-format.md: a pendulum drops).
double PendulumTangency(double rigidity, double weight, double gap) {
  return std::pow(24.0 * rigidity * gap / weight, 0.25);
}
double PendulumBuildForce(double rigidity, double weight, double gap) {
  return -0.5 * weight * PendulumTangency(rigidity, weight, gap);
}

// The pendulum: the weight of the unsupported span pulls the bit toward the low side (drops); the
// load lies in the vertical plane, so no walk.
TEST(WallOffsets, SlickStringBitDropsAsBeamTheorySays) {
  const Solved& s = UniformStringInHorizontalHole();
  ASSERT_TRUE(s.result.converged);
  ASSERT_TRUE(s.result.bit.has_value());
  const BitReport& bit = *s.result.bit;
  const BitTendency tendency = ClassifyBitTendency(bit);
  const double rigidity = BendingRigidity(kPipeOd, kPipeId), weight = WeightPerLength(kPipeOd, kPipeId);
  const double gap = 0.5 * (kHoleDiameter - kPipeOd);
  const double expected = PendulumBuildForce(rigidity, weight, gap);
  std::printf("[ measure  ] uniform string: tangency at L = %.3f m; bit side %.3f N, build %.3f N vs beam theory "
              "%.3f N (%.2e), walk %.2e N, threshold %.3f N\n",
              PendulumTangency(rigidity, weight, gap), bit.side_force, bit.build_force, expected,
              bit.build_force / expected - 1.0, bit.walk_force, tendency.threshold);
  EXPECT_NEAR(bit.build_force / expected, 1.0, 0.02);
  EXPECT_EQ(tendency.inclination, InclinationTendency::Drop);
  EXPECT_EQ(tendency.azimuth, AzimuthTendency::None);
}

// A transient sample reads a few stations only (StaticNodeResults and AddWallOffsets over a list
// of stations): the bit's node (no contact of its own), a joint, an interior node and the top, in
// any order, must come out as the whole string's results at those stations, to the bit.
TEST(WallOffsets, ResultsAtListedStationsAreTheWholeStringsThere) {
  const Solved& s = HorizontalHole();
  ASSERT_TRUE(s.result.converged);
  const std::vector<Station> stations = StringStations(s.built.system);
  int joint = -1;
  for (std::size_t i = 0; i < stations.size(); ++i) {
    if (stations[i].lower_body >= 0) joint = static_cast<int>(i);
  }
  ASSERT_GE(joint, 0);
  const int top = static_cast<int>(stations.size()) - 1;
  const std::vector<Index> listed = {top, 0, joint, top / 2, 0};
  std::vector<StaticNodeResult> all = StaticNodeResults(s.built, s.result.q, 1.0);
  AddWallOffsets(s.built, s.result.q, all);
  std::vector<StaticNodeResult> some = StaticNodeResults(s.built, s.result.q, 1.0, listed);
  AddWallOffsets(s.built, s.result.q, some, listed);
  ASSERT_EQ(some.size(), listed.size());
  for (std::size_t i = 0; i < listed.size(); ++i) {
    const StaticNodeResult& expected = all[listed[i]];
    const StaticNodeResult& got = some[i];
    EXPECT_EQ(got.s, expected.s) << listed[i];
    EXPECT_EQ(got.displacement, expected.displacement) << listed[i];
    EXPECT_EQ(got.force, expected.force) << listed[i];
    EXPECT_EQ(got.moment, expected.moment) << listed[i];
    EXPECT_EQ(got.von_mises_stress, expected.von_mises_stress) << listed[i];
    EXPECT_EQ(got.wall_contact, expected.wall_contact) << listed[i];
    EXPECT_EQ(got.md, expected.md) << listed[i];
    EXPECT_EQ(got.hole_offset, expected.hole_offset) << listed[i];
    EXPECT_EQ(got.offset_high_side_angle, expected.offset_high_side_angle) << listed[i];
    EXPECT_EQ(got.clearance, expected.clearance) << listed[i];
  }
  EXPECT_GT(all[joint].force.norm(), 0.0);
  EXPECT_THROW(AddWallOffsets(s.built, s.result.q, some, std::vector<Index>{0}), std::exception);
}

TEST(WallOffsets, WithoutAWellNothingIsSet) {
  model::ModelInput input = testing::V1Rod();
  input.supports = {testing::ClampAt(0.0)};
  input.loads = {testing::PointLoad(testing::kRodLength, Vec3(0.0, 0.0, -1000.0))};
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const StaticResult result = RunStatic(built, StaticSettings{});
  ASSERT_FALSE(result.nodes.empty());
  for (const auto& node : result.nodes) {
    EXPECT_FALSE(node.has_wall);
    EXPECT_FALSE(node.wall_contact);
    EXPECT_EQ(node.hole_offset, 0.0);
    EXPECT_EQ(node.clearance, 0.0);
  }
}

}  // namespace wall_offsets_test
}  // namespace drillflex::analyses
