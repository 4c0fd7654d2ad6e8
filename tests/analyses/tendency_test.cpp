// Directional tendency (analyses/tendency_analysis.hpp, tendency_hole.hpp).
//
// The steady hole: ends at the case's bit with its direction, is the circle of the asked curvature
// above it (checked against the circle's closed form), straight above the arc. The carry into a hole
// is the identity into the same hole.
//
// The steady curvature's limits (tendency.md): with S → ∞ (1e6) the curvature is the one at which a
// static in a hole drawn at that curvature, independently of the tendency's own hole (its survey
// written from I(σ) = I_bit − κ σ), has no build force at the bit: the force changes sign between
// κ* ∓ 0.01°/100 ft; with S = 0 the bit's tilt changes sign there.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analyses/point_the_bit.hpp"
#include "analyses/tendency_analysis.hpp"
#include "cms/reduction_cache.hpp"
#include "core/error.hpp"
#include "fe/material.hpp"
#include "field_parts.hpp"

namespace drillflex::analyses {
namespace tendency_test {

using testing::kFt;
using testing::kIn;
using testing::kLbf;
using testing::Part;

constexpr double kBitMd = 3000.0 * kFt;
constexpr double kInclination = 40.0 * kDegree;
constexpr double kAzimuth = 90.0 * kDegree;

// A packed rotary BHA (bit, near-bit stabilizer, 30 ft collar, string stabilizer, two collars), not
// rotating, 25 klbf on the bit, in a straight hole at 40° toward the east, 10 ppg mud.
model::ModelInput PackedBha() {
  model::ModelInput input;
  model::Component stabilizer = Part(model::ComponentType::Stabilizer, 6.75, 2.8125, 5.0);
  stabilizer.blade_diameter = 8.375 * kIn;
  stabilizer.blade_length = 1.5 * kFt;
  input.string.components = {Part(model::ComponentType::Bit, 8.5, 2.0, 1.0), stabilizer,
                             Part(model::ComponentType::Collar, 6.75, 2.8125, 30.0), stabilizer,
                             Part(model::ComponentType::Collar, 6.75, 2.8125, 30.0, 2)};
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.gravity = 9.81;
  input.fluid = model::FluidConfig{1198.0, 0.02, {}, -1.0};
  input.settings.elements_per_body = 6;
  input.settings.modes_per_body = 4;
  input.well = model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{
                                       {0.0, kInclination, kAzimuth}, {4000.0 * kFt, kInclination, kAzimuth}}),
                                   std::vector<well::HoleSection>{well::HoleSection{{}, 8.5 * kIn, {}}});
  input.bit_md = kBitMd;
  input.operation.weight_on_bit = 25000.0 * kLbf;
  return input;
}

// The hole building at `build` (1/m) over the string and 30 m above it, straight above that: its
// survey written from the inclination along the arc, I(σ) = I_bit − κ σ (σ up from the bit).
model::ModelInput InBuildingHole(model::ModelInput input, double build) {
  const double arc = model::StringLength(input.string) + 30.0;
  std::vector<well::SurveyStation> stations = {{0.0, kInclination - build * arc, kAzimuth}};
  for (int i = 40; i >= 0; --i) {
    const double sigma = arc * i / 40.0;
    stations.push_back({kBitMd - sigma, kInclination - build * sigma, kAzimuth});
  }
  input.well = model::MakeWellbore(well::Trajectory(stations), input.well->hole.sections());
  return input;
}

const ModelFactory& Factory() {
  static cms::ReductionCache cache;
  static const ModelFactory build = [](const model::ModelInput& input) { return model::BuildSystemModel(input, cache); };
  return build;
}

BitReport BitIn(const model::ModelInput& input) {
  const model::BuiltModel built = Factory()(input);
  const StaticResult result = RunStaticInWell(input, built, StaticSettings{});
  return *result.bit;
}

