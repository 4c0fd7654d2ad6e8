// The string's limits along a static (analyses/string_limits.hpp) on a case's string in a straight
// hole at 30°, against hand computations: Dawson & Paslay's load with r of the tool joints wherever
// the station lies on a joint, and the stations, zones and utilisations of a given axial force.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "analyses/string_limits.hpp"
#include "io/case.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::analyses {
namespace string_limits_screen_test {

// Three 9 m collars, then 9 m joints of 5 in pipe (0.127 × 0.1086 m) with 6-5/8 in tool joints
// (0.1683 × 0.0826 m, 0.5 m a joint) in an 8-1/2 in (0.2159 m) hole at 30°, 1200 kg/m³ mud, g 9.81.
io::Case Case(int inclination_deg = 30) {
  return io::ParseCase(fmt::format(R"(name: limits
units: SI
gravity: 9.81
well:
  survey: [[0, {0}, 0], [400, {0}, 0]]
  hole: [{{diameter: 0.2159}}]
  bit_md: 297
fluid: {{density: 1200}}
string:
  - {{type: collar, od: 0.1715, id: 0.0714, length: 9, count: 3}}
  - {{type: pipe, od: 0.127, id: 0.1086, length: 9, count: 5, joint_od: 0.1683, joint_id: 0.0826, joint_length: 0.5}}
model: {{body_length: 9, elements_per_body: 4, modes_per_body: 4}}
operation: {{wob: 40 kN, torque_on_bit: 2 kN*m, rpm: 60}}
analyses:
  static: {{}}
)",
                                   inclination_deg),
                       "limits.yaml");
}

// By hand (Python): w = g (ρ_s − ρ_m) (A_body + 0.5/9 (A_joint − A_body)) = 270.97859 N/m,
// E I = 2.1e11 π/64 (0.127⁴ − 0.1086⁴) = 1 247 796.5 N·m², r = (0.2159 − 0.1683)/2 = 0.0238 m:
// F_s = 2 √(E I w sin 30° / r) = 168 564.41 N, F_h = √2 F_s = 238 386.08 N. (With the body's
// r = 0.04445 m it would be 123 344.1 N.)
constexpr double kSinusoidal = 168564.41;
constexpr double kHelical = 238386.08;

TEST(StringLimitsScreen, DawsonPaslayWithTheToolJointsClearanceAlongTheWholeJoint) {
  const io::Case c = Case();
  // s 31.5 m: mid-body of the first joint; s 36 m: on its connection (a tool joint).
  for (const double s : {31.5, 36.0, 60.0}) {
    EXPECT_NEAR(BucklingLoadsAt(c.input, s, 297.0 - s).sinusoidal, kSinusoidal, 0.5) << "s " << s;
    EXPECT_NEAR(BucklingLoadsAt(c.input, s, 297.0 - s).helical, kHelical, 0.5) << "s " << s;
  }
}

// In a vertical hole Dawson–Paslay's load is zero (no weight across the hole); the string's own weight
// holds it: Lubinski's 1.94 (E I w²)^(1/3) and Wu & Juvkam-Wold's 5.55 (E I w²)^(1/3). By hand (Python):
// (E I w²)^(1/3) = (1 247 796.5 × 270.97859²)^(1/3) = 4508.2145 N: 8745.94 N and 25 020.59 N.
TEST(StringLimitsScreen, AVerticalHoleTakesLubinskisLoadsNotZero) {
  const io::Case c = Case(0);
  const BucklingLoads loads = BucklingLoadsAt(c.input, 60.0, 237.0);
  EXPECT_NEAR(loads.sinusoidal, 8745.94, 0.05);
  EXPECT_NEAR(loads.helical, 25020.59, 0.05);
}

