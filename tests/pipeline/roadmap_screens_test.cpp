// A roadmap point's screens (pipeline/roadmap.hpp): the stiff roadmap's buckled zones from its own
// statics, the fatigue of its rotating runs in each dogleg, and the casing worn drilling down the
// roadmap's depths, each against a hand computation (the formulas written out here, the figures checked
// in Python).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analyses/string_limits.hpp"
#include "pipeline/depth_runs.hpp"
#include "pipeline/roadmap.hpp"
#include "pipeline/roadmap_runs.hpp"

namespace drillflex::pipeline {
namespace roadmap_screens_test {

constexpr double kGravity = 9.81;                     // m/s², the cases'
constexpr double kBuoyedDensity = 7850.0 - 1200.0;    // kg/m³: steel less the 1200 kg/m³ mud
constexpr double kModulus = 2.1e11;                   // Pa, the built-in steel's

double Area(double od, double id) { return kPi / 4.0 * (od * od - id * id); }
double SecondMoment(double od, double id) { return kPi / 64.0 * (std::pow(od, 4) - std::pow(id, 4)); }

// ---- the stiff roadmap's buckled zones -----------------------------------------------------------------

// 5 in plain pipe (0.127 × 0.1086 m, 11 joints of 9 m) at the bottom, 8 collars (0.1715 × 0.0714 m) above
// to carry the WOB, in a straight 8-1/2 in hole at 20°, the bit at 171 m (the whole string), drilling with
// 110 kN and 1 kN·m.
io::Case InvertedString() {
  return io::ParseCase(R"(name: inverted
units: SI
gravity: 9.81
well: {survey: [[0, 20, 0], [400, 20, 0]], hole: [{diameter: 0.2159}], bit_md: 171}
fluid: {density: 1200}
string:
  - {type: pipe, od: 0.127, id: 0.1086, length: 9, count: 11}
  - {type: collar, od: 0.1715, id: 0.0714, length: 9, count: 8}
model: {body_length: 9, elements_per_body: 4, modes_per_body: 4}
operation: {wob: 110 kN, torque_on_bit: 1 kN*m, rpm: 60}
)",
                       "inverted.yaml");
}

// On bottom the rotating string carries no axial friction (its friction acts around it), so the
// compression falls from the WOB by w cos 20° a metre up the hole: w = g (ρ_s − ρ_m) A = 222.1128 N/m,
// 208.7178 N/m along the hole. Dawson–Paslay with the body's r = (0.2159 − 0.127)/2 = 0.04445 m and
// E I = 1 247 796.5 N·m²: F_s = 2 √(E I w sin 20° / r) = 92 358.88 N, F_h = √2 F_s = 130 615.18 N. So the
// pipe is beyond F_s for (110 000 − 92 358.88)/208.7178 = 84.52 m above the bit, MD 86.48 m to 171 m, and
// nowhere beyond F_h (the collars above it, compressed at most 110 000 − 99 × 208.72 = 89.34 kN, are far
// below their own F_s). Pulling out, running in (w cos 20° − μ w sin 20° > 0) and rotating off bottom the
// string hangs in tension from the free bit up: no zone. The stiff model's stations are 2.25 m apart;
// the buckled pipe's axial force along the hole is the straight one's to within its helix's slope.
TEST(RoadmapScreens, TheStiffRoadmapsZonesComeFromItsOwnStatics) {
  const io::Case c = InvertedString();
  const double w = kGravity * kBuoyedDensity * Area(0.127, 0.1086);
  const double inclination = 20.0 * kPi / 180.0;
  const double stiffness = kModulus * SecondMoment(0.127, 0.1086);
  const double sinusoidal = 2.0 * std::sqrt(stiffness * w * std::sin(inclination) / 0.04445);
  EXPECT_NEAR(sinusoidal, 92358.88, 0.01);  // the figure above
  const double zone_top = 171.0 - (110e3 - sinusoidal) / (w * std::cos(inclination));
  EXPECT_NEAR(zone_top, 86.48, 0.005);
  const analyses::RoadmapSettings settings = CompleteRoadmapSettings(c, {171.0, 45.0, {0.25}});
  const std::vector<RoadmapPoint> points = RunRoadmapDepth(c, settings, 171.0);
  ASSERT_EQ(points.size(), 1u);
  const RoadmapPoint& point = points.front();
  ASSERT_FALSE(point.failed()) << point.message;
  ASSERT_TRUE(point.screens.has_value());  // the stiff runs' own
  const RoadmapLimits limits = RoadmapPointLimits(c, settings, point);
  const std::vector<analyses::BuckledZone>& zones = limits.screens.on_bottom.zones;
  ASSERT_EQ(zones.size(), 1u);
  EXPECT_EQ(zones[0].state, analyses::BucklingState::Sinusoidal);
  EXPECT_NEAR(zones[0].md_from, zone_top, 2.25 + 0.5);
  EXPECT_NEAR(zones[0].md_to, 171.0, 1e-6);
  EXPECT_TRUE(limits.screens.pick_up.zones.empty());
  EXPECT_TRUE(limits.screens.slack_off.zones.empty());
  EXPECT_TRUE(limits.screens.rotating.zones.empty());
  std::printf("stiff on-bottom zone: sinusoidal MD %.3f-%.3f m, by hand %.3f-171 m\n", zones[0].md_from,
              zones[0].md_to, zone_top);
}

// ---- fatigue in a dogleg along the roadmap -----------------------------------------------------------

// 3 collars, then 13 joints of 5 in pipe with 6-5/8 in tool joints (0.5 m of 0.1683 × 0.0826 m a joint)
// in a hole vertical to 30 m, building 3°/30 m to 9° at 120 m, then holding; the bit at 147 m (the
// collars in the hold, the pipe's top 3 m below the surface: the pipe above the model by the soft string).
io::Case DoglegCase() {
  return io::ParseCase(R"(name: dogleg
units: SI
gravity: 9.81
well: {survey: [[0, 0, 0], [30, 0, 0], [120, 9, 0], [300, 9, 0]], hole: [{diameter: 0.2159}], bit_md: 147}
fluid: {density: 1200}
string:
  - {type: collar, od: 0.1715, id: 0.0714, length: 9, count: 3}
  - {type: pipe, od: 0.127, id: 0.1086, length: 9, count: 13, joint_od: 0.1683, joint_id: 0.0826, joint_length: 0.5}
model: {body_length: 9, elements_per_body: 4, modes_per_body: 4}
operation: {wob: 40 kN, rpm: 60}
)",
                       "dogleg.yaml");
}

