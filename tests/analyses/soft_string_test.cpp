// The soft-string torque and drag (Johancsik, Friesen & Dawson, SPE 11380) against independent
// references: the buoyed weight in a vertical hole, the closed form of a straight inclined hole, a hand
// computation of Johancsik's formulas from the survey table of a 3-D well, the refinement of the
// survey on the same minimum-curvature path, the capstan law e^{μθ} of a weightless bend, the normal
// force against the vector form of the lateral load (the sign convention), and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analyses/soft_string.hpp"
#include "core/error.hpp"
#include "field_parts.hpp"

namespace drillflex::analyses {
namespace soft_string_test {

using testing::kFt;
using testing::kIn;
using testing::kLbf;
using testing::Part;

constexpr double kSteelDensity = 7850.0;  // kg/m³
constexpr double kMudDensity = 1198.26;   // kg/m³, 10 ppg
constexpr double kGravity = 9.81;         // m/s²
constexpr double kJointFraction = 0.4572 / 9.144;  // 18 in of tool joint per 30 ft joint (the defaults)

// By hand: w = g (ρ_s A_m − ρ_f A_o + ρ_f A_i) with the same mud inside and out = g (ρ_s − ρ_f) A_m,
// A_m the metal area with the tool joints smeared over their spacing (a fraction f of the length).
double HandWeightPerLength(double od_in, double id_in, double joint_od_in = 0.0, double joint_id_in = 0.0,
                           double joint_fraction = 0.0) {
  const double body = kPi / 4.0 * (od_in * od_in - id_in * id_in) * kIn * kIn;
  const double joint = kPi / 4.0 * (joint_od_in * joint_od_in - joint_id_in * joint_id_in) * kIn * kIn;
  const double metal = (1.0 - joint_fraction) * body + joint_fraction * joint;
  return kGravity * (kSteelDensity - kMudDensity) * metal;
}

// 6-1/2 in × 2-13/16 in collars (30 ft) and 5 in 19.5 lb/ft drill pipe (4.276 in bore, 30 ft joints)
// with 6-5/8 in × 3-1/4 in tool joints.
model::Component Collars(int count) { return Part(model::ComponentType::Collar, 6.5, 2.8125, 30.0, count); }
double CollarWeight() { return HandWeightPerLength(6.5, 2.8125); }
model::Component Pipe(int count) {
  model::Component pipe = Part(model::ComponentType::Pipe, 5.0, 4.276, 30.0, count);
  pipe.joint_diameter = 6.625 * kIn;
  pipe.joint_inner_diameter = 3.25 * kIn;
  return pipe;
}
double PipeWeight() { return HandWeightPerLength(5.0, 4.276, 6.625, 3.25, kJointFraction); }

// A string of `components` in mud in a well of `survey` (SI), bit at `bit_md`.
model::ModelInput InWell(std::vector<model::Component> components, std::vector<well::SurveyStation> survey,
                         double bit_md) {
  model::ModelInput input;
  input.string.components = std::move(components);
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, kSteelDensity};
  input.gravity = kGravity;
  input.fluid = model::FluidConfig{kMudDensity, 0.02, {}, -1.0};
  input.well = model::MakeWellbore(well::Trajectory(std::move(survey)));
  input.bit_md = bit_md;
  return input;
}

SoftStringOperation Operation(SoftStringMotion motion, double axial, double tangential, double wob = 0.0,
                              double tob = 0.0) {
  SoftStringOperation operation;
  operation.motion = motion;
  operation.axial_friction = axial;
  operation.tangential_friction = tangential;
  operation.weight_on_bit = wob;
  operation.torque_on_bit = tob;
  return operation;
}

double Relative(double value, double reference) { return std::abs(value / reference - 1.0); }

// 1. Vertical: no wall force, the hook load is the buoyed weight less the WOB whatever the friction,
// the torque the TOB.
TEST(SoftString, VerticalHoleHookLoadIsTheBuoyedWeight) {
  const double bit_md = 2500.0;
  const model::ModelInput input =
      InWell({Collars(20), Pipe(50)}, {{0.0, 0.0, 0.0}, {1000.0, 0.0, 0.0}, {3000.0, 0.0, 0.0}}, bit_md);
  const double collar_length = 20 * 30.0 * kFt;  // the pipe continued to the surface
  const double weight = CollarWeight() * collar_length + PipeWeight() * (bit_md - collar_length);
  double worst = 0.0;
  for (SoftStringMotion motion : {SoftStringMotion::PickUp, SoftStringMotion::SlackOff, SoftStringMotion::Rotating}) {
    const SoftStringResult off = ComputeSoftString(input, Operation(motion, 0.3, 0.3));
    const SoftStringResult on = ComputeSoftString(input, Operation(motion, 0.3, 0.3, 1.0e5, 12000.0));
    EXPECT_NEAR(off.hook_load, weight, 1e-12 * weight);
    EXPECT_NEAR(on.hook_load, weight - 1.0e5, 1e-12 * weight);
    EXPECT_EQ(off.surface_torque, 0.0);
    EXPECT_NEAR(on.surface_torque, 12000.0, 1e-12 * 12000.0);
    for (const SoftStringStation& station : on.stations) EXPECT_EQ(station.normal_force, 0.0);
    worst = std::max({worst, Relative(off.hook_load, weight), Relative(on.hook_load, weight - 1.0e5)});
  }
  std::printf("[ measure  ] vertical: hook load %.6f N, buoyed weight %.6f N, worst relative error %.2e\n",
              ComputeSoftString(input, Operation(SoftStringMotion::PickUp, 0.3, 0.3)).hook_load, weight, worst);
}

// A string longer than the hole: the part above the surface is left out.
TEST(SoftString, StringAboveTheSurfaceIsLeftOut) {
  const model::ModelInput input = InWell({Collars(20)}, {{0.0, 0.0, 0.0}, {500.0, 0.0, 0.0}}, 100.0);
  const SoftStringResult result = ComputeSoftString(input, Operation(SoftStringMotion::PickUp, 0.3, 0.3));
  EXPECT_NEAR(result.hook_load, CollarWeight() * 100.0, 1e-12 * CollarWeight() * 100.0);
  EXPECT_EQ(result.stations.back().md, 0.0);
  EXPECT_EQ(result.stations.back().s, 100.0);
}

// 2. Straight inclined hole at 40°: 20 collars and 50 joints of pipe, the bit at 3000 m (the pipe
// continued to the surface); each part's buoyed weight along the hole, N.
struct StraightInclinedWell {
  double inclination = 40.0 * kDegree;
  model::ModelInput input = InWell({Collars(20), Pipe(50)},
                                   {{0.0, 40.0 * kDegree, 130.0 * kDegree}, {4000.0, 40.0 * kDegree, 130.0 * kDegree}},
                                   3000.0);
  double collar_weight = CollarWeight() * 20 * 30.0 * kFt;
  double pipe_weight = PipeWeight() * (3000.0 - 20 * 30.0 * kFt);
  double weight = collar_weight + pipe_weight;
  // Σ μ_t W_k r_k sin I: the friction torque with N = W sin I (collars r 3.25 in, joints 6.625/2 in).
  double FrictionTorque(double mu_t) const {
    return mu_t * std::sin(inclination) * (collar_weight * 3.25 * kIn + pipe_weight * 6.625 / 2.0 * kIn);
  }
};

// N = W sin I on every element, so F = −WOB + ΣW cos I ± μ ΣW sin I and M = TOB + μ_t Σ W_k r_k sin I,
// exactly.
TEST(SoftString, StraightInclinedHoleMatchesTheClosedForm) {
  const StraightInclinedWell well;
  const model::ModelInput& input = well.input;
  const double inclination = well.inclination, weight = well.weight;
  const double wob = 50000.0, tob = 5000.0, mu_a = 0.3, mu_t = 0.2;
  const double along = weight * std::cos(inclination), across = weight * std::sin(inclination);
  const double torque = tob + well.FrictionTorque(mu_t);
  const auto run = [&](SoftStringMotion motion) {
    return ComputeSoftString(input, Operation(motion, mu_a, mu_t, wob, tob));
  };
  const SoftStringResult pick_up = run(SoftStringMotion::PickUp);
  const SoftStringResult slack_off = run(SoftStringMotion::SlackOff);
  const SoftStringResult rotating = run(SoftStringMotion::Rotating);
  EXPECT_NEAR(pick_up.hook_load, -wob + along + mu_a * across, 1e-12 * weight);
  EXPECT_NEAR(slack_off.hook_load, -wob + along - mu_a * across, 1e-12 * weight);
  EXPECT_NEAR(rotating.hook_load, -wob + along, 1e-12 * weight);
  EXPECT_NEAR(rotating.surface_torque, torque, 1e-12 * torque);
  EXPECT_NEAR(pick_up.surface_torque, tob, 1e-12 * tob);  // sliding: no friction torque
  EXPECT_NEAR(slack_off.surface_torque, tob, 1e-12 * tob);
  std::printf("[ measure  ] straight 40 deg: pick-up %.3e, slack-off %.3e, rotating %.3e, torque %.3e relative\n",
              Relative(pick_up.hook_load, -wob + along + mu_a * across),
              Relative(slack_off.hook_load, -wob + along - mu_a * across), Relative(rotating.hook_load, -wob + along),
              Relative(rotating.surface_torque, torque));
}

// 2b. The rotating string's climb (wall_climb): the wall's normal force and its friction together carry
// the lateral load W sin I, N √(1 + μ_t²) = W sin I, so the friction torque is Johancsik's divided by
// √(1 + μ_t²); the axial force and the sliding runs do not change.
TEST(SoftString, TheClimbDividesTheRotatingTorqueBySqrtOnePlusMuSquared) {
  const StraightInclinedWell well;
  const double wob = 50000.0, tob = 5000.0, mu_a = 0.3, mu_t = 0.2;
  SoftStringOperation rotating = Operation(SoftStringMotion::Rotating, mu_a, mu_t, wob, tob);
  rotating.wall_climb = true;
  const SoftStringResult climbing = ComputeSoftString(well.input, rotating);
  const double torque = tob + well.FrictionTorque(mu_t) / std::sqrt(1.0 + mu_t * mu_t);
  EXPECT_NEAR(climbing.surface_torque, torque, 1e-12 * torque);
  EXPECT_NEAR(climbing.hook_load, -wob + well.weight * std::cos(well.inclination), 1e-12 * well.weight);
  SoftStringOperation pick_up = Operation(SoftStringMotion::PickUp, mu_a, mu_t, wob, tob);
  pick_up.wall_climb = true;
  EXPECT_NEAR(ComputeSoftString(well.input, pick_up).hook_load,
              -wob + well.weight * (std::cos(well.inclination) + mu_a * std::sin(well.inclination)),
              1e-12 * well.weight);
}

// 3. A 3-D well: vertical to a kick-off at 1500 ft (surveyed with azimuth 0), 3°/100 ft build turning
// 1.5°/100 ft right from 41.5° to 30° at 55° at 2500 ft, held to 3500 ft; bit at 3200 ft under
// 25 × 30.5 ft of collars (their top at 2437.5 ft, inside the last build arc) and 60 joints of drill
// pipe continued to the surface (its top at 637.5 ft).
struct SurveyRow {
  double md_ft, inclination_deg, azimuth_deg;
};
const std::vector<SurveyRow> kBuildAndTurn = {
    {0.0, 0.0, 0.0},       {1500.0, 0.0, 0.0},    {1600.0, 3.0, 41.5},   {1700.0, 6.0, 43.0},
    {1800.0, 9.0, 44.5},   {1900.0, 12.0, 46.0},  {2000.0, 15.0, 47.5},  {2100.0, 18.0, 49.0},
    {2200.0, 21.0, 50.5},  {2300.0, 24.0, 52.0},  {2400.0, 27.0, 53.5},  {2500.0, 30.0, 55.0},
    {3500.0, 30.0, 55.0}};
constexpr double kBitMdFt = 3200.0, kCollarTopFt = 2437.5;

model::ModelInput BuildAndTurnWell(const std::vector<SurveyRow>& rows) {
  std::vector<well::SurveyStation> survey;
  for (const SurveyRow& row : rows) {
    survey.push_back({row.md_ft * kFt, row.inclination_deg * kDegree, row.azimuth_deg * kDegree});
  }
  model::Component collars = Collars(25);
  collars.length = 30.5 * kFt;
  return InWell({collars, Pipe(60)}, std::move(survey), kBitMdFt * kFt);
}

struct HandAngles {
  double inclination = 0.0, azimuth = 0.0;  // rad
};

// Inclination and azimuth at an MD (ft) from the survey table: the table's at a station; between two,
// on the minimum-curvature arc, the tangent t = (sin((1 − f)β) t₁ + sin(fβ) t₂) / sin β (the great
// circle from t₁ to t₂, β = acos t₁·t₂, f the fraction of the interval's MD).
HandAngles HandAnglesAt(double md_ft) {
  for (std::size_t i = 0; i + 1 < kBuildAndTurn.size(); ++i) {
    const SurveyRow& a = kBuildAndTurn[i];
    const SurveyRow& b = kBuildAndTurn[i + 1];
    if (md_ft == a.md_ft) return {a.inclination_deg * kDegree, a.azimuth_deg * kDegree};
    if (md_ft > b.md_ft) continue;
    const auto tangent = [](const SurveyRow& row) {
      const double i = row.inclination_deg * kDegree, az = row.azimuth_deg * kDegree;
      return Vec3(std::sin(i) * std::cos(az), std::sin(i) * std::sin(az), std::cos(i));
    };
    const Vec3 t1 = tangent(a), t2 = tangent(b);
    const double beta = std::acos(std::clamp(t1.dot(t2), -1.0, 1.0));
    const double f = (md_ft - a.md_ft) / (b.md_ft - a.md_ft);
    const Vec3 t =
        beta < 1e-12 ? t1 : Vec3((std::sin((1.0 - f) * beta) * t1 + std::sin(f * beta) * t2) / std::sin(beta));
    double azimuth = std::atan2(t.y(), t.x());
    if (azimuth < 0.0) azimuth += 2.0 * kPi;
    return {std::acos(std::clamp(t.z(), -1.0, 1.0)), azimuth};
  }
  return {kBuildAndTurn.back().inclination_deg * kDegree, kBuildAndTurn.back().azimuth_deg * kDegree};
}

// The element ends by hand: the bit, the survey stations above it, the collars' and the pipe's tops.
const std::vector<double> kHandCutsFt = {3200.0, 2500.0, 2437.5, 2400.0, 2300.0, 2200.0, 2100.0, 2000.0,
                                         1900.0, 1800.0, 1700.0, 1600.0, 1500.0, 637.5,  0.0};

struct HandResult {
  double hook_load = 0.0, torque = 0.0;
};

// Johancsik's table by hand, from the bit up: per element N = √((T ΔA sin Ī)² + (T ΔI + W sin Ī)²),
// ΔI, ΔA upper minus lower end; T += W cos Ī ± μ_a N; M += μ_t N r rotating. A vertical end (the
// kick-off) takes the azimuth of the element's other end, the plane of the arc leaving it.
HandResult HandJohancsik(SoftStringMotion motion, double mu_a, double mu_t, double wob, double tob) {
  double tension = -wob, torque = tob;
  for (std::size_t k = 1; k < kHandCutsFt.size(); ++k) {
    HandAngles lower = HandAnglesAt(kHandCutsFt[k - 1]), upper = HandAnglesAt(kHandCutsFt[k]);
    if (lower.inclination == 0.0) lower.azimuth = upper.azimuth;
    if (upper.inclination == 0.0) upper.azimuth = lower.azimuth;
    const bool collar = 0.5 * (kHandCutsFt[k - 1] + kHandCutsFt[k]) > kCollarTopFt;
    const double w = collar ? CollarWeight() : PipeWeight();
    const double r = (collar ? 6.5 : 6.625) / 2.0 * kIn;
    const double big_w = w * (kHandCutsFt[k - 1] - kHandCutsFt[k]) * kFt;
    const double mean = 0.5 * (lower.inclination + upper.inclination);
    const double d_inclination = upper.inclination - lower.inclination;
    double d_azimuth = upper.azimuth - lower.azimuth;
    if (d_azimuth > kPi) d_azimuth -= 2.0 * kPi;
    if (d_azimuth < -kPi) d_azimuth += 2.0 * kPi;
    const double a = tension * d_azimuth * std::sin(mean);
    const double b = tension * d_inclination + big_w * std::sin(mean);
    const double normal = std::sqrt(a * a + b * b);
    const double sign = motion == SoftStringMotion::PickUp ? 1.0 : motion == SoftStringMotion::SlackOff ? -1.0 : 0.0;
    tension += big_w * std::cos(mean) + sign * mu_a * normal;
    if (motion == SoftStringMotion::Rotating) torque += mu_t * normal * r;
  }
  return {tension, torque};
}

TEST(SoftString, BuildAndTurnWellMatchesAHandComputation) {
  const model::ModelInput input = BuildAndTurnWell(kBuildAndTurn);
  const double wob = 25000.0 * kLbf, tob = 8000.0, mu_a = 0.25, mu_t = 0.3;
  struct Run {
    const char* name;
    SoftStringMotion motion;
    double wob, tob;
  };
  const Run runs[] = {{"pick-up", SoftStringMotion::PickUp, 0.0, 0.0},
                      {"slack-off", SoftStringMotion::SlackOff, 0.0, 0.0},
                      {"sliding", SoftStringMotion::SlackOff, wob, tob},
                      {"rotating off bottom", SoftStringMotion::Rotating, 0.0, 0.0},
                      {"rotating on bottom", SoftStringMotion::Rotating, wob, tob}};
  for (const Run& run : runs) {
    const SoftStringResult result = ComputeSoftString(input, Operation(run.motion, mu_a, mu_t, run.wob, run.tob));
    const HandResult hand = HandJohancsik(run.motion, mu_a, mu_t, run.wob, run.tob);
    ASSERT_EQ(result.stations.size(), kHandCutsFt.size());
    for (std::size_t k = 0; k < kHandCutsFt.size(); ++k) {
      EXPECT_NEAR(result.stations[k].md, kHandCutsFt[k] * kFt, 1e-9) << k;
      EXPECT_NEAR(result.stations[k].s, (kBitMdFt - kHandCutsFt[k]) * kFt, 1e-9) << k;
    }
    EXPECT_NEAR(result.hook_load, hand.hook_load, 1e-6 * std::abs(hand.hook_load)) << run.name;
    if (run.motion == SoftStringMotion::Rotating && run.wob == 0.0) {
      EXPECT_NEAR(result.surface_torque, hand.torque, 1e-6 * hand.torque) << run.name;
      EXPECT_GT(hand.torque, 1000.0);  // the bend and the hold carry friction torque
    } else {
      EXPECT_NEAR(result.surface_torque, hand.torque, 1e-6 * std::abs(hand.torque)) << run.name;
    }
    std::printf("[ measure  ] %-20s hook load %.6f N (hand %.6f, %.1e), torque %.6f N m (hand %.6f, %.1e)\n",
                run.name, result.hook_load, hand.hook_load, Relative(result.hook_load, hand.hook_load),
                result.surface_torque, hand.torque,
                hand.torque == 0.0 ? std::abs(result.surface_torque) : Relative(result.surface_torque, hand.torque));
  }
}

// The survey with each interval cut into `parts` by stations on the same minimum-curvature path.
model::ModelInput RefinedBuildAndTurn(int parts) {
  const model::ModelInput coarse = BuildAndTurnWell(kBuildAndTurn);
  const well::Trajectory& path = coarse.well->trajectory;
  std::vector<well::SurveyStation> survey;
  const auto& stations = path.stations();
  for (std::size_t i = 0; i + 1 < stations.size(); ++i) {
    for (int j = 0; j < parts; ++j) {
      const double md = stations[i].md + (stations[i + 1].md - stations[i].md) * j / parts;
      survey.push_back({md, path.Inclination(md), path.Azimuth(md)});
    }
  }
  survey.push_back(stations.back());
  model::ModelInput input = coarse;
  input.well = model::MakeWellbore(well::Trajectory(std::move(survey)), coarse.well->hole.sections());
  return input;
}

// 4. Refinement: the discrete table converges to the soft-string ODE along the same path; the change
// from m to 2m parts an interval shrinks like 1/m (the lower end's tension in each element: first order;
// measured 6.8e-4 … 2.1e-5 for the pick-up from 1 to 64 parts).
TEST(SoftString, RefiningTheSurveyConverges) {
  const double wob = 25000.0 * kLbf, tob = 8000.0;
  const SoftStringOperation pick_up = Operation(SoftStringMotion::PickUp, 0.25, 0.3);
  const SoftStringOperation sliding = Operation(SoftStringMotion::SlackOff, 0.25, 0.3, wob, tob);
  const SoftStringOperation rotating = Operation(SoftStringMotion::Rotating, 0.25, 0.3, wob, tob);
  std::vector<double> pick_ups, slides, torques;
  for (int parts : {1, 2, 4, 8, 16, 32, 64}) {
    const model::ModelInput input = RefinedBuildAndTurn(parts);
    pick_ups.push_back(ComputeSoftString(input, pick_up).hook_load);
    slides.push_back(ComputeSoftString(input, sliding).hook_load);
    torques.push_back(ComputeSoftString(input, rotating).surface_torque);
  }
  for (const std::vector<double>* series : {&pick_ups, &slides, &torques}) {
    const std::vector<double>& v = *series;
    std::printf("[ measure  ] refinement, relative change per doubling:");
    for (std::size_t k = 1; k < v.size(); ++k) {
      const double change = Relative(v[k], v[k - 1]);
      std::printf(" %.2e", change);
      EXPECT_LT(change, 2e-3);
      if (k >= 2) {
        const double previous = Relative(v[k - 1], v[k - 2]);
        EXPECT_LT(change, 0.6 * previous) << k;  // halves with each doubling (first order)
        EXPECT_GT(change, 0.4 * previous) << k;
      }
    }
    std::printf("\n");
    // Halving from here on, the 64-part value is within about its last change (< 1e-4) of the limit.
    EXPECT_LT(Relative(v.back(), v[v.size() - 2]), 1e-4);
  }
}

// A weightless (gravity 0) string in a planar arc of angle θ under a tension T₀ at the bit (a WOB of
// −T₀), on `parts` survey intervals: every element carries N = T θ/parts.
model::ModelInput WeightlessArc(bool turn, double theta, int parts) {
  const double radius = 300.0, length = radius * theta;
  std::vector<well::SurveyStation> survey;
  for (int k = 0; k <= parts; ++k) {
    const double angle = theta * k / parts;
    // In the vertical plane at azimuth 75° from 20° inclination, or horizontal from azimuth 10°.
    survey.push_back(turn ? well::SurveyStation{length * k / parts, 90.0 * kDegree, 10.0 * kDegree + angle}
                          : well::SurveyStation{length * k / parts, 20.0 * kDegree + angle, 75.0 * kDegree});
  }
  model::ModelInput input = InWell({Pipe(1)}, std::move(survey), length);
  input.string.components[0].length = length;  // one component along the arc: no cut but the stations'
  input.gravity = 0.0;
  return input;
}

// 5. Capstan: dT = μ T dθ, T_top/T_bottom = e^{±μθ}; the table gives (1 ± μθ/n)^n, whose relative
// error −(μθ)²/(2n) + O(n⁻²) is the tolerance. Rotating, T stays T₀ and the torque μ_t r T₀ θ is exact.
TEST(SoftString, WeightlessBendFollowsTheCapstanLaw) {
  const double theta = 90.0 * kDegree, mu = 0.3, tension = 2.0e5, x = mu * theta;
  const double radius = 6.625 / 2.0 * kIn;
  for (bool turn : {false, true}) {
    for (int parts : {10, 100, 1000}) {
      const model::ModelInput input = WeightlessArc(turn, theta, parts);
      const double up = ComputeSoftString(input, Operation(SoftStringMotion::PickUp, mu, mu, -tension)).hook_load;
      const double down = ComputeSoftString(input, Operation(SoftStringMotion::SlackOff, mu, mu, -tension)).hook_load;
      const SoftStringResult rotating =
          ComputeSoftString(input, Operation(SoftStringMotion::Rotating, mu, mu, -tension));
      const double up_error = up / tension / std::exp(x) - 1.0;
      const double down_error = down / tension / std::exp(-x) - 1.0;
      const double bound = x * x / (2.0 * parts);
      EXPECT_LE(std::abs(up_error), bound) << parts;
      // (1 − x/n)^n e^x − 1 = −x²/(2n) − x³/(3n²) + …: a little beyond the leading term.
      EXPECT_LE(std::abs(down_error), bound * (1.0 + 2.0 * x / parts)) << parts;
      EXPECT_NEAR(up_error * parts, -x * x / 2.0, 0.03 * x * x / 2.0 * std::max(1.0, 100.0 / parts)) << parts;
      EXPECT_NEAR(down_error * parts, -x * x / 2.0, 0.03 * x * x / 2.0 * std::max(1.0, 100.0 / parts)) << parts;
      EXPECT_NEAR(rotating.hook_load, tension, 1e-12 * tension);
      EXPECT_NEAR(rotating.surface_torque, mu * radius * tension * theta, 1e-12 * mu * radius * tension * theta);
      std::printf("[ measure  ] capstan %s, %4d parts: pick-up %+.3e, slack-off %+.3e (bound %.3e), torque %.1e\n",
                  turn ? "turn" : "build", parts, up_error, down_error, bound,
                  Relative(rotating.surface_torque, mu * radius * tension * theta));
    }
  }
}

// The sign convention: on one short element, N agrees to first order in the angles with the length of
// the lateral load on the wall, |T (t_lower − t_upper) + W ĝ⊥| (t down the hole, ĝ⊥ normal to the mean
// tangent): with T ΔI = W sin Ī / 2 in a build the tension lifts half the weight off the low side (the
// opposite sign would add it). The difference is second order: it drops ~4 times as the angles halve
// (T doubled to keep the balance).
TEST(SoftString, NormalForceAgreesWithTheVectorForm) {
  const double mean_inclination = 35.0 * kDegree, mean_azimuth = 120.0 * kDegree, length = 30.0;
  const auto tangent = [](double i, double a) {
    return Vec3(std::sin(i) * std::cos(a), std::sin(i) * std::sin(a), std::cos(i));
  };
  double previous = 0.0;
  for (double delta : {0.02, 0.01, 0.005, 0.0025}) {
    // Building by δ and turning right by 0.7 δ going down.
    const double upper_i = mean_inclination - delta / 2.0, lower_i = mean_inclination + delta / 2.0;
    const double upper_a = mean_azimuth - 0.35 * delta, lower_a = mean_azimuth + 0.35 * delta;
    model::ModelInput input = InWell({Pipe(1)}, {{0.0, upper_i, upper_a}, {length, lower_i, lower_a}}, length);
    input.string.components[0].length = length;
    const double weight = PipeWeight() * length;
    const double tension = 0.5 * weight * std::sin(mean_inclination) / delta;
    const SoftStringResult result = ComputeSoftString(input, Operation(SoftStringMotion::Rotating, 0.0, 0.0, -tension));
    ASSERT_EQ(result.stations.size(), 2u);
    const double normal = result.stations[1].normal_force;
    const Vec3 t_lower = tangent(lower_i, lower_a), t_upper = tangent(upper_i, upper_a);
    const Vec3 mean_t = (t_lower + t_upper).normalized();
    const Vec3 down = Vec3::UnitZ();
    const Vec3 lateral = tension * (t_lower - t_upper) + weight * (down - down.dot(mean_t) * mean_t);
    const double difference = Relative(normal, lateral.norm());
    // Tension lifts: well below the weight's W sin Ī (1.5 W sin Ī with the opposite sign).
    EXPECT_LT(normal, 0.8 * weight * std::sin(mean_inclination));
    EXPECT_LT(difference, 0.05 * delta);
    if (previous > 0.0) {
      EXPECT_GT(previous / difference, 3.0) << delta;
      EXPECT_LT(previous / difference, 5.0) << delta;
    }
    std::printf("[ measure  ] vector form, angles %.4f rad: N %.3f N, |lateral| %.3f N, relative difference %.3e\n",
                delta, normal, lateral.norm(), difference);
    previous = difference;
  }
}

TEST(SoftString, BadInputThrows) {
  model::ModelInput input = InWell({Collars(2)}, {{0.0, 0.0, 0.0}, {500.0, 0.0, 0.0}}, 100.0);
  const SoftStringOperation rotating = Operation(SoftStringMotion::Rotating, 0.2, 0.2);
  const auto key = [&](const model::ModelInput& in) {
    try {
      ComputeSoftString(in, rotating);
    } catch (const InputError& error) {
      return error.key_path();
    }
    return std::string("(no error)");
  };
  model::ModelInput no_well = input;
  no_well.well.reset();
  EXPECT_EQ(key(no_well), "well");
  model::ModelInput no_string = input;
  no_string.string.components.clear();
  EXPECT_EQ(key(no_string), "string");
  model::ModelInput at_surface = input;
  at_surface.bit_md = 0.0;
  EXPECT_EQ(key(at_surface), "well.bit_md");
  model::ModelInput no_material = input;
  no_material.string.components[0].material = "unobtainium";
  EXPECT_EQ(key(no_material), "string[0].material");
  EXPECT_THROW(ComputeSoftString(input, Operation(SoftStringMotion::PickUp, -0.1, 0.2)), LogicError);
  EXPECT_THROW(ComputeSoftString(input, Operation(SoftStringMotion::Rotating, 0.2, std::nan(""))), LogicError);
  EXPECT_NO_THROW(ComputeSoftString(input, rotating));
}

}  // namespace soft_string_test
}  // namespace drillflex::analyses