TEST(TendencyHole, EndsAtTheBitAndIsTheCircleOfItsCurvature) {
  const model::ModelInput input = PackedBha();
  const HoleCurvature curvature{3.0 * kDegreesPer100Ft, -1.5 * kDegreesPer100Ft};
  const double arc = 60.0, top = kBitMd - 100.0;
  const well::Trajectory hole = ConstantCurvatureHole(input.well->trajectory, kBitMd, top, arc, curvature);
  const well::PathFrame bit = input.well->trajectory.Frame(kBitMd);
  EXPECT_LT((hole.Position(kBitMd) - input.well->trajectory.Position(kBitMd)).norm(), 1e-9);
  EXPECT_LT((hole.Tangent(kBitMd) - bit.tangent).norm(), 1e-12);
  const Vec3 kappa = curvature.build * bit.high_side + curvature.right * bit.right;
  const double k = kappa.norm();
  const Vec3 n = kappa / k;
  for (const double sigma : {0.5, 17.0, 42.0, 59.5}) {
    const Vec3 expected = input.well->trajectory.Position(kBitMd) - std::sin(k * sigma) / k * bit.tangent +
                          (1.0 - std::cos(k * sigma)) / k * n;
    EXPECT_LT((hole.Position(kBitMd - sigma) - expected).norm(), 1e-9) << sigma;
    EXPECT_NEAR(hole.Curvature(kBitMd - sigma).norm(), k, 1e-12 * k + 1e-15);
  }
  EXPECT_LT((hole.Curvature(kBitMd - 1e-3) - kappa).norm(), 1e-5 * k);
  // Straight above the arc, along its top tangent.
  EXPECT_LT(hole.Curvature(top + 10.0).norm(), 1e-12);
  EXPECT_LT((hole.Tangent(top + 10.0) - hole.Tangent(kBitMd - arc)).norm(), 1e-12);
  const HoleCurvature read = CurvatureAtBit(hole, kBitMd);
  EXPECT_NEAR(read.build, curvature.build, 1e-9 * k);
  EXPECT_NEAR(read.right, curvature.right, 1e-9 * k);
}

TEST(TendencyHole, CarryingIntoTheSameHoleChangesNothing) {
  model::ModelInput input = PackedBha();
  const model::BuiltModel built = Factory()(input);
  const StaticResult result = RunStaticInWell(input, built, StaticSettings{});
  const VecX carried =
      CarryIntoHole(built.system, result.q, built.system, kBitMd, input.well->trajectory, input.well->trajectory);
  EXPECT_LT((carried - result.q).lpNorm<Eigen::Infinity>(), 1e-12);
}

// The steady curvature with S, and the statics that bracket its limit's criterion `criterion`.
template <class Criterion>
void ExpectSteadyCurvatureBrackets(double steerability, Criterion criterion, const char* what) {
  const model::ModelInput input = PackedBha();
  TendencySettings settings;
  settings.steerability = steerability;
  const TendencyResult result = RunTendency(input, Factory(), StaticSettings{}, settings);
  const double steady = result.curvature.build;
  for (const TendencyPoint& point : result.trace) {
    std::printf("[ measure  ]   %+.5f deg/100 ft: deviation %+.4e rad (force %+.4g N, tilt %+.4e rad)\n",
                point.curvature.build / kDegreesPer100Ft, point.deviation_build, point.bit.build_force, point.bit.tilt);
  }
  const double below = criterion(BitIn(InBuildingHole(input, steady - 0.01 * kDegreesPer100Ft)));
  const double above = criterion(BitIn(InBuildingHole(input, steady + 0.01 * kDegreesPer100Ft)));
  std::printf("[ measure  ] S = %g: steady %.4f deg/100 ft build, %.2e right (%zu statics); %s at -0.01: %.4g, "
              "at +0.01: %.4g\n",
              steerability, steady / kDegreesPer100Ft, result.curvature.right / kDegreesPer100Ft, result.trace.size(),
              what, below, above);
  EXPECT_LT(below * above, 0.0) << what << " keeps its sign across the steady curvature ± 0.01 deg/100 ft";
  EXPECT_NEAR(result.curvature.right, 0.0, 1e-3 * kDegreesPer100Ft);  // a plane well, not rotating: no walk
  EXPECT_NEAR(result.turn_rate, 0.0, 1e-3 * kDegreesPer100Ft);
  EXPECT_LE(result.trace.size(), 8u);
}

TEST(Tendency, ZeroSideForceCriterionWhenTheBitSteersAtWill) {
  ExpectSteadyCurvatureBrackets(1e6, [](const BitReport& bit) { return bit.build_force; }, "build force");
}