// The hole's inclination at MD m (rad).
double DoglegInclination(double md) {
  const double build = 3.0 * kPi / 180.0 / 30.0;  // rad/m
  return md <= 30.0 ? 0.0 : md >= 120.0 ? 9.0 * kPi / 180.0 : (md - 30.0) * build;
}

// The fatigue utilisation at MD m in the build of the string rotating off bottom, by hand: no axial
// friction, so the tension is the buoyed weight below along the hole, T = w_c 27 cos 9° + w_p ∫ cos I
// from m to the collars' top (120 m: I = (m − 30) κ there, ∫ cos I = (sin I(120) − sin I(m))/κ), w_p with
// the tool joints averaged in: g (ρ_s − ρ_m)(A_body + 0.5/9 (A_joint − A_body)) = 270.97859 N/m, w_c =
// 1245.7822 N/m. Lubinski's bending stress in the dogleg κ = 1.7453293e-3 /m: E D κ/2 · KL/tanh KL,
// K = √(T/(E I)), L = 4.5 m (half the joint spacing); API RP 7G's endurance line for grade E (the default
// E-75) under σ_t = T/A_body: 19 500 − (10/67) σ_t − (0.6/670²)(σ_t − 33 500)² psi.
double FatigueByHand(double md) {
  const double kappa = 3.0 * kPi / 180.0 / 30.0;
  const double area = Area(0.127, 0.1086);
  const double pipe = kGravity * kBuoyedDensity * (area + 0.5 / 9.0 * (Area(0.1683, 0.0826) - area));
  const double collar = kGravity * kBuoyedDensity * Area(0.1715, 0.0714);
  const double tension = collar * 27.0 * std::cos(9.0 * kPi / 180.0) +
                         pipe * (std::sin(DoglegInclination(120.0)) - std::sin(DoglegInclination(md))) / kappa;
  const double stiffness = kModulus * SecondMoment(0.127, 0.1086);
  const double kl = std::sqrt(tension / stiffness) * 4.5;
  const double bending = kModulus * 0.127 * kappa / 2.0 * kl / std::tanh(kl);
  constexpr double kPsi = 6894.757293168361;
  const double tensile = tension / area / kPsi;
  const double allowed = (19500.0 - 10.0 / 67.0 * tensile - 0.6 / (670.0 * 670.0) * std::pow(tensile - 33500.0, 2)) * kPsi;
  return bending / allowed;
}

