// The torque-and-drag roadmap (pipeline/roadmap.hpp) against the soft-string references a straight
// hole gives exactly (Johancsik et al. 1984): in a vertical hole the three hook loads are the buoyed
// weight W; in a straight hole at inclination I the string lies on the low side with N = w sin I a
// metre, so pulling out reads W cos I + μ W sin I, running in W cos I − μ W sin I, and rotating
// W cos I (the friction then acts around the string).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analyses/soft_string.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::pipeline {
namespace roadmap_test {

constexpr double kSteelDensity = 7850.0;  // kg/m³ (fe/material.hpp built-in steel)
constexpr double kMudDensity = 1200.0;    // kg/m³
constexpr double kGravity = 9.81;         // m/s² (the case's default with a well)

// Buoyed weight a metre of a plain tube (no tool joints), N/m: steel less the mud it displaces,
// inside and out.
double TubeWeight(double od, double id) { return kGravity * (kSteelDensity - kMudDensity) * kPi / 4.0 * (od * od - id * id); }

// Three 9 m collars and 9 m joints of plain pipe to the surface in a straight hole at `inclination`,
// the bit at 297 m (27 m of collars and 30 joints: nothing above the model).
io::Case StraightHole(double inclination_deg) {
  return io::ParseCase(fmt::format(R"(name: roadmap
units: SI
well:
  survey: [[0, {0}, 0], [400, {0}, 0]]
  hole: [{{diameter: 0.2159}}]
  bit_md: 297
fluid: {{density: 1200}}
string:
  - {{type: collar, od: 0.1715, id: 0.0714, length: 9, count: 3}}
  - {{type: pipe, od: 0.127, id: 0.1086, length: 9, count: 5}}
model: {{body_length: 9, elements_per_body: 4, modes_per_body: 4}}
operation: {{wob: 40 kN, torque_on_bit: 2 kN*m, rpm: 60}}
analyses:
  static: {{}}
)",
                                   inclination_deg),
                       "roadmap.yaml");
}

std::vector<RoadmapPoint> Roadmap(const io::Case& c, const analyses::RoadmapSettings& settings) {
  return RunRoadmap(c, CompleteRoadmapSettings(c, settings));
}

double BuoyedWeight(double bit_md) {
  return TubeWeight(0.1715, 0.0714) * 27.0 + TubeWeight(0.127, 0.1086) * (bit_md - 27.0);
}

// The stiff model's string (StiffCaseAtDepth): the case's own (3 collars and 5 joints, 72 m) where
// no part of it is in compression; else up to a stand (27.43 m) and a joint above the soft string's
// highest station in compression. At 297 m in the 30° hole under the 40 kN WOB: the collars (1245.6
// N/m buoyed, 27 m) leave −40 000 + 1245.6 × 27 × cos 30° = −10 875 N at their top, the pipe (222.1
// N/m) adds 192.4 N/m along the hole, so the soft string's stations every 9 m are in compression up
// to 81 m; 81 + 27.43 + 9 = 117.4 m takes ten joints (117 m).
TEST(Roadmap, TheStiffModelHangsInTensionAtItsTop) {
  const io::Case inclined = StraightHole(30.0);
  analyses::RoadmapSettings settings = CompleteRoadmapSettings(inclined, {297.0, 45.0, {0.2}});
  EXPECT_EQ(StiffCaseAtDepth(inclined, 297.0, settings).input.string.components.back().count, 10);
  io::Case no_wob = inclined;
  no_wob.input.operation.weight_on_bit = 0.0;
  EXPECT_EQ(StiffCaseAtDepth(no_wob, 297.0, settings).input.string.components.back().count, 5);
  settings.stiff_length = 200.0;  // 27 + 19 × 9 = 198 m
  EXPECT_EQ(StiffCaseAtDepth(no_wob, 297.0, settings).input.string.components.back().count, 19);
  settings.stiff_length = std::numeric_limits<double>::infinity();
  EXPECT_EQ(StiffCaseAtDepth(no_wob, 297.0, settings).input.string.components.back().count, 30);
  EXPECT_EQ(StiffCaseAtDepth(no_wob, 60.0, settings).input.string.components.back().count, 3);  // 27 + 27 ≤ 60
}