TEST(Tendency, BitAxisCriterionWhenTheBitCannotSteer) {
  ExpectSteadyCurvatureBrackets(0.0, [](const BitReport& bit) { return bit.tilt; }, "tilt");
}

// A 5° bend 1.5 ft from the bit and full-gauge blades 5.75 ft up: its three-point yield is 174°/100 ft.
// No curvature within ±30°/100 ft is steady: the search says so, with the bit's deviation and side
// force at both ends (both deviations toward the high side: the bit wants more build than 30°/100 ft).
TEST(Tendency, NoSteadyCurvatureWithinThirtyDegreesSaysSoWithBothEnds) {
  model::ModelInput input = PackedBha();
  model::Component motor = Part(model::ComponentType::Motor, 6.75, 4.0, 4.0);
  motor.bend_angle = 5.0 * kDegree;
  motor.bend_to_bit = 1.5 * kFt;
  motor.toolface = 0.0;
  model::Component stabilizer = Part(model::ComponentType::Stabilizer, 6.75, 3.0, 2.0);
  stabilizer.blade_diameter = 8.5 * kIn;
  stabilizer.blade_length = 0.5 * kFt;
  input.string.components = {Part(model::ComponentType::Bit, 8.5, 1.25, 0.75), motor, stabilizer,
                             Part(model::ComponentType::Collar, 6.75, 2.8125, 30.0)};
  input.operation.weight_on_bit = 20000.0 * kLbf;
  try {
    RunTendency(input, Factory(), StaticSettings{}, TendencySettings{});
    ADD_FAILURE() << "a steady curvature was found";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    std::printf("[ measure  ] %s\n", message.c_str());
    EXPECT_NE(message.find("no steady curvature within ±30 deg/100 ft"), std::string::npos) << message;
    EXPECT_NE(message.find("at -30 deg/100 ft the bit deviates +"), std::string::npos) << message;
    EXPECT_NE(message.find("at +30 deg/100 ft the bit deviates +"), std::string::npos) << message;
    EXPECT_NE(message.find("side force"), std::string::npos) << message;
  }
}

// A push-the-bit system: pads 2 ft from the bit pushing it toward the high side with 5 klbf, full steer,
// S → ∞: the steady build is where a static in a hole drawn at that build, with the pads' force put on
// the string as a load of its own, leaves the bit no build force (it changes sign across ± 0.01°/100 ft).
// Neutral (steer 0) it is the BHA's own tendency, to the last digit; the pads build more.
TEST(Tendency, PushTheBitSteersWithItsPadForce) {
  const model::ModelInput input = PackedBha();
  TendencySettings settings;
  settings.steerability = 1e6;
  const double own = RunTendency(input, Factory(), StaticSettings{}, settings).build_rate;
  RssSettings rss;
  rss.at = 2.0 * kFt;
  rss.force = 5000.0 * kLbf;
  rss.toolface = 0.0;
  rss.steer = 0.0;
  settings.rss = rss;
  EXPECT_EQ(RunTendency(input, Factory(), StaticSettings{}, settings).build_rate, own);
  settings.rss->steer = 1.0;
  const double steered = RunTendency(input, Factory(), StaticSettings{}, settings).build_rate;
  model::ModelInput padded = input;
  model::Load pads;
  pads.at = 2.0 * kFt;
  pads.force = Vec3(0.0, 0.0, 5000.0 * kLbf);  // string frame: z the high side
  padded.loads.push_back(pads);
  const double below = BitIn(InBuildingHole(padded, steered - 0.01 * kDegreesPer100Ft)).build_force;
  const double above = BitIn(InBuildingHole(padded, steered + 0.01 * kDegreesPer100Ft)).build_force;
  std::printf("[ measure  ] own %.4f deg/100 ft, pads at full steer %.4f; build force at -0.01: %.4g N, at +0.01: %.4g N\n",
              own / kDegreesPer100Ft, steered / kDegreesPer100Ft, below, above);
  EXPECT_GT(steered, own + 1.0 * kDegreesPer100Ft);
  EXPECT_LT(below * above, 0.0);
}

