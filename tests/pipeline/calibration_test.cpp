// Calibration (pipeline/calibration.hpp) recovers what made the readings: readings computed by the
// model of the readings itself at known friction factors (cased and open hole), hook-load offset and bit
// torque coefficient, on a 3-D well with casing, plus 1 % Gaussian noise (a fixed seed), are fitted back;
// every parameter lies within its 95 % interval of the truth and the intervals shrink as the readings
// grow (about as 1/√n). And the Student quantile against its table.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "pipeline/calibration.hpp"

namespace drillflex::pipeline {
namespace calibration_test {

// A 3-D well (a build to 40° while turning 30°, then a hold), cased to 700 m MD, open below; 5 in pipe
// on a 6-3/4 in collar section.
io::Case Well() {
  return io::ParseCase(R"(name: calibration
units: SI
well:
  survey: [[0, 0, 0], [300, 0, 0], [800, 40, 30], [1600, 40, 30]]
  hole:
    - {to: 700, diameter: 0.2248, cased: true}
    - {diameter: 0.2159}
  bit_md: 1500
fluid: {density: 1200}
string:
  - {type: bit, od: 0.2159, length: 0.3}
  - {type: collar, od: 0.1715, id: 0.0714, length: 9, count: 6}
  - {type: pipe, od: 0.127, id: 0.1086, length: 9, count: 20}
model: {body_length: 9, elements_per_body: 4, modes_per_body: 4}
operation: {wob: 60 kN, torque_on_bit: 2 kN*m, rpm: 80}
)",
                       "calibration.yaml");
}

constexpr double kOpen = 0.32, kCased = 0.18, kOffset = 350e3, kBit = 0.4;

// Readings at n depths from 900 m to 1500 m: drilling (with WOB from 40 to 90 kN), rotating off
// bottom, pick-up and slack-off in turn, each made by the model at the true parameters with 1 % noise.
io::RigReadings Readings(const io::Case& c, int n, ReadingsModelKind kind, unsigned seed) {
  io::RigReadings readings;
  readings.file = "synthetic.csv";
  const io::RigActivity activities[] = {io::RigActivity::kDrilling, io::RigActivity::kRotatingOffBottom,
                                        io::RigActivity::kPickUp, io::RigActivity::kSlackOff};
  for (int i = 0; i < n; ++i) {
    io::RigReading r;
    r.bit_md = 900.0 + 600.0 * i / std::max(1, n - 1);
    r.activity = activities[i % 4];
    r.weight_on_bit = r.activity == io::RigActivity::kDrilling ? 40e3 + 50e3 * ((i * 7) % 11) / 10.0 : 0.0;
    r.rotary_speed = r.activity == io::RigActivity::kDrilling || r.activity == io::RigActivity::kRotatingOffBottom
                         ? 80.0 * kPi / 30.0
                         : 0.0;
    r.surface_torque = 0.0;
    r.line = i + 3;
    readings.rows.push_back(r);
  }
  ReadingsModelOptions options;
  options.kind = kind;
  options.jobs = 2;
  ReadingsModel model(c, readings, options);
  const std::vector<ModelledReading> truth = model.Evaluate({kOpen, kCased, kOffset, kBit});
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (std::size_t i = 0; i < readings.rows.size(); ++i) {
    EXPECT_FALSE(truth[i].failed()) << truth[i].message;
    readings.rows[i].hook_load = truth[i].hook_load * (1.0 + noise(random));
    // Pick-up and slack-off read no torque (the string does not turn).
    const bool turns = readings.rows[i].rotary_speed > 0.0;
    readings.rows[i].surface_torque =
        turns ? std::optional<double>(truth[i].surface_torque * (1.0 + noise(random))) : std::nullopt;
  }
  return readings;
}

struct Recovered {
  double open_width = 0.0, cased_width = 0.0, offset_width = 0.0, bit_width = 0.0;
};

Recovered Recover(int n, ReadingsModelKind kind) {
  const io::Case c = Well();
  const io::RigReadings readings = Readings(c, n, kind, 17u + static_cast<unsigned>(n));
  CalibrationSettings settings;
  settings.model.kind = kind;
  settings.model.jobs = 2;
  const CalibrationResult result = Calibrate(c, readings, settings);
  EXPECT_TRUE(result.converged);
  const double truth[] = {kOpen, kCased, kOffset, kBit};
  for (const FittedParameter& p : result.parameters) {
    const double t = truth[static_cast<int>(p.parameter)];
    EXPECT_TRUE(p.fitted) << CalibrationParameterName(p.parameter);
    EXPECT_LE(p.low, t) << CalibrationParameterName(p.parameter) << " " << p.value;
    EXPECT_GE(p.high, t) << CalibrationParameterName(p.parameter) << " " << p.value;
    std::printf("%s, %d readings: %s %.6g (95 %%: %.6g to %.6g), truth %.6g\n",
                kind == ReadingsModelKind::kSoft ? "soft" : "stiff", n, CalibrationParameterName(p.parameter), p.value,
                p.low, p.high, t);
  }
  std::printf("  RMS hook load %.4g N, torque %.4g N*m; %d iterations, %d evaluations\n", result.hook_load_rms,
              result.torque_rms, result.iterations, result.evaluations);
  const auto& q = result.parameters;
  return {q[0].high - q[0].low, q[1].high - q[1].low, q[2].high - q[2].low, q[3].high - q[3].low};
}

TEST(Calibration, TheSoftStringRecoversWhatMadeItsReadings) {
  const Recovered few = Recover(24, ReadingsModelKind::kSoft);
  const Recovered many = Recover(96, ReadingsModelKind::kSoft);
  // Four times the readings: the intervals about halve (1/√4); asserted below 0.75 of the few's.
  EXPECT_LT(many.open_width, 0.75 * few.open_width);
  EXPECT_LT(many.cased_width, 0.75 * few.cased_width);
  EXPECT_LT(many.offset_width, 0.75 * few.offset_width);
  EXPECT_LT(many.bit_width, 0.75 * few.bit_width);
}

TEST(Calibration, TheStiffStringRecoversWhatMadeItsReadings) { Recover(40, ReadingsModelKind::kStiff); }

// Without casing the cased hole's friction is left out (not asked) or refused (asked by name); without
// any torque the bit's coefficient.
TEST(Calibration, WhatTheReadingsCannotDetermineIsLeftOutOrRefused) {
  io::Case c = Well();
  c.input.well = model::MakeWellbore(c.input.well->trajectory, {well::HoleSection{{}, 0.2159, {}}});
  io::RigReadings readings = Readings(Well(), 12, ReadingsModelKind::kSoft, 5u);
  for (io::RigReading& r : readings.rows) r.surface_torque.reset();
  CalibrationSettings settings;
  settings.model.kind = ReadingsModelKind::kSoft;
  const CalibrationResult result = Calibrate(c, readings, settings);
  EXPECT_TRUE(result.parameters[0].fitted);
  EXPECT_FALSE(result.parameters[1].fitted);
  EXPECT_TRUE(result.parameters[2].fitted);
  EXPECT_FALSE(result.parameters[3].fitted);
  ASSERT_GE(result.warnings.size(), 2u);
  settings.fit = {CalibrationParameter::kCasedHoleFriction};
  try {
    Calibrate(c, readings, settings);
    ADD_FAILURE() << "a cased-hole friction without casing was fitted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("synthetic.csv"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("cased_hole_friction"), std::string::npos) << error.what();
  }
}

// Student's t at 0.975 beyond the code's own table (dof ≤ 10), where the Cornish–Fisher expansion
// answers, against Abramowitz & Stegun's table 26.10: 2.2010 (11), 2.0860 (20), 2.0423 (30), 2.0003 (60),
// 1.9840 (100), 1.9600 (∞).
TEST(Calibration, StudentQuantileMatchesItsTable) {
  EXPECT_NEAR(StudentQuantile975(11), 2.2010, 2e-4);
  EXPECT_NEAR(StudentQuantile975(20), 2.0860, 1e-4);
  EXPECT_NEAR(StudentQuantile975(30), 2.0423, 1e-4);
  EXPECT_NEAR(StudentQuantile975(60), 2.0003, 1e-4);
  EXPECT_NEAR(StudentQuantile975(100), 1.9840, 1e-4);
  EXPECT_NEAR(StudentQuantile975(100000), 1.9600, 1e-4);
}

}  // namespace calibration_test
}  // namespace drillflex::pipeline