TEST(Roadmap, TheTopComponentReachesTheSurface) {
  const io::Case c = CaseAtDepth(StraightHole(0.0), 200.0);
  EXPECT_EQ(c.input.string.components.back().count, 19);  // 27 + 19 × 9 = 198 m: 2 m above the model
  EXPECT_EQ(c.input.bit_md, 200.0);
  EXPECT_THROW(CaseAtDepth(StraightHole(0.0), 30.0), InputError);
}

// Off bottom the string hangs straight: pick-up, slack-off and rotating all read the buoyed weight. On
// bottom the 40 kN WOB puts the lower pipe (above 27 m of collars weighing 30 kN) in compression,
// which in a vertical hole buckles it with no low side to lie on; with the torque on bit the energy's
// minimum is not found there (the buckled spans' azimuth is free and the dead torque keeps releasing
// work as they turn), so the on-bottom run fails with its reason and leaves only its torque NaN. (The
// fallback paths removed in issue 32 reported the straight, unstable string instead: the torque on
// bit alone, 2 kN·m.)
TEST(Roadmap, AVerticalHoleHangsItsBuoyedWeightWhateverTheMotion) {
  const std::vector<RoadmapPoint> points = Roadmap(StraightHole(0.0), {207.0, 45.0, {0.2, 0.4}});
  ASSERT_EQ(points.size(), 6u);  // 207, 252 and 297 m, two friction factors each
  for (const RoadmapPoint& point : points) {
    EXPECT_TRUE(std::isnan(point.on_bottom_torque)) << point.bit_md << " m: " << point.on_bottom_torque;
    EXPECT_EQ(point.message.rfind("on bottom: ", 0), 0u) << point.message;
    const double weight = BuoyedWeight(point.bit_md);
    for (const double hook : {point.pick_up, point.slack_off, point.rotating}) {
      EXPECT_NEAR(hook, weight, 1e-3 * weight) << point.bit_md << " m, mu " << point.friction;
    }
  }
}

TEST(Roadmap, AStraightInclinedHoleDragsMuWSinI) {
  const double inclination = 30.0 * kPi / 180.0;
  for (const double friction : {0.2, 0.4}) {
    const std::vector<RoadmapPoint> points = Roadmap(StraightHole(30.0), {297.0, 45.0, {friction}});
    ASSERT_EQ(points.size(), 1u);
    const RoadmapPoint& point = points.front();
    ASSERT_TRUE(point.message.empty()) << point.message;
    const double weight = BuoyedWeight(297.0);
    const double along = weight * std::cos(inclination), drag = friction * weight * std::sin(inclination);
    EXPECT_NEAR(point.pick_up, along + drag, 5e-3 * (along + drag)) << friction;
    EXPECT_NEAR(point.slack_off, along - drag, 5e-3 * (along - drag)) << friction;
    EXPECT_NEAR(point.rotating, along, 5e-3 * along) << friction;
    // Rotating, the string climbs the wall until μN and N together carry w sin I a metre (V7):
    // N = w sin I / sqrt(1 + μ²), and the torque is Σ μ N r over the collars (r = 0.08575 m) and the
    // pipe (0.0635 m), clockwise looking down-hole (positive): 656.3 N·m at μ = 0.2. On bottom the TOB
    // (2 kN·m) adds to it.
    const double torque = friction * std::sin(inclination) / std::sqrt(1.0 + friction * friction) *
                          (TubeWeight(0.1715, 0.0714) * 27.0 * 0.08575 + TubeWeight(0.127, 0.1086) * 270.0 * 0.0635);
    EXPECT_NEAR(point.off_bottom_torque, torque, 0.02 * torque) << friction;
    EXPECT_GT(point.on_bottom_torque, point.off_bottom_torque + 1.9e3);
    std::printf("I = 30 deg, mu %.1f: pick-up %.1f N (%+.3f %%), slack-off %.1f N (%+.3f %%), rotating %.1f N "
                "(%+.3f %%), off-bottom torque %.1f N*m (%+.3f %%)\n",
                friction, point.pick_up, 100.0 * (point.pick_up / (along + drag) - 1.0), point.slack_off,
                100.0 * (point.slack_off / (along - drag) - 1.0), point.rotating, 100.0 * (point.rotating / along - 1.0),
                point.off_bottom_torque, 100.0 * (point.off_bottom_torque / torque - 1.0));
  }
}