TEST(StringLimitsScreen, ZonesAndUtilisationsOfAGivenAxialForce) {
  const io::Case c = Case();
  // Stations every metre from s 28 to 40 m (all pipe): compression 0.5 F_s, then 1.2 F_s (s 31-33,
  // sinusoidal), 1.6 F_s (s 34-35, beyond √2 F_s: helical), then 0.2 F_s.
  std::vector<StaticNodeResult> nodes;
  for (int s = 28; s <= 40; ++s) {
    StaticNodeResult node;
    node.s = s;
    node.has_wall = true;
    node.md = 297.0 - s;
    const double ratio = s <= 30 ? 0.5 : s <= 33 ? 1.2 : s <= 35 ? 1.6 : 0.2;
    node.axial_force = -ratio * kSinusoidal;
    nodes.push_back(node);
  }
  const StringLimits limits = ComputeStringLimits(c.input, nodes, 1.25);
  ASSERT_EQ(limits.nodes.size(), nodes.size());
  EXPECT_EQ(limits.nodes[0].buckling, BucklingState::None);
  EXPECT_EQ(limits.nodes[3].buckling, BucklingState::Sinusoidal);
  EXPECT_EQ(limits.nodes[6].buckling, BucklingState::Helical);
  EXPECT_NEAR(limits.nodes[6].helical_load, kHelical, 0.5);
  ASSERT_EQ(limits.zones.size(), 2u);
  EXPECT_EQ(limits.zones[0].state, BucklingState::Sinusoidal);
  EXPECT_DOUBLE_EQ(limits.zones[0].md_from, 297.0 - 35.0);
  EXPECT_DOUBLE_EQ(limits.zones[0].md_to, 297.0 - 31.0);
  EXPECT_EQ(limits.zones[1].state, BucklingState::Helical);
  EXPECT_DOUBLE_EQ(limits.zones[1].md_from, 297.0 - 35.0);
  EXPECT_DOUBLE_EQ(limits.zones[1].md_to, 297.0 - 34.0);
  // Helical: 1.6 F_s / (√2 F_s) = 1.131371 at s 34 (the first of the two).
  EXPECT_NEAR(limits.helical_buckling.utilisation, 1.6 / std::sqrt(2.0), 1e-6);
  EXPECT_DOUBLE_EQ(limits.helical_buckling.s, 34.0);
  // Yield: E-75 (no grade given), 75 ksi / 1.25 = 413.685 MPa; |N| / A with A = 3.4047325e-3 m²:
  // 1.6 × 168 564.41 / 3.4047325e-3 / 413.685438e6 = 0.191484.
  EXPECT_NEAR(limits.yield.utilisation, 1.6 * kSinusoidal / 3.4047325e-3 / 413.685438e6, 1e-5);
  EXPECT_EQ(limits.closest.limit, "helical_buckling");
  EXPECT_FALSE(std::isfinite(limits.makeup_torque.utilisation));
  EXPECT_EQ(limits.notes.size(), 2u);  // the pipe rated as E-75; no make-up torque
}

// The same 5 in pipe (`joints` of it, above `below`'s components) in an 8-1/2 in hole along `survey`
// (MD, inclination, azimuth rows), 1200 kg/m³ mud, g 9.81, the bit at `bit_md`, under `operation`.
io::Case PipeCase(const std::string& survey, double bit_md, const std::string& below, int joints,
                  const std::string& operation) {
  const std::string text = fmt::format(
      "name: pipe\nunits: SI\ngravity: 9.81\nwell: {{survey: {}, hole: [{{diameter: 0.2159}}], bit_md: {}}}\n"
      "fluid: {{density: 1200}}\nstring:\n{}"
      "  - {{type: pipe, od: 0.127, id: 0.1086, length: 9, count: {}, joint_od: 0.1683, joint_id: 0.0826, "
      "joint_length: 0.5}}\nmodel: {{body_length: 9, elements_per_body: 4, modes_per_body: 4}}\noperation: {}\n",
      survey, bit_md, below, joints, operation);
  return io::ParseCase(text, "pipe.yaml");
}