// Both rotating runs turn the pipe through the build (MD 30 to 120 m): one dogleg each, its worst station
// where the tension is largest, at its top. By hand (Python) at MD 30 m: T = 57 509.91 N, KL = 0.966078,
// σ_b = 30.1007 MPa against 123.0419 MPa: 0.244637. The soft string sums W cos Ī over elements of up to
// 30 ft (Johancsik: Ī the element's mean inclination, ΔI 0.016 rad a joint) where the hand integrates
// cos I: ΔI²/24 ≈ 1e-5 of the tension, within 2e-5. The stiff string's tension is the buoyed weight below
// to 1e-4 (its bending's share of the axial balance), and inside the build its own bending stress (M c/I,
// E D κ/2 between the joints, up to 3 % below Lubinski's at them) leaves Lubinski's the larger: within
// 1e-4 of the hand there (measured 1.9e-5).
TEST(RoadmapScreens, FatigueInEachDoglegOfTheRotatingRunsByHand) {
  EXPECT_NEAR(FatigueByHand(30.0), 0.244637, 1e-6);
  const io::Case c = DoglegCase();
  const analyses::RoadmapSettings settings = CompleteRoadmapSettings(c, {147.0, 45.0, {0.25}});
  RoadmapPoint soft_point;
  soft_point.bit_md = 147.0;
  soft_point.friction = 0.25;
  const RoadmapLimits soft = RoadmapPointLimits(c, settings, soft_point);
  ASSERT_EQ(soft.screens.rotating.doglegs.size(), 1u);
  const analyses::DoglegFatigue& dogleg = soft.screens.rotating.doglegs.front();
  EXPECT_NEAR(dogleg.md_from, 30.0, 9.2);
  EXPECT_NEAR(dogleg.md_to, 120.0, 9.2);  // the build's end, the collars' top
  EXPECT_NEAR(dogleg.utilisation, FatigueByHand(dogleg.md), 2e-5 * FatigueByHand(dogleg.md));
  EXPECT_NEAR(dogleg.curvature, 3.0 * kPi / 180.0 / 30.0, 1e-9);
  EXPECT_EQ(soft.screens.rotating.fatigue.limit, "fatigue");
  EXPECT_DOUBLE_EQ(soft.fatigue_rotating, dogleg.utilisation);
  EXPECT_DOUBLE_EQ(soft.fatigue_rotating_md, dogleg.md);
  EXPECT_TRUE(soft.screens.pick_up.doglegs.empty());  // not rotating: not screened
  EXPECT_FALSE(std::isfinite(soft.screens.slack_off.fatigue.utilisation));

  // The stiff string: the roadmap point's dogleg, and its stations (DepthRuns::Stations, what the point's
  // screens read) one joint inside the build's ends against the hand computation at their own MD.
  const std::vector<RoadmapPoint> points = RunRoadmapDepth(c, settings, 147.0);
  ASSERT_EQ(points.size(), 1u);
  ASSERT_FALSE(points.front().failed()) << points.front().message;
  const RoadmapLimits stiff = RoadmapPointLimits(c, settings, points.front());
  ASSERT_EQ(stiff.screens.rotating.doglegs.size(), 1u);
  const analyses::DoglegFatigue& turning = stiff.screens.rotating.doglegs.front();
  EXPECT_NEAR(turning.md_from, 30.0, 2.25);
  EXPECT_NEAR(turning.md_to, 120.0, 2.25);
  EXPECT_NEAR(stiff.fatigue_rotating, turning.utilisation, 1e-12);
  io::Case at = StiffCaseAtDepth(c, 147.0, settings);
  at.input.supports.clear();
  DepthRuns runs(at);
  runs.SolveAtRest();
  TdRunLoads loads;
  loads.rotary_speed = settings.rotary_speed;
  runs.Run(TdRun::kRotatingOffBottom, {0.25, std::nullopt}, loads);
  const std::vector<analyses::StaticNodeResult> stations = runs.Stations(TdRun::kRotatingOffBottom);
  model::ModelInput whole = CaseAtDepth(c, 147.0).input;
  whole.operation.rotary_speed = 1.0;
  const analyses::StringLimits limits = analyses::ComputeStringLimits(whole, stations, 1.0);
  double worst = 0.0;
  int inside = 0;
  for (const analyses::NodeLimits& node : limits.nodes) {
    if (node.md < 39.5 || node.md > 111.0) continue;
    const double hand = FatigueByHand(node.md);
    EXPECT_NEAR(node.fatigue_utilisation, hand, 1e-4 * hand) << "MD " << node.md;
    worst = std::max(worst, std::abs(node.fatigue_utilisation / hand - 1.0));
    ++inside;
  }
  EXPECT_GT(inside, 30);
  // At the kick-off the pipe in tension bends beyond Lubinski's constant-curvature figure (its first joint
  // in the build carries the change of curvature): the dogleg's worst is there, above the hand's.
  EXPECT_LT(turning.md, 41.0);
  EXPECT_GT(turning.utilisation, FatigueByHand(turning.md));
  std::printf("rotating off bottom: soft worst %.6f at MD %.2f m (hand %.6f); stiff stations MD 39.5-111 m within "
              "%.2e of the hand (%d); stiff worst %.6f at MD %.2f m, the hand's Lubinski there %.6f (%+.2f %%)\n",
              dogleg.utilisation, dogleg.md, FatigueByHand(dogleg.md), worst, inside, turning.utilisation, turning.md,
              FatigueByHand(turning.md), 100.0 * (turning.utilisation / FatigueByHand(turning.md) - 1.0));
}