// The soft string (RunSoftRoadmap, Johancsik) in the straight 30° hole: exactly W cos I ± μ W sin I
// and W cos I, and the torque μ w sin I r summed, without the stiff string's climb (N = w sin I).
TEST(Roadmap, TheSoftStringIsJohancsiksClosedFormInAStraightHole) {
  const double inclination = 30.0 * kPi / 180.0;
  const io::Case c = StraightHole(30.0);
  const std::vector<RoadmapPoint> points = RunSoftRoadmap(c, CompleteRoadmapSettings(c, {297.0, 45.0, {0.2}}));
  ASSERT_EQ(points.size(), 1u);
  const RoadmapPoint& point = points.front();
  const double weight = BuoyedWeight(297.0), along = weight * std::cos(inclination);
  const double drag = 0.2 * weight * std::sin(inclination);
  EXPECT_NEAR(point.pick_up, along + drag, 1e-9 * weight);
  EXPECT_NEAR(point.slack_off, along - drag, 1e-9 * weight);
  EXPECT_NEAR(point.rotating, along, 1e-9 * weight);
  const double torque = 0.2 * std::sin(inclination) *
                        (TubeWeight(0.1715, 0.0714) * 27.0 * 0.08575 + TubeWeight(0.127, 0.1086) * 270.0 * 0.0635);
  EXPECT_NEAR(point.off_bottom_torque, torque, 1e-9 * torque);
  EXPECT_NEAR(point.on_bottom_torque, torque + 2e3, 1e-9 * torque);  // TOB 2 kN·m; WOB changes no N here
}