// Fatigue in a dogleg: the same pipe (joints 9 m apart: L = 4.5 m) in a build of 3°/30 m from 100 to 400 m
// MD, rotating, 200 kN of tension, no bending of its own in the static. By hand (Python, RP 7G's grade E
// line for the default E-75): σ_t = 200 kN / A = 8519.773 psi, σ_allowed = 119 929 736.3 Pa,
// K L = √(T/(E I)) 4.5 = 1.801589, σ_b = E D κ/2 · KL/tanh KL = 44 278 170.75 Pa with κ = 1.7453293e-3 /m:
// the fatigue utilisation 0.3692009; Lubinski's permissible curvature 2 σ_allowed/(E D) · tanh KL/KL =
// 4.7273154e-3 /m (8.1257 °/30 m).
TEST(StringLimitsScreen, FatigueInABuildByHand) {
  const io::Case c = PipeCase("[[0, 0, 0], [100, 0, 0], [400, 30, 0]]", 350.0,
                              "  - {type: collar, od: 0.1715, id: 0.0714, length: 9, count: 3}\n", 30,
                              "{wob: 40 kN, rpm: 60}");
  StaticNodeResult node;
  node.s = 100.0;  // MD 250 m: pipe in the build
  node.axial_force = 200e3;
  std::vector<StaticNodeResult> nodes{node};
  const StringLimits limits = ComputeStringLimits(c.input, nodes, 1.25);
  ASSERT_EQ(limits.nodes.size(), 1u);
  const NodeLimits& at = limits.nodes[0];
  EXPECT_NEAR(at.hole_curvature, 1.7453293e-3, 1e-9);
  EXPECT_NEAR(at.allowable_bending_stress, 119929736.3, 1.0);
  EXPECT_NEAR(at.dogleg_bending_stress, 44278170.75, 1.0);
  EXPECT_NEAR(at.fatigue_utilisation, 0.3692009, 1e-6);
  EXPECT_NEAR(at.max_dogleg, 4.7273154e-3, 1e-9);
  EXPECT_EQ(limits.fatigue.limit, "fatigue");
  EXPECT_DOUBLE_EQ(limits.fatigue.md, 250.0);
  // Not rotating: no fatigue screen.
  io::Case still = c;
  still.input.operation.rotary_speed = 0.0;
  EXPECT_FALSE(std::isfinite(ComputeStringLimits(still.input, nodes, 1.25).fatigue.utilisation));
}

// A roadmap point's buckled zones (pipeline::RoadmapPointLimits): the same pipe alone, 2000 m down a
// straight 30° hole, drilling on bottom with 300 kN: the soft string rotating carries no axial friction, so
// the compression falls from the WOB by w cos 30° = 234.674 N/m up the hole. By hand: beyond F_h (238 386.08 N)
// for (300 000 − 238 386.08)/234.674 = 262.55 m above the bit, beyond F_s (168 564.41 N) for 560.08 m; the
// zones end at the soft string's stations (every 30 ft, 9.144 m). Slacking off from the bit (off bottom)
// nothing is in compression.
TEST(StringLimitsScreen, RoadmapPointBuckledZonesByHand) {
  const io::Case c = PipeCase("[[0, 30, 0], [2500, 30, 0]]", 2000.0, "", 20, "{wob: 300 kN, rpm: 60}");
  pipeline::RoadmapPoint point;
  point.bit_md = 2000.0;
  point.friction = 0.25;
  const pipeline::RoadmapLimits limits = pipeline::RoadmapPointLimits(c, analyses::RoadmapSettings{}, point);
  EXPECT_TRUE(limits.screens.slack_off.zones.empty());
  ASSERT_EQ(limits.screens.on_bottom.zones.size(), 2u);
  EXPECT_EQ(limits.screens.on_bottom.zones[0].state, BucklingState::Sinusoidal);
  EXPECT_NEAR(limits.screens.on_bottom.zones[0].md_from, 2000.0 - 560.08, 9.2);
  EXPECT_DOUBLE_EQ(limits.screens.on_bottom.zones[0].md_to, 2000.0);
  EXPECT_EQ(limits.screens.on_bottom.zones[1].state, BucklingState::Helical);
  EXPECT_NEAR(limits.screens.on_bottom.zones[1].md_from, 2000.0 - 262.55, 9.2);
  EXPECT_DOUBLE_EQ(limits.screens.on_bottom.zones[1].md_to, 2000.0);
  // Pulling out and rotating off bottom the string hangs in tension from the bit up: no zone.
  EXPECT_TRUE(limits.screens.pick_up.zones.empty());
  EXPECT_TRUE(limits.screens.rotating.zones.empty());
}