// ---- casing wear down the roadmap ----------------------------------------------------------------------

// 5 in pipe with 6-5/8 in tool joints alone in a straight hole at 30°, cased to 150 m (0.2205 m bore,
// 0.01199 m wall: 9-5/8 in 47 lb/ft), open below; drilled from 200 to 290 m at 20 m/h and 120 rpm, wear
// factor 5e-13 1/Pa.
io::Case WearCase() {
  return io::ParseCase(R"(name: wear
units: SI
gravity: 9.81
well:
  survey: [[0, 30, 0], [400, 30, 0]]
  hole: [{to: 150, diameter: 0.2205, cased: true, wall: 0.01199}, {diameter: 0.2159}]
  bit_md: 290
fluid: {density: 1200}
string:
  - {type: pipe, od: 0.127, id: 0.1086, length: 9, count: 32, joint_od: 0.1683, joint_id: 0.0826, joint_length: 0.5}
model: {body_length: 9, elements_per_body: 4, modes_per_body: 4}
operation: {wob: 40 kN, rpm: 60}
limits: {wear: {factor: 5e-13, rop: 20 m/h, from: 200, rpm: 120}}
)",
                       "wear.yaml");
}

// The groove of depth h a joint of radius r cuts into a bore of radius R: π r² less the lens of the two
// circles, centres R − r + h apart; its depth for an area by bisection.
double GrooveArea(double big, double r, double h) {
  const double d = big - r + h;
  const double lens = r * r * std::acos((d * d + r * r - big * big) / (2.0 * d * r)) +
                      big * big * std::acos((d * d + big * big - r * r) / (2.0 * d * big)) -
                      0.5 * std::sqrt((-d + r + big) * (d + r - big) * (d - r + big) * (d + r + big));
  return kPi * r * r - lens;
}
double GrooveDepth(double big, double r, double area) {
  double low = 0.0, high = r;
  for (int i = 0; i < 200; ++i) (GrooveArea(big, r, 0.5 * (low + high)) < area ? low : high) = 0.5 * (low + high);
  return 0.5 * (low + high);
}