// A gentle 3-D well (a 500 m build to 40° while turning 30°, then a hold) with 1 100 m of plain 5 in
// pipe: the string lies on the wall all along, its bending stiffness carries next to nothing through
// 2.4°/30 m, and the stiff string's hook loads are the soft string's. Its torque is the soft string's
// times 1/√(1 + μ²): the rotating pipe climbs the wall until N and μN carry the lateral load (V7).
TEST(Roadmap, TheStiffStringMeetsTheSoftStringWhereBendingCarriesNothing) {
  const io::Case c = io::ParseCase(R"(name: gentle
units: SI
well:
  survey: [[0, 0, 0], [300, 0, 0], [800, 40, 30], [1200, 40, 30]]
  hole: [{diameter: 0.2159}]
  bit_md: 1100
fluid: {density: 1200}
string:
  - {type: pipe, od: 0.127, id: 0.1086, length: 9, count: 122}
model: {body_length: 9, elements_per_body: 6, modes_per_body: 6}
operation: {rpm: 60}
)",
                                   "gentle.yaml");
  const analyses::RoadmapSettings settings = CompleteRoadmapSettings(c, {1100.0, 100.0, {0.3}});
  const RoadmapPoint stiff = RunRoadmap(c, settings).front();
  const RoadmapPoint soft = RunSoftRoadmap(c, settings).front();
  // The lower 300 m stiff, the pipe above by the soft string from the stiff part's top tension and
  // torque: the same hook loads, and the torque with the climb the stiff string has.
  analyses::RoadmapSettings shorter = settings;
  shorter.stiff_length = 300.0;
  const RoadmapPoint part = RunRoadmap(c, shorter).front();
  ASSERT_TRUE(part.message.empty()) << part.message;
  EXPECT_NEAR(part.pick_up, soft.pick_up, 5e-4 * soft.pick_up);
  EXPECT_NEAR(part.slack_off, soft.slack_off, 5e-4 * soft.slack_off);
  EXPECT_NEAR(part.rotating, soft.rotating, 5e-4 * soft.rotating);
  ASSERT_TRUE(stiff.message.empty()) << stiff.message;
  EXPECT_NEAR(stiff.pick_up, soft.pick_up, 5e-4 * soft.pick_up);
  EXPECT_NEAR(stiff.slack_off, soft.slack_off, 5e-4 * soft.slack_off);
  EXPECT_NEAR(stiff.rotating, soft.rotating, 5e-4 * soft.rotating);
  const double climbing = soft.off_bottom_torque / std::sqrt(1.0 + 0.3 * 0.3);
  EXPECT_NEAR(stiff.off_bottom_torque, climbing, 0.01 * climbing);
  EXPECT_NEAR(part.off_bottom_torque, climbing, 0.01 * climbing);
  std::printf("gentle 3-D well, mu 0.3: stiff / soft pick-up %+.4f %%, slack-off %+.4f %%, rotating %+.4f %%, "
              "torque against soft/sqrt(1+mu^2) %+.3f %%\n",
              100.0 * (stiff.pick_up / soft.pick_up - 1.0), 100.0 * (stiff.slack_off / soft.slack_off - 1.0),
              100.0 * (stiff.rotating / soft.rotating - 1.0), 100.0 * (stiff.off_bottom_torque / climbing - 1.0));
}


// The stiff string's limit EI → 0 is the soft string (Johancsik), in a well where bending carries
// load: a 3-D build at 6°/30 m while turning (200 m → 400 m: 40° of build, 30° of turn), then a hold,
// 5 in pipe without tool joints, the whole string stiff (stiff_length = surface), μ = 0.3. The model's
// `bending_stiffness_factor` lowers EI alone (EA, GJ, the weight stay). The soft string's elements are
// 0.25 m (its scheme is first order in their length: at 9 m its drags move by ~1.4 %), its rotating
// torque with the climb of the wall (SoftStringOperation::wall_climb, V7). Measured (Release):
//
//   hole      EI ×     pick-up drag   slack-off drag   torque   (stiff against soft)
//   5.31 in   1        +2.72 %        +1.33 %          +1.99 %  the pipe's bending at the build's ends
//   5.31 in   0.01     −0.28 %        −0.09 %          −0.07 %
//   5.31 in   1e-4     −0.26 %        −0.06 %          −0.02 %
//   8.5 in    1e-4     −1.22 %        −0.50 %          −0.51 %
//
// What stays at EI → 0 is the clearance, which the soft string leaves out: at the build's end a cable
// pulled to the high side crosses the hole to the low side of the hold free of the wall (over ~√(2·2c·T/w
// sin I), 11 m at c = 44 mm), cutting the corner; it shrinks with the clearance c (44 mm → 4 mm: the
// drags' difference 1.22 → 0.26 % and 0.50 → 0.06 %).
struct EiLimitErrors {
  double pick_up_drag = 0.0;    // (pick-up − rotating) against the soft string's, relative
  double slack_off_drag = 0.0;  // (rotating − slack-off), relative
  double torque = 0.0;          // off-bottom torque, relative
};