// A point-the-bit system in the packed BHA: the fulcrum 2.5 ft from the bit (in the near-bit
// stabilizer's body, below its blades at 2.75–4.25 ft), the bit's axis `offset_deg` off the tool's.
RssSettings PointTheBitAt(double offset_deg, double toolface_deg, double steer) {
  RssSettings rss;
  rss.type = RssType::Point;
  rss.at = 2.5 * kFt;
  rss.offset = offset_deg * kDegree;
  rss.toolface = toolface_deg * kDegree;
  rss.steer = steer;
  return rss;
}

TendencyResult PointTheBitTendency(const model::ModelInput& input, const RssSettings& rss) {
  TendencySettings settings;
  settings.rss = rss;
  return RunTendency(input, Factory(), StaticSettings{}, settings);
}

// A zero offset bends nothing: at any steer the tendency is the BHA's own, to round-off.
TEST(Tendency, PointTheBitWithoutOffsetIsTheBhasOwnTendency) {
  const model::ModelInput input = PackedBha();
  const TendencyResult own = RunTendency(input, Factory(), StaticSettings{}, TendencySettings{});
  for (const double steer : {1.0, 0.5}) {
    const TendencyResult pointed = PointTheBitTendency(input, PointTheBitAt(0.0, 0.0, steer));
    std::printf("[ measure  ] offset 0, steer %g: %.12f deg/100 ft build, %.3e right (own %.12f, %.3e)\n", steer,
                pointed.build_rate / kDegreesPer100Ft, pointed.curvature.right / kDegreesPer100Ft,
                own.build_rate / kDegreesPer100Ft, own.curvature.right / kDegreesPer100Ft);
    EXPECT_NEAR(pointed.build_rate, own.build_rate, 1e-9 * std::abs(own.build_rate));
    EXPECT_NEAR(pointed.curvature.right, own.curvature.right, 1e-9 * std::abs(own.build_rate));
  }
}

// The bend held at its toolface: at 0 it builds above the BHA's own tendency, at 180 it drops below it by
// as much (measured 2.874 and 2.834°/100 ft), at 90 and 270 it turns right and left by as much as each
// other with the build the BHA's own. The string's weight, which holds it on the low side, breaks the
// symmetry between steering up and sideways: 90 turns 2.677°/100 ft, 6.9 % less than 0 builds.
TEST(Tendency, PointTheBitSteersTowardItsToolface) {
  const model::ModelInput input = PackedBha();
  const double own = RunTendency(input, Factory(), StaticSettings{}, TendencySettings{}).build_rate;
  HoleCurvature at[4];
  for (int k = 0; k < 4; ++k) at[k] = PointTheBitTendency(input, PointTheBitAt(0.5, 90.0 * k, 1.0)).curvature;
  const double up = at[0].build - own, down = own - at[2].build;
  std::printf("[ measure  ] own %+.4f deg/100 ft; toolface 0: %+.4f build, %+.4f right; 90: %+.4f, %+.4f; 180: %+.4f, "
              "%+.4f; 270: %+.4f, %+.4f\n",
              own / kDegreesPer100Ft, at[0].build / kDegreesPer100Ft, at[0].right / kDegreesPer100Ft,
              at[1].build / kDegreesPer100Ft, at[1].right / kDegreesPer100Ft, at[2].build / kDegreesPer100Ft,
              at[2].right / kDegreesPer100Ft, at[3].build / kDegreesPer100Ft, at[3].right / kDegreesPer100Ft);
  EXPECT_GT(up, 1.0 * kDegreesPer100Ft);
  EXPECT_NEAR(down, up, 0.02 * up);                   // 180 drops as much as 0 builds
  EXPECT_NEAR(at[0].right, 0.0, 1e-3 * up);          // a plane well: no walk at the high side or the low
  EXPECT_NEAR(at[2].right, 0.0, 1e-3 * up);
  EXPECT_NEAR(at[1].right, up, 0.1 * up);             // 90 turns right
  EXPECT_NEAR(at[3].right, -at[1].right, 1e-3 * up);  // 270 turns left by as much (the plane's mirror)
  EXPECT_NEAR(at[1].build, at[3].build, 1e-3 * up);
  EXPECT_NEAR(at[1].build, own, 0.05 * up);
}