// The zones of all four runs of a roadmap point (pipeline::RoadmapPointLimits), by hand: the same pipe
// 2000 m down a straight hole rising at 150° (60° above the horizontal: steep enough that even pulling
// out leaves the string in compression), friction 0.25, drilling with 50 kN. In a straight hole the soft
// string's wall force is w sin 150° a metre and its axial force changes by w cos 150° ± μ w sin 150° up the
// hole (w = 270.97859 N/m): the compression grows by 200.8020 N/m pulling out (−cos + μ sin), 268.5467 N/m
// running in (−cos − μ sin), 234.6743 N/m rotating (−cos), from 0 off bottom and from the WOB on bottom.
// sin 150° = sin 30°: F_s and F_h are the 30° hole's. Beyond F_s (F_h) from (F − WOB)/rate above the bit
// to the surface (Python): pick-up 839.46 (1187.17) m, slack-off 627.69 (887.69) m, rotating 718.29
// (1015.82) m, on bottom 505.23 (802.76) m. Each zone runs from the surface to MD 2000 m less that; its
// deep end lies at a soft-string station (every 9.144 m).
TEST(StringLimitsScreen, RoadmapPointZonesOfEveryRunByHand) {
  const io::Case c = PipeCase("[[0, 150, 0], [2500, 150, 0]]", 2000.0, "", 20, "{wob: 50 kN, rpm: 60}");
  pipeline::RoadmapPoint point;
  point.bit_md = 2000.0;
  point.friction = 0.25;
  const pipeline::RoadmapLimits limits = pipeline::RoadmapPointLimits(c, analyses::RoadmapSettings{}, point);
  struct Expected {
    const char* run;
    const std::vector<BuckledZone>* zones;
    double sinusoidal, helical;  // m above the bit where the compression reaches F_s, F_h
  };
  for (const Expected& run : {Expected{"pick-up", &limits.screens.pick_up.zones, 839.46, 1187.17},
                              Expected{"slack-off", &limits.screens.slack_off.zones, 627.69, 887.69},
                              Expected{"rotating", &limits.screens.rotating.zones, 718.29, 1015.82},
                              Expected{"on bottom", &limits.screens.on_bottom.zones, 505.23, 802.76}}) {
    ASSERT_EQ(run.zones->size(), 2u) << run.run;
    const BuckledZone& sinusoidal = (*run.zones)[0];
    const BuckledZone& helical = (*run.zones)[1];
    EXPECT_EQ(sinusoidal.state, BucklingState::Sinusoidal) << run.run;
    EXPECT_NEAR(sinusoidal.md_from, 0.0, 9.2) << run.run;
    EXPECT_NEAR(sinusoidal.md_to, 2000.0 - run.sinusoidal, 9.2) << run.run;
    EXPECT_EQ(helical.state, BucklingState::Helical) << run.run;
    EXPECT_NEAR(helical.md_from, 0.0, 9.2) << run.run;
    EXPECT_NEAR(helical.md_to, 2000.0 - run.helical, 9.2) << run.run;
  }
}

}  // namespace string_limits_screen_test
}  // namespace drillflex::analyses