EiLimitErrors StiffAgainstSoft(double bending_stiffness_factor, double hole_diameter = 0.2159) {
  const io::Case c = io::ParseCase(fmt::format(R"(name: ei-limit
units: SI
well:
  survey: [[0, 0, 0], [200, 0, 0], [400, 40, 30], [700, 40, 30]]
  hole: [{{diameter: {}}}]
  bit_md: 600
fluid: {{density: 1200}}
string:
  - {{type: pipe, od: 0.127, id: 0.1086, length: 9, count: 66}}
model: {{body_length: 9, elements_per_body: 4, modes_per_body: 4, bending_stiffness_factor: {}}}
operation: {{rpm: 60}}
)",
                                               hole_diameter, bending_stiffness_factor),
                                   "ei-limit.yaml");
  constexpr double kMu = 0.3;
  analyses::RoadmapSettings settings = CompleteRoadmapSettings(c, {600.0, 100.0, {kMu}});
  settings.stiff_length = std::numeric_limits<double>::infinity();
  const RoadmapPoint stiff = RunRoadmap(c, settings).front();
  EXPECT_TRUE(stiff.message.empty()) << stiff.message;
  const io::Case at = StiffCaseAtDepth(c, 600.0, settings);
  auto soft = [&](analyses::SoftStringMotion motion) {
    analyses::SoftStringOperation operation;
    operation.motion = motion;
    operation.axial_friction = operation.tangential_friction = kMu;
    operation.max_element_length = 0.25;
    operation.wall_climb = true;
    return analyses::ComputeSoftString(at.input, operation);
  };
  const auto pick_up = soft(analyses::SoftStringMotion::PickUp);
  const auto slack_off = soft(analyses::SoftStringMotion::SlackOff);
  const auto rotating = soft(analyses::SoftStringMotion::Rotating);
  EiLimitErrors errors;
  errors.pick_up_drag = (stiff.pick_up - stiff.rotating) / (pick_up.hook_load - rotating.hook_load) - 1.0;
  errors.slack_off_drag = (stiff.rotating - stiff.slack_off) / (rotating.hook_load - slack_off.hook_load) - 1.0;
  errors.torque = stiff.off_bottom_torque / rotating.surface_torque - 1.0;
  std::printf("hole %.4f m, EI x %-6g: pick-up drag %+.3f %%, slack-off drag %+.3f %%, torque %+.3f %% against the soft string\n",
              hole_diameter, bending_stiffness_factor, 100.0 * errors.pick_up_drag, 100.0 * errors.slack_off_drag,
              100.0 * errors.torque);
  return errors;
}

TEST(Roadmap, TheStiffStringApproachesTheSoftStringAsEIGoesToZero) {
  const EiLimitErrors steel = StiffAgainstSoft(1.0, 0.135);
  const EiLimitErrors cable = StiffAgainstSoft(1e-4, 0.135);
  const EiLimitErrors wide = StiffAgainstSoft(1e-4, 0.2159);
  // The steel pipe's bending stiffness adds drag and torque in the build (~2 μ κ √(EI T) a dogleg end).
  EXPECT_GT(steel.pick_up_drag, 0.015);
  EXPECT_GT(steel.slack_off_drag, 0.007);
  EXPECT_GT(steel.torque, 0.01);
  // With EI → 0 (and a small clearance) the stiff string is the soft string.
  EXPECT_LT(std::abs(cable.pick_up_drag), 0.004);
  EXPECT_LT(std::abs(cable.slack_off_drag), 0.0015);
  EXPECT_LT(std::abs(cable.torque), 0.001);
  // What is left shrinks with the clearance.
  EXPECT_LT(std::abs(cable.pick_up_drag), 0.5 * std::abs(wide.pick_up_drag));
  EXPECT_LT(std::abs(cable.slack_off_drag), 0.5 * std::abs(wide.slack_off_drag));
  EXPECT_LT(std::abs(cable.torque), 0.5 * std::abs(wide.torque));
}

