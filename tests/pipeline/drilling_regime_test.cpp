// The drilling regime of a transient (pipeline/drilling_regime.hpp) on made-up runs whose answer is
// known: a bit speed Ω(1 + A sin νt) has severity (max − min)/mean = 2A; a probe on a circle of radius
// r turning at ω has whirl speed ω exactly (its unwrapped angle is linear in time).
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/drilling_regime.hpp"

namespace drillflex::pipeline {
namespace drilling_regime_test {

constexpr double kBitSpeed = 12.0;    // rad/s
constexpr double kClearance = 0.05;   // m

// 4 s at 1 ms: the bit at kBitSpeed (1 + amplitude sin 5πt): whole periods over the second half (2–4 s),
// its extremes on samples, one probe on a circle of `radius`
// precessing at `whirl` rad/s (clockwise looking down-hole positive, as the whirl angle: from the high
// side toward the right).
analyses::TransientResult MadeUpRun(double amplitude, double radius, double whirl) {
  analyses::TransientResult result;
  result.probe_s = {10.0};
  for (int i = 0; i <= 4000; ++i) {
    analyses::TransientSample sample;
    sample.time = 1e-3 * i;
    sample.bit_speed = kBitSpeed * (1.0 + amplitude * std::sin(5.0 * kPi * sample.time));
    analyses::ProbeSample probe;
    const double angle = whirl * sample.time;
    probe.whirl_angle = std::fmod(std::fmod(angle, 2.0 * kPi) + 2.0 * kPi, 2.0 * kPi);
    probe.lateral_z = radius * std::cos(angle);  // the high side at angle 0
    probe.lateral_y = radius * std::sin(angle);  // then toward the right
    sample.probes = {probe};
    result.samples.push_back(sample);
  }
  return result;
}

TEST(DrillingRegime, ABitTurningSteadilyWithAStillStringIsSmooth) {
  const DrillingRegime regime = ClassifyDrillingRegime(MadeUpRun(0.0, kClearance, 0.0), {kClearance});
  EXPECT_NEAR(regime.stick_slip_severity, 0.0, 1e-12);
  EXPECT_EQ(regime.whirl, Whirl::None);
  EXPECT_EQ(regime.Name(), "smooth");
}

TEST(DrillingRegime, SeverityNamesTorsionalOscillationAndStickSlip) {
  // The mean over the window's samples: Ω to the sampling's 1/2001 (the two ends count once more).
  DrillingRegime regime = ClassifyDrillingRegime(MadeUpRun(0.25, 0.0, 0.0), {kClearance});
  EXPECT_NEAR(regime.stick_slip_severity, 0.5, 1e-3);
  EXPECT_EQ(regime.Name(), "torsional oscillation");
  regime = ClassifyDrillingRegime(MadeUpRun(1.0, 0.0, 0.0), {kClearance});
  EXPECT_NEAR(regime.stick_slip_severity, 2.0, 4e-3);
  EXPECT_EQ(regime.Name(), "stick-slip");
}

TEST(DrillingRegime, AnOrbitAgainstTheBitIsBackwardWhirlAtItsSpeed) {
  const double whirl = -20.0;  // rad/s, against the bit's +12
  const DrillingRegime regime = ClassifyDrillingRegime(MadeUpRun(0.0, 0.9 * kClearance, whirl), {kClearance});
  EXPECT_EQ(regime.whirl, Whirl::Backward);
  EXPECT_NEAR(regime.whirl_speed, whirl, 1e-9 * std::abs(whirl));
  EXPECT_EQ(regime.whirl_probe_s, 10.0);
  EXPECT_EQ(regime.Name(), "smooth, backward whirl");
}

TEST(DrillingRegime, AnOrbitWithTheBitIsForwardWhirl) {
  const DrillingRegime regime = ClassifyDrillingRegime(MadeUpRun(1.0, kClearance, 5.0), {kClearance});
  EXPECT_EQ(regime.whirl, Whirl::Forward);
  EXPECT_NEAR(regime.whirl_speed, 5.0, 1e-9 * 5.0);
  EXPECT_EQ(regime.Name(), "stick-slip, forward whirl");
}

TEST(DrillingRegime, NoWhirlInsideHalfTheClearanceLessThanATurnSwingingThroughTheCentreOrWithoutAWall) {
  // Orbiting fast but at a third of the clearance: the string shakes about the centre, it does not whirl.
  EXPECT_EQ(ClassifyDrillingRegime(MadeUpRun(0.0, kClearance / 3.0, -20.0), {kClearance}).whirl, Whirl::None);
  // On the wall but turning 0.8 of a turn over the 2 s window: it creeps, it does not whirl.
  EXPECT_EQ(ClassifyDrillingRegime(MadeUpRun(0.0, kClearance, 0.8 * kPi), {kClearance}).whirl,
            Whirl::None);
  // Swinging in a plane through the centre, 0.9 of the clearance either side (its whirl angle flips by
  // half a turn at each pass: no orbit).
  analyses::TransientResult swing = MadeUpRun(0.0, 0.0, 0.0);
  for (analyses::TransientSample& sample : swing.samples) {
    analyses::ProbeSample& probe = sample.probes[0];
    probe.lateral_z = 0.9 * kClearance * std::cos(9.0 * sample.time);
    probe.whirl_angle = probe.lateral_z >= 0.0 ? 0.0 : kPi;
  }
  EXPECT_EQ(ClassifyDrillingRegime(swing, {kClearance}).whirl, Whirl::None);
  // A probe with no wall known.
  EXPECT_EQ(ClassifyDrillingRegime(MadeUpRun(0.0, kClearance, -20.0), {std::nan("")}).whirl, Whirl::None);
}

}  // namespace drilling_regime_test
}  // namespace drillflex::pipeline