// In the straight cased hole the rotating soft string presses w sin 30° = 135.4893 N/m on the casing
// (w = 270.97859 N/m with its joints), whatever the friction. From 200 to 245 m the string rotates
// 45 m / 20 m/h = 8100 s, to 290 m 8100 s more; the sliding distance π D_tj (ω/2π) t, so the worn area
// WF (F_n/L) π D_tj (ω/2π) t = 5.8026e-7 m² at 245 m and 1.16052e-6 m² at 290 m, the same at every casing
// station (the string covers the casing at every depth). Grooves (Python): 6.4394e-5 m and 1.02264e-4 m
// deep, of the 0.01199 m wall 0.537 % and 0.853 %. Nothing worn at the first depth.
TEST(RoadmapScreens, CasingWearAccumulatesDownTheRoadmapByHand) {
  const io::Case c = WearCase();
  const analyses::RoadmapSettings settings = CompleteRoadmapSettings(c, {200.0, 45.0, {0.2, 0.3}});
  const std::vector<RoadmapPoint> points = RunSoftRoadmap(c, settings);
  ASSERT_EQ(points.size(), 6u);  // 200, 245, 290 m; two friction factors each
  const std::vector<RoadmapWear> wear = RoadmapCasingWear(c, settings, points);
  ASSERT_EQ(wear.size(), points.size());
  const double area = Area(0.127, 0.1086);
  const double w = kGravity * kBuoyedDensity * (area + 0.5 / 9.0 * (Area(0.1683, 0.0826) - area));
  const double side = w * 0.5;
  EXPECT_NEAR(side, 135.4893, 1e-4);
  EXPECT_NEAR(GrooveDepth(0.5 * 0.2205, 0.5 * 0.1683, 1.1605236e-6), 1.02264e-4, 1e-9);  // the figure above
  const double omega = 120.0 * kPi / 30.0, rop = 20.0 / 3600.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double time = (points[i].bit_md - 200.0) / rop;
    const double worn = 5e-13 * side * kPi * 0.1683 * omega / (2.0 * kPi) * time;
    if (time == 0.0) {
      EXPECT_DOUBLE_EQ(wear[i].rotating_time, 0.0);
      EXPECT_FALSE(std::isfinite(wear[i].groove_depth)) << "nothing drilled yet";
      continue;
    }
    const double groove = GrooveDepth(0.5 * 0.2205, 0.5 * 0.1683, worn);
    EXPECT_NEAR(wear[i].rotating_time, time, 1e-9 * time) << points[i].bit_md;
    EXPECT_NEAR(wear[i].side_force_per_length, side, 1e-9 * side) << points[i].bit_md;
    EXPECT_NEAR(wear[i].worn_area, worn, 1e-9 * worn) << points[i].bit_md;
    EXPECT_NEAR(wear[i].groove_depth, groove, 1e-9) << points[i].bit_md;
    EXPECT_NEAR(wear[i].remaining_wall, 0.01199 - groove, 1e-9) << points[i].bit_md;
    EXPECT_NEAR(wear[i].utilisation, groove / 0.01199, 1e-7) << points[i].bit_md;
    EXPECT_LE(wear[i].md, 150.0);
    std::printf("bit %.0f m, mu %.1f: worn %.6e m2 (hand %.6e), groove %.6e m (hand %.6e)\n", points[i].bit_md,
                points[i].friction, wear[i].worn_area, worn, wear[i].groove_depth, groove);
  }
  // Without a rop (a run of rotating hours at the bit MD): no wear along the roadmap.
  io::Case hours = c;
  hours.limits.wear->rate_of_penetration.reset();
  hours.limits.wear->rotating_time = 3600.0;
  EXPECT_FALSE(std::isfinite(RoadmapCasingWear(hours, settings, points).back().groove_depth));
}

}  // namespace roadmap_screens_test
}  // namespace drillflex::pipeline
