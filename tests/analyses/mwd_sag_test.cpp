// The MWD's sag (analyses/mwd_sag.hpp) against a continuous beam solved here: a uniform collar in a
// horizontal hole (no axial force: no WOB, no weight along the hole), held at the bit (pinned: its
// tilt is free), on two full-gauge stabilizers (zero clearance: pins on the hole's axis), its top free.
// EI v'''' = w on each span, v the deflection toward the low side, x up the hole from the bit; the
// sensor's axis against the hole's is v'(x) (down-hole, a string falling toward the low side as it goes
// up the hole points its axis to the high side: the sensor reads the inclination higher).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "analyses/static_analysis.hpp"
#include "cms/reduction_cache.hpp"
#include "fe/material.hpp"
#include "field_parts.hpp"

namespace drillflex::analyses {
namespace mwd_sag_test {

using testing::kFt;
using testing::kIn;
using testing::Part;

// A 35 ft span: its largest deflection (0.34 in) stays inside the 1 in clearance of the 6.5 in collar.
constexpr double kStab1 = 5.0 * kFt, kStab2 = 40.0 * kFt, kTop = 48.0 * kFt;

// The slope v' at x of the beam above (pins at 0, kStab1, kStab2; free end at kTop) under w (N/m).
double BeamSlope(double w, double ei, double x) {
  // Three spans, v_i(ξ) = w ξ⁴/(24 EI) + c3 ξ³ + c2 ξ² + c1 ξ + c0, ξ from the span's start.
  const double length[3] = {kStab1, kStab2 - kStab1, kTop - kStab2};
  Eigen::Matrix<double, 12, 12> a = Eigen::Matrix<double, 12, 12>::Zero();
  Eigen::Matrix<double, 12, 1> b = Eigen::Matrix<double, 12, 1>::Zero();
  const double q = w / ei;
  // Rows of v, v', v'', v''' of span i at ξ (coefficients c0..c3) and their load parts.
  const auto row = [&](int derivative, double xi) {
    Eigen::Matrix<double, 1, 4> r;
    switch (derivative) {
      case 0: r << 1, xi, xi * xi, xi * xi * xi; break;
      case 1: r << 0, 1, 2 * xi, 3 * xi * xi; break;
      case 2: r << 0, 0, 2, 6 * xi; break;
      default: r << 0, 0, 0, 6; break;
    }
    return r;
  };
  const auto load = [&](int derivative, double xi) {
    switch (derivative) {
      case 0: return q * std::pow(xi, 4) / 24.0;
      case 1: return q * std::pow(xi, 3) / 6.0;
      case 2: return q * xi * xi / 2.0;
      default: return q * xi;
    }
  };
  int n = 0;
  const auto set = [&](int span, int derivative, double xi, double value) {  // v_span^(d)(ξ) = value
    a.block<1, 4>(n, 4 * span) = row(derivative, xi);
    b[n++] = value - load(derivative, xi);
  };
  const auto equal = [&](int span, int derivative) {  // v_span^(d)(L) = v_{span+1}^(d)(0)
    a.block<1, 4>(n, 4 * span) = row(derivative, length[span]);
    a.block<1, 4>(n, 4 * span + 4) = -row(derivative, 0.0);
    b[n++] = load(derivative, 0.0) - load(derivative, length[span]);
  };
  set(0, 0, 0.0, 0.0);
  set(0, 2, 0.0, 0.0);
  set(0, 0, length[0], 0.0);
  set(1, 0, 0.0, 0.0);
  set(1, 0, length[1], 0.0);
  set(2, 0, 0.0, 0.0);
  equal(0, 1);
  equal(0, 2);
  equal(1, 1);
  equal(1, 2);
  set(2, 2, length[2], 0.0);
  set(2, 3, length[2], 0.0);
  const Eigen::Matrix<double, 12, 1> c = a.fullPivLu().solve(b);
  const int span = x < kStab1 ? 0 : x < kStab2 ? 1 : 2;
  const double xi = x - (span == 0 ? 0.0 : span == 1 ? kStab1 : kStab2);
  return row(1, xi).dot(c.segment<4>(4 * span)) + load(1, xi);
}

TEST(MwdSag, IsTheSlopeOfTheCollarBetweenItsStabilizers) {
  const double od = 6.5, id = 2.8125;
  model::ModelInput input;
  model::Component stabilizer = Part(model::ComponentType::Stabilizer, od, id, 2.0);
  stabilizer.blade_diameter = 8.5 * kIn;  // full gauge
  stabilizer.blade_length = 0.2 * kFt;
  input.string.components = {Part(model::ComponentType::Bit, od, id, 4.0), stabilizer,
                             Part(model::ComponentType::Collar, od, id, 33.0), stabilizer,
                             Part(model::ComponentType::Collar, od, id, 7.0)};
  const fe::Material steel{"steel", 2.1e11, 0.3, 7850.0};
  input.materials["steel"] = steel;
  input.gravity = 9.81;
  input.settings.top = model::TopCondition::Free;
  input.settings.contact.stiffness = 1e12;  // a pin on the axis: 6e10 N/m a blade, 2e-7 m under 13 kN
  input.well = model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{
                                       {0.0, 90.0 * kDegree, 0.0}, {4000.0 * kFt, 90.0 * kDegree, 0.0}}),
                                   std::vector<well::HoleSection>{well::HoleSection{{}, 8.5 * kIn, {}}});
  input.bit_md = 3000.0 * kFt;
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const double area = 0.25 * kPi * (std::pow(od * kIn, 2) - std::pow(id * kIn, 2));
  const double ei = steel.youngs_modulus * kPi / 64.0 * (std::pow(od * kIn, 4) - std::pow(id * kIn, 4));
  const double w = steel.density * area * input.gravity;
  for (const double at_ft : {12.0, 22.5, 33.0}) {
    StaticSettings settings;
    settings.mwd_at = at_ft * kFt;
    const StaticResult result = RunStaticInWell(input, built, settings);
    ASSERT_TRUE(result.mwd.has_value());
    const double beam = BeamSlope(w, ei, result.mwd->s);
    std::printf("[ measure  ] sensor at %.2f ft: sag %.6e rad, continuous beam %.6e rad (%+.3f %%)\n",
                result.mwd->s / kFt, result.mwd->sag, beam, 100.0 * (result.mwd->sag / beam - 1.0));
    EXPECT_NEAR(result.mwd->sag, beam, 0.01 * std::abs(beam) + 1e-7);
  }
}

}  // namespace mwd_sag_test
}  // namespace drillflex::analyses