// The duty cycle: the steady curvature at steer 0.5 is where the time-average of the bit's deviation,
// half the time neutral (the case's string) and half the time steering (the string bent at the fulcrum
// by hand: the bend of a bent housing on the stabilizer), vanishes: statics in holes drawn at that
// build ∓ 0.01°/100 ft bracket it.
TEST(Tendency, PointTheBitDutyCycleIsTheTimeAverageOfTheDeviation) {
  const model::ModelInput input = PackedBha();
  const TendencyResult half = PointTheBitTendency(input, PointTheBitAt(0.5, 0.0, 0.5));
  const double natural = RunTendency(input, Factory(), StaticSettings{}, TendencySettings{}).build_rate;
  const double full = PointTheBitTendency(input, PointTheBitAt(0.5, 0.0, 1.0)).build_rate;
  model::ModelInput bent = input;
  bent.string.components[1].bend_angle = 0.5 * kDegree;
  bent.string.components[1].bend_to_bit = 2.5 * kFt;
  bent.string.components[1].toolface = 0.0;
  const double per_force = kDefaultSteerability / input.operation.weight_on_bit;
  const auto criterion = [&](double build) {
    const BitReport neutral = BitIn(InBuildingHole(input, build));
    const BitReport steering = BitIn(InBuildingHole(bent, build));
    return 0.5 * (neutral.tilt + per_force * neutral.build_force) + 0.5 * (steering.tilt + per_force * steering.build_force);
  };
  const double below = criterion(half.build_rate - 0.01 * kDegreesPer100Ft);
  const double above = criterion(half.build_rate + 0.01 * kDegreesPer100Ft);
  std::printf("[ measure  ] natural %.4f, full %.4f, at 50 %% %.4f deg/100 ft (the mean of natural and full %.4f); "
              "mean deviation at -0.01: %.3e, at +0.01: %.3e rad\n",
              natural / kDegreesPer100Ft, full / kDegreesPer100Ft, half.build_rate / kDegreesPer100Ft,
              0.5 * (natural + full) / kDegreesPer100Ft, below, above);
  EXPECT_LT(below * above, 0.0);
  // Close to linear in the steer, not exactly (the deviation is not linear in the curvature: the contacts
  // move): measured 1.8763°/100 ft against the mean of natural and full, 1.8065, 2.4 % of their span.
  EXPECT_NEAR(half.build_rate, 0.5 * (natural + full), 0.05 * (full - natural));
}

// The housing holds the toolface in space: with 5000 ft·lbf on the bit the string twists at the
// fulcrum, and the bend is set against the twist, so the steering turns the hole as without the torque.
TEST(Tendency, PointTheBitHoldsItsToolfaceAgainstTheTwist) {
  model::ModelInput input = PackedBha();
  const HoleCurvature calm = PointTheBitTendency(input, PointTheBitAt(0.5, 90.0, 1.0)).curvature;
  input.operation.torque_on_bit = 5000.0 * kLbf * kFt;
  const TendencyResult twisted = PointTheBitTendency(input, PointTheBitAt(0.5, 90.0, 1.0));
  const double twist = TwistAt(twisted.equilibrium, 2.5 * kFt);
  std::printf("[ measure  ] toolface 90, no torque: %+.4f build, %+.4f right deg/100 ft; 5000 ft*lbf: %+.4f, %+.4f "
              "(twist at the fulcrum %.3f deg, %d statics)\n",
              calm.build / kDegreesPer100Ft, calm.right / kDegreesPer100Ft, twisted.curvature.build / kDegreesPer100Ft,
              twisted.curvature.right / kDegreesPer100Ft, twist / kDegree, twisted.statics);
  EXPECT_GT(std::abs(twist), 1.0 * kDegree);  // the twist the bend is set against is not nothing
  EXPECT_NEAR(twisted.curvature.right, calm.right, 0.02 * std::abs(calm.right));
  EXPECT_NEAR(twisted.curvature.build, calm.build, 0.02 * std::abs(calm.right));
}