// Friction by hole section (well.hole `cased`, `friction`): the straight 30° hole cased to 150 m MD
// with its own friction 0.15, open below. The roadmap's factor (0.3) is the open hole's; the cased
// hole keeps its own unless the settings' cased_friction replaces it. At 297 m the pipe runs from the
// surface to 270 m (150 m of it cased, 120 m open) and the collars 270–297 m (open). By hand
// (Johancsik in a straight hole, N = w sin I a metre): pick-up W cos I + sin I Σ μ_k w_k L_k,
// slack-off with −, the torque sin I Σ μ_k w_k L_k r_k; the stiff string's torque with each section's
// climb, N = w sin I / √(1 + μ_k²).
io::Case CasedAbove150(double inclination_deg) {
  io::Case c = StraightHole(inclination_deg);
  c.input.well = model::MakeWellbore(
      c.input.well->trajectory, {well::HoleSection{150.0, 0.2159, {}, true, 0.15}, well::HoleSection{{}, 0.2159, {}}});
  return c;
}

struct SectionDrag {
  double along = 0.0, drag = 0.0, torque = 0.0, climbing_torque = 0.0;
};

SectionDrag HandComputed(double inclination, double cased, double open) {
  const double pipe = TubeWeight(0.127, 0.1086), collar = TubeWeight(0.1715, 0.0714);
  SectionDrag d;
  d.along = BuoyedWeight(297.0) * std::cos(inclination);
  const double sine = std::sin(inclination);
  d.drag = sine * (cased * pipe * 150.0 + open * (pipe * 120.0 + collar * 27.0));
  const double cased_torque = cased * sine * pipe * 150.0 * 0.0635;
  const double open_torque = open * sine * (pipe * 120.0 * 0.0635 + collar * 27.0 * 0.08575);
  d.torque = cased_torque + open_torque;
  d.climbing_torque = cased_torque / std::sqrt(1.0 + cased * cased) + open_torque / std::sqrt(1.0 + open * open);
  return d;
}

TEST(Roadmap, CasedAndOpenHoleEachDragWithTheirOwnFriction) {
  const double inclination = 30.0 * kPi / 180.0;
  const io::Case c = CasedAbove150(30.0);
  for (const std::optional<double> cased_friction : {std::optional<double>{}, std::optional<double>{0.05}}) {
    analyses::RoadmapSettings settings = CompleteRoadmapSettings(c, {297.0, 45.0, {0.3}});
    settings.cased_friction = cased_friction;
    const SectionDrag hand = HandComputed(inclination, cased_friction.value_or(0.15), 0.3);
    const RoadmapPoint soft = RunSoftRoadmap(c, settings).front();
    EXPECT_NEAR(soft.pick_up, hand.along + hand.drag, 1e-9 * hand.along);
    EXPECT_NEAR(soft.slack_off, hand.along - hand.drag, 1e-9 * hand.along);
    EXPECT_NEAR(soft.off_bottom_torque, hand.torque, 1e-9 * hand.torque);
    const RoadmapPoint stiff = RunRoadmap(c, settings).front();
    ASSERT_TRUE(stiff.message.empty()) << stiff.message;
    EXPECT_NEAR(stiff.pick_up, hand.along + hand.drag, 5e-3 * (hand.along + hand.drag));
    EXPECT_NEAR(stiff.slack_off, hand.along - hand.drag, 5e-3 * (hand.along - hand.drag));
    EXPECT_NEAR(stiff.off_bottom_torque, hand.climbing_torque, 0.02 * hand.climbing_torque);
    std::printf("cased 0.15 over 150 m%s, open 0.3: stiff pick-up %+.3f %%, slack-off %+.3f %%, torque %+.3f %% "
                "against the hand computation\n",
                cased_friction ? " (replaced by 0.05)" : "",
                100.0 * (stiff.pick_up / (hand.along + hand.drag) - 1.0),
                100.0 * (stiff.slack_off / (hand.along - hand.drag) - 1.0),
                100.0 * (stiff.off_bottom_torque / hand.climbing_torque - 1.0));
  }
}

}  // namespace roadmap_test
}  // namespace drillflex::pipeline
