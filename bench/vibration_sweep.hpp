// The sweep of issue 5's vibration bench (bench/vibration_bench.cpp), also the one the reduced sweep
// is checked on against the direct one (tests/io/reduced_sweep_test.cpp): 231 rotary speeds (20–250
// rpm, step 1) with three excitations, an imbalance (0.02 kg·m at 40 ft, 1×), the bit (500 lbf
// lateral, 1000 lbf axial, 3×) and a mud motor (5 lobes, rotor at 150 rpm, 200 lbf at 20 ft).
#pragma once

#include "analyses/analysis_settings.hpp"

namespace drillflex::bench {

inline analyses::VibrationSettings ThreeExcitationSweep(analyses::VibrationMethod method) {
  constexpr double kRpm = kPi / 30.0, kFoot = 0.3048, kLbf = 4.4482216152605;
  analyses::VibrationSettings settings;
  settings.method = method;
  settings.speed_from = 20.0 * kRpm;
  settings.speed_to = 250.0 * kRpm;
  settings.speed_step = 1.0 * kRpm;
  analyses::Excitation imbalance;
  imbalance.type = analyses::ExcitationType::Imbalance;
  imbalance.at = 40.0 * kFoot;
  imbalance.imbalance = 0.02;
  analyses::Excitation bit;
  bit.type = analyses::ExcitationType::Bit;
  bit.harmonic = 3;
  bit.lateral = 500.0 * kLbf;
  bit.axial = 1000.0 * kLbf;
  analyses::Excitation motor;
  motor.type = analyses::ExcitationType::Motor;
  motor.lobes = 5;
  motor.motor_speed = 150.0 * kRpm;
  motor.lateral = 200.0 * kLbf;
  motor.at = 20.0 * kFoot;
  settings.excitations = {imbalance, bit, motor};
  return settings;
}

}  // namespace drillflex::bench