// In a string turning at 120 rpm (the wall's friction rolling it to the right): the search settles, the
// bend at the high side builds above the rotating BHA's own tendency and at the right turns it right.
TEST(Tendency, PointTheBitSteersInARotatingString) {
  model::ModelInput input = PackedBha();
  input.operation.rotary_speed = 120.0 * kPi / 30.0;
  input.operation.torque_on_bit = 5000.0 * kLbf * kFt;
  input.static_sliding = model::PrescribedSliding{0.0, input.operation.rotary_speed};
  const HoleCurvature own = RunTendency(input, Factory(), StaticSettings{}, TendencySettings{}).curvature;
  const TendencyResult high = PointTheBitTendency(input, PointTheBitAt(0.5, 0.0, 1.0));
  const TendencyResult right = PointTheBitTendency(input, PointTheBitAt(0.5, 90.0, 1.0));
  std::printf("[ measure  ] rotating: own %+.4f build, %+.4f right; toolface 0: %+.4f, %+.4f (%d statics); 90: %+.4f, "
              "%+.4f (%d statics) deg/100 ft\n",
              own.build / kDegreesPer100Ft, own.right / kDegreesPer100Ft, high.curvature.build / kDegreesPer100Ft,
              high.curvature.right / kDegreesPer100Ft, high.statics, right.curvature.build / kDegreesPer100Ft,
              right.curvature.right / kDegreesPer100Ft, right.statics);
  EXPECT_GT(high.curvature.build, own.build + 1.0 * kDegreesPer100Ft);
  EXPECT_GT(right.curvature.right, own.right + 1.0 * kDegreesPer100Ft);
}

// What every directional driller knows (issue 34's qualitative checks), at 30°, 8-1/2 in hole, S 0.05:
// a near-bit stabilizer (a fulcrum) builds, a pendulum (the first stabilizer 45 ft up) drops, a second
// stabilizer 30 ft above the near-bit one damps the fulcrum's build, more WOB lessens the pendulum's drop.
model::ModelInput Assembly(const std::vector<double>& stabilizers_ft, double wob_klbf) {
  model::ModelInput input = PackedBha();
  input.well = model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{
                                       {0.0, 30.0 * kDegree, kAzimuth}, {4000.0 * kFt, 30.0 * kDegree, kAzimuth}}),
                                   input.well->hole.sections());
  input.operation.weight_on_bit = wob_klbf * 1000.0 * kLbf;
  model::Component stabilizer = Part(model::ComponentType::Stabilizer, 6.75, 2.8125, 4.0);
  stabilizer.blade_diameter = 8.4375 * kIn;
  stabilizer.blade_length = 1.0 * kFt;
  input.string.components = {Part(model::ComponentType::Bit, 8.5, 2.0, 1.0)};
  double top = 1.0;  // ft
  for (const double at : stabilizers_ft) {  // blades' middle at `at`
    if (at - 2.0 > top) input.string.components.push_back(Part(model::ComponentType::Collar, 6.75, 2.8125, at - 2.0 - top));
    input.string.components.push_back(stabilizer);
    top = at + 2.0;
  }
  input.string.components.push_back(Part(model::ComponentType::Collar, 6.75, 2.8125, 120.0 - top));
  return input;
}

double SteadyBuild(const model::ModelInput& input) {
  return RunTendency(input, Factory(), StaticSettings{}, TendencySettings{}).build_rate / kDegreesPer100Ft;
}

TEST(Tendency, FulcrumBuildsPendulumDropsSecondStabilizerDampsWobLessensTheDrop) {
  const double fulcrum = SteadyBuild(Assembly({3.0}, 25.0));
  const double packed = SteadyBuild(Assembly({3.0, 33.0}, 25.0));
  const double pendulum = SteadyBuild(Assembly({45.0}, 15.0));
  const double pendulum_heavy = SteadyBuild(Assembly({45.0}, 35.0));
  std::printf("[ measure  ] fulcrum %+.3f deg/100 ft, with a second stabilizer at 33 ft %+.3f; pendulum (45 ft) "
              "%+.3f at 15 klbf, %+.3f at 35 klbf\n",
              fulcrum, packed, pendulum, pendulum_heavy);
  EXPECT_GT(fulcrum, 0.0);
  EXPECT_LT(pendulum, 0.0);
  EXPECT_LT(packed, fulcrum);
  EXPECT_GT(pendulum_heavy, pendulum);
}

// The formation's term: flat beds turn a hole at inclination I toward the vertical by h sin 2I (the
// small-h form of the orthotropic drillability); beds normal to the hole, or parallel to it, not at all.
TEST(Tendency, FormationTurnsTheHoleTowardTheBeddingsNormal) {
  const double h = 0.01;
  const well::PathFrame bit = PackedBha().well->trajectory.Frame(kBitMd);  // 40° toward the east
  const HoleCurvature flat = FormationDeviation({h, 0.0, 0.0}, bit);
  EXPECT_NEAR(flat.build, -h * std::sin(2.0 * kInclination), 1e-15);
  EXPECT_NEAR(flat.right, 0.0, 1e-15);
  // Beds dipping 40° toward the west: their normal is the hole's direction.
  const HoleCurvature normal = FormationDeviation({h, kInclination, 270.0 * kDegree}, bit);
  EXPECT_NEAR(std::hypot(normal.build, normal.right), 0.0, 1e-15);
  // With S 0.25 the steady curvature is where tilt + S F / WOB = h sin 2I: a static in a hole drawn at it
  // ∓ 0.01°/100 ft brackets that.
  TendencySettings settings;
  settings.steerability = 0.25;
  settings.formation = FormationSettings{h, 0.0, 0.0};
  const model::ModelInput input = PackedBha();
  const TendencyResult result = RunTendency(input, Factory(), StaticSettings{}, settings);
  const auto criterion = [&](double build) {
    const BitReport report = BitIn(InBuildingHole(input, build));
    return report.tilt + 0.25 * report.build_force / input.operation.weight_on_bit - h * std::sin(2.0 * kInclination);
  };
  const double below = criterion(result.build_rate - 0.01 * kDegreesPer100Ft);
  const double above = criterion(result.build_rate + 0.01 * kDegreesPer100Ft);
  std::printf("[ measure  ] h %.2f, flat beds: steady %.4f deg/100 ft; criterion at -0.01: %.3e, at +0.01: %.3e\n", h,
              result.build_rate / kDegreesPer100Ft, below, above);
  EXPECT_LT(below * above, 0.0);
}

TEST(Tendency, RefusesAStringItCannotTake) {
  model::ModelInput input = PackedBha();
  input.operation.weight_on_bit = 0.0;
  ASSERT_TRUE(TendencyInputProblem(input).has_value());
  EXPECT_EQ(TendencyInputProblem(input)->first, "operation.wob");
  EXPECT_THROW(RunTendency(input, Factory(), StaticSettings{}, TendencySettings{}), InputError);
  input = PackedBha();
  input.string.components.front().type = model::ComponentType::Collar;
  EXPECT_EQ(TendencyInputProblem(input)->first, "string");
  input = PackedBha();
  input.well.reset();
  EXPECT_EQ(TendencyInputProblem(input)->first, "well");
  EXPECT_FALSE(TendencyInputProblem(PackedBha()).has_value());
  // A point-the-bit system's fulcrum inside the bit, above the string's top, or on a bent motor.
  input = PackedBha();
  EXPECT_FALSE(PointTheBitProblem(input, PointTheBitAt(0.5, 0.0, 1.0)).has_value());
  RssSettings rss = PointTheBitAt(0.5, 0.0, 1.0);
  rss.at = 0.5 * kFt;
  ASSERT_TRUE(PointTheBitProblem(input, rss).has_value());
  EXPECT_EQ(PointTheBitProblem(input, rss)->first, "analyses.tendency.rss.at");
  TendencySettings settings;
  settings.rss = rss;
  EXPECT_THROW(RunTendency(input, Factory(), StaticSettings{}, settings), InputError);
  rss.at = 1000.0 * kFt;
  EXPECT_TRUE(PointTheBitProblem(input, rss).has_value());
  input.string.components[1].bend_angle = 1.0 * kDegree;
  input.string.components[1].bend_to_bit = 3.0 * kFt;
  EXPECT_TRUE(PointTheBitProblem(input, PointTheBitAt(0.5, 0.0, 1.0)).has_value());
}

}  // namespace tendency_test
}  // namespace drillflex::analyses
