// The case reader: every key of the contract read into SI, and every rejected input reported with
// its file, line and key path.
#include "io/case.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace drillflex::io {
namespace case_reader_test {

using ::testing::HasSubstr;

constexpr double kFt = 0.3048;
constexpr double kIn = 0.0254;
constexpr double kLbf = 4.4482216152605;

const char* kFieldCase = R"(name: 8-1/2 in rotary BHA in a build section
units: field
well:
  survey:
    - [0, 0, 0]
    - [5000, 0, 0]
    - [6000, 30, 45]
  hole:
    - {to: 4000, diameter: 9.625, cased: true, friction: 0.18, axial_friction: 0.2}
    - {diameter: 8.5}
  bit_md: 6000
fluid: {density: 10.5, viscosity: 20}
materials:
  brass: {E: 1.0e11 Pa, nu: 0.33, density: 8500 kg/m3}
string:
  - {type: bit, od: 8.5, length: 1.0}
  - {type: stabilizer, od: 6.75, id: 2.8125, length: 5, blade_od: 8.375}
  - {type: collar, od: 6.75, id: 2.8125, length: 30, count: 3}
  - {type: pipe, od: 5, id: 4.276, length: 1000, material: steel, joint_od: 6.625}
model:
  body_length: 3.0 m
  elements_per_body: 10
  modes_per_body: 6
  coupling_factor: 100
  structural_damping: 0.01
  bending_stiffness_factor: 0.5
  contact: {stiffness: 1e8 N/m, damping_ratio: 0.1, friction: 0.25}
supports:
  - {at: 0, fix: [x, y, z]}
loads:
  - {at: 5.08 m, force: [0, 1000, 0]}
  - {from: 0, to: 5.08 m, per_length: [0, 0, 100]}
  - {at: 5.08 m, moment: [0, 0, 500]}
operation: {wob: 25, rpm: 120, torque_on_bit: 5000}
analyses:
  static: {}
  modes: {count: 10, kind: all}
  vibration:
    rpm: {from: 20, to: 250, step: 1}
    excitations:
      - {type: imbalance, at: 40, me: 0.02 kg*m}
      - {type: bit, harmonic: 3, lateral: 500 lbf, axial: 1000 lbf}
  transient: {duration: 10 s, output_interval: 0.01 s, probes: [10 ft, 60 ft]}
)";

TEST(CaseReader, ReadsEveryKeyOfTheContractInSI) {
  const Case c = ParseCase(kFieldCase, "case.yaml");
  EXPECT_EQ(c.name, "8-1/2 in rotary BHA in a build section");
  EXPECT_EQ(c.units, units::System::Field);
  EXPECT_EQ(c.output_units, units::System::Field);
  ASSERT_TRUE(c.well);
  ASSERT_EQ(c.well->survey.size(), 3u);
  EXPECT_NEAR(c.well->survey[2].md, 6000 * kFt, 1e-9);
  EXPECT_NEAR(c.well->survey[2].inclination, 30 * kDegree, 1e-12);
  EXPECT_NEAR(c.well->survey[2].azimuth, 45 * kDegree, 1e-12);
  ASSERT_EQ(c.well->hole.size(), 2u);
  EXPECT_NEAR(*c.well->hole[0].to_md, 4000 * kFt, 1e-9);
  EXPECT_NEAR(c.well->hole[1].diameter, 8.5 * kIn, 1e-12);
  EXPECT_FALSE(c.well->hole[1].to_md);
  EXPECT_TRUE(c.well->hole[0].cased);
  EXPECT_EQ(c.well->hole[0].friction, 0.18);
  EXPECT_EQ(c.well->hole[0].axial_friction, 0.2);
  EXPECT_FALSE(c.well->hole[1].cased);
  EXPECT_FALSE(c.well->hole[1].friction);
  EXPECT_NEAR(c.well->bit_md, 6000 * kFt, 1e-9);
  EXPECT_NEAR(c.well->output_step, 30 * kFt, 1e-12);
  ASSERT_TRUE(c.input.fluid);
  EXPECT_NEAR(c.input.fluid->density, 10.5 * 119.826427, 1e-3);
  EXPECT_NEAR(c.input.fluid->viscosity, 0.020, 1e-12);
  EXPECT_DOUBLE_EQ(c.input.gravity, 9.81);
  ASSERT_TRUE(c.input.materials.count("brass"));
  EXPECT_DOUBLE_EQ(c.input.materials.at("brass").youngs_modulus, 1.0e11);
  ASSERT_TRUE(c.input.materials.count("steel"));
  ASSERT_EQ(c.input.string.components.size(), 4u);
  const auto& stabilizer = c.input.string.components[1];
  EXPECT_EQ(stabilizer.type, model::ComponentType::Stabilizer);
  EXPECT_NEAR(stabilizer.inner_diameter, 2.8125 * kIn, 1e-12);
  EXPECT_NEAR(*stabilizer.blade_diameter, 8.375 * kIn, 1e-12);
  EXPECT_EQ(c.input.string.components[2].count, 3);
  EXPECT_NEAR(*c.input.string.components[3].joint_diameter, 6.625 * kIn, 1e-12);
  EXPECT_NEAR(c.input.settings.body_length, 3.0, 1e-12);
  EXPECT_EQ(c.input.settings.modes_per_body, 6);
  EXPECT_DOUBLE_EQ(c.input.settings.contact.stiffness, 1e8);
  EXPECT_DOUBLE_EQ(c.input.settings.bending_stiffness_factor, 0.5);
  ASSERT_EQ(c.input.supports.size(), 1u);
  EXPECT_TRUE(c.input.supports[0].fixed[model::kX] && c.input.supports[0].fixed[model::kZ]);
  EXPECT_FALSE(c.input.supports[0].fixed[model::kRx]);
  ASSERT_EQ(c.input.loads.size(), 3u);
  EXPECT_NEAR(c.input.loads[0].force.y(), 1000 * kLbf, 1e-9);
  EXPECT_TRUE(c.input.loads[1].distributed);
  EXPECT_NEAR(c.input.loads[1].force_per_length.z(), 100 * kLbf / kFt, 1e-9);
  EXPECT_NEAR(c.input.loads[2].moment.z(), 500 * kLbf * kFt, 1e-9);
  EXPECT_NEAR(c.input.operation.weight_on_bit, 25000 * kLbf, 1e-6);
  EXPECT_NEAR(c.input.operation.rotary_speed, 120 * 2 * kPi / 60, 1e-12);
  EXPECT_NEAR(c.input.operation.torque_on_bit, 5000 * kLbf * kFt, 1e-9);
  ASSERT_TRUE(c.analyses.static_analysis);
  ASSERT_TRUE(c.analyses.modes);
  EXPECT_EQ(c.analyses.modes->count, 10);
  ASSERT_TRUE(c.analyses.vibration);
  EXPECT_NEAR(c.analyses.vibration->speed_to, 250 * 2 * kPi / 60, 1e-12);
  ASSERT_EQ(c.analyses.vibration->excitations.size(), 2u);
  EXPECT_NEAR(c.analyses.vibration->excitations[0].at, 40 * kFt, 1e-12);
  EXPECT_NEAR(c.analyses.vibration->excitations[0].imbalance, 0.02, 1e-15);
  EXPECT_EQ(c.analyses.vibration->excitations[1].harmonic, 3);
  EXPECT_NEAR(c.analyses.vibration->excitations[1].axial, 1000 * kLbf, 1e-9);
  ASSERT_TRUE(c.analyses.transient);
  EXPECT_NEAR(c.analyses.transient->duration, 10.0, 1e-12);
  ASSERT_EQ(c.analyses.transient->probes.size(), 2u);
  EXPECT_NEAR(c.analyses.transient->probes[1], 60 * kFt, 1e-12);
  EXPECT_FALSE(c.analyses.buckling);
}

TEST(CaseReader, TransientIntegratorKeysAndInitialLoads) {
  const Case c = ParseCase(R"(string:
  - {type: collar, od: 0.2, id: 0.07, length: 30}
analyses:
  transient:
    duration: 2 s
    output_interval: 5 ms
    time_step: 1 ms
    rho_infinity: 0.9
    tolerance: 1e-6
    vtk_frames: 25
    initial_loads:
      - {at: 30, force: [0, 0, 100]}
)",
                           "transient.yaml");
  ASSERT_TRUE(c.analyses.transient);
  const auto& t = *c.analyses.transient;
  EXPECT_NEAR(t.output_interval, 5e-3, 1e-15);
  ASSERT_TRUE(t.time_step);
  EXPECT_NEAR(*t.time_step, 1e-3, 1e-15);
  EXPECT_DOUBLE_EQ(t.rho_infinity, 0.9);
  EXPECT_DOUBLE_EQ(t.tolerance, 1e-6);
  EXPECT_EQ(t.start, analyses::TransientStart::Equilibrium);
  EXPECT_EQ(t.vtk_frames, 25);
  EXPECT_EQ(t.state_frames, 0);  // the command line turns vtk_frames into state_frames
  ASSERT_EQ(t.initial_loads.size(), 1u);
  EXPECT_NEAR(t.initial_loads[0].at, 30.0, 1e-12);  // SI case: m and N
  EXPECT_NEAR(t.initial_loads[0].force.z(), 100.0, 1e-12);
}

TEST(CaseReader, BitRockLaws) {
  const Case detournay = ParseCase(R"(units: field
string:
  - {type: bit, od: 8.5, length: 1}
  - {type: collar, od: 6.75, id: 2.8125, length: 30}
analyses:
  transient:
    bit_rock: {law: detournay, specific_energy: 8.7 ksi, cutting_ratio: 0.6, contact_force: 4500,
               friction: 0.6, geometry: 1.1, stick_speed: 0.2, contact_speed: 0.1 ft/h}
)",
                                   "detournay.yaml");
  ASSERT_TRUE(detournay.analyses.transient && detournay.analyses.transient->bit_rock);
  const model::BitRockParameters& d = *detournay.analyses.transient->bit_rock;
  EXPECT_EQ(d.law, model::BitRockLaw::Detournay);
  EXPECT_NEAR(d.specific_energy, 8.7e3 * kLbf / (kIn * kIn), 1e-6 * d.specific_energy);  // ksi
  EXPECT_DOUBLE_EQ(d.cutting_ratio, 0.6);
  EXPECT_NEAR(d.contact_force, 4500 * kLbf, 1e-9);  // lbf
  EXPECT_DOUBLE_EQ(d.friction, 0.6);
  EXPECT_DOUBLE_EQ(d.geometry, 1.1);
  EXPECT_EQ(d.radius, 0.0);                          // from the bit's OD when the model is built
  EXPECT_NEAR(d.stick_speed, 0.2 * 2 * kPi / 60, 1e-12);  // rpm
  EXPECT_NEAR(d.contact_speed, 0.1 * kFt / 3600, 1e-15);
  const Case friction = ParseCase(R"(string:
  - {type: collar, od: 0.2, id: 0.07, length: 30}
analyses:
  transient:
    bit_rock: {law: friction, static_torque: 3 kN*m, kinetic_torque: 2000, stick_speed: 0.01}
)",
                                  "friction.yaml");
  const model::BitRockParameters& f = *friction.analyses.transient->bit_rock;
  EXPECT_EQ(f.law, model::BitRockLaw::Friction);
  EXPECT_NEAR(f.static_torque, 3000.0, 1e-9);
  EXPECT_NEAR(f.kinetic_torque, 2000.0, 1e-9);       // SI case: N·m
  EXPECT_NEAR(f.stick_speed, 0.01 * 2 * kPi / 60, 1e-15);
  EXPECT_DOUBLE_EQ(f.stribeck_speed, f.stick_speed);  // default: the drop over the stick speed
}

// `bit_rock.bottom` and `bit_rock.side_cutting`, with the friction law or without a law.
TEST(CaseReader, BitBottomAndSideCutting) {
  const Case field = ParseCase(R"(units: field
string:
  - {type: bit, od: 8.5, length: 1}
  - {type: collar, od: 6.75, id: 2.8125, length: 30}
analyses:
  transient:
    bit_rock:
      law: friction
      static_torque: 3000
      kinetic_torque: 2000
      bottom: {stiffness: 2e6, damping_ratio: 0.1, motion: {amplitude: 0.25, frequency: 6 Hz, ramp: 2 s}}
      side_cutting: {resistance: 1e5}
)",
                               "bottom.yaml");
  const model::BitRockParameters& f = *field.analyses.transient->bit_rock;
  EXPECT_EQ(f.law, model::BitRockLaw::Friction);
  ASSERT_TRUE(f.bottom.has_value());
  EXPECT_NEAR(f.bottom->stiffness, 2e6 * kLbf / kIn, 1e-6 * f.bottom->stiffness);  // lbf/in
  EXPECT_DOUBLE_EQ(f.bottom->damping_ratio, 0.1);
  EXPECT_NEAR(f.bottom->amplitude, 0.25 * kIn, 1e-15);  // in
  EXPECT_DOUBLE_EQ(f.bottom->frequency, 6.0);
  EXPECT_DOUBLE_EQ(f.bottom->ramp_time, 2.0);
  EXPECT_EQ(f.bottom->level, 0.0);  // placed at the transient's start
  ASSERT_TRUE(f.side_cutting.has_value());
  EXPECT_NEAR(*f.side_cutting, 1e5 * kLbf / kIn, 1e-6 * *f.side_cutting);
  // No law: a bottom alone, with its defaults (stiffness from the model, 5 % damping, no motion).
  const Case bare = ParseCase("string:\n  - {type: collar, od: 8, id: 2.8125, length: 30}\nanalyses:\n  transient:\n    bit_rock: {bottom: }\n", "bare.yaml");
  const model::BitRockParameters& b = *bare.analyses.transient->bit_rock;
  EXPECT_EQ(b.law, model::BitRockLaw::None);
  ASSERT_TRUE(b.bottom.has_value());
  EXPECT_EQ(b.bottom->stiffness, 0.0);
  EXPECT_DOUBLE_EQ(b.bottom->damping_ratio, 0.05);
  EXPECT_EQ(b.bottom->amplitude, 0.0);
  EXPECT_FALSE(b.side_cutting.has_value());
}

TEST(CaseReader, TransientDrives) {
  // Field units: rpm, ft·lbf, ft/s; the speed drive defaults to operation.rpm with a 2 s ramp.
  const char* head = "units: field\nstring:\n  - {type: collar, od: 8, id: 2.8125, length: 90}\n"
                     "operation: {rpm: 100, hook_load: 50}\n";
  const auto transient = [&](const std::string& keys) {
    return *ParseCase(std::string(head) + "analyses:\n  transient: " + keys + "\n", "drives.yaml").analyses.transient;
  };
  const auto by_default = transient("{}");
  ASSERT_TRUE(by_default.top_drive);
  EXPECT_EQ(by_default.top_drive->mode, model::TopDriveMode::Speed);
  EXPECT_NEAR(by_default.top_drive->setting.target, 100 * kPi / 30, 1e-12);
  EXPECT_DOUBLE_EQ(by_default.top_drive->setting.ramp_time, model::kDefaultTopDriveRamp);
  EXPECT_FALSE(by_default.block);
  EXPECT_FALSE(by_default.vtk_frames);  // the command line's default
  const auto speed = transient("{top_drive: {rpm: 120, ramp: 0.5 s}, block: {velocity: -1.5, ramp: 1 s}}");
  EXPECT_NEAR(speed.top_drive->setting.target, 4 * kPi, 1e-12);
  EXPECT_DOUBLE_EQ(speed.top_drive->setting.ramp_time, 0.5);
  ASSERT_TRUE(speed.block);
  EXPECT_EQ(speed.block->mode, model::BlockMode::Velocity);
  EXPECT_NEAR(speed.block->setting.target, -1.5 * kFt, 1e-12);  // running in at 1.5 ft/s
  EXPECT_FALSE(speed.block->line_stiffness);                    // as stiff as the hold it replaces
  // The line between block and top: lbf/in in field units.
  const auto soft = transient("{block: {velocity: -1.5, stiffness: 2000}}");
  ASSERT_TRUE(soft.block && soft.block->line_stiffness);
  EXPECT_NEAR(*soft.block->line_stiffness, 2000 * kLbf / 0.0254, 1e-6);
  const auto torque = transient("{top_drive: {torque: 15000}, block: {}}");
  EXPECT_EQ(torque.top_drive->mode, model::TopDriveMode::Torque);
  EXPECT_NEAR(torque.top_drive->setting.target, 15000 * kFt * kLbf, 1e-9);
  EXPECT_DOUBLE_EQ(torque.top_drive->setting.ramp_time, 0.0);
  EXPECT_EQ(torque.block->mode, model::BlockMode::HookLoad);
  EXPECT_NEAR(torque.block->setting.target, 50 * kLbf, 1e-9);  // operation.hook_load (lbf)
  // The block's own hook load may be negative: a compression, pushing the top down-hole, here
  // ramped from 0 over 25 s.
  const auto pushing = transient("{block: {hook_load: -11 lbf, ramp: 25 s}}");
  ASSERT_TRUE(pushing.block);
  EXPECT_EQ(pushing.block->mode, model::BlockMode::HookLoad);
  EXPECT_NEAR(pushing.block->setting.target, -11 * kLbf, 1e-9);
  EXPECT_DOUBLE_EQ(pushing.block->setting.ramp_time, 25.0);
  EXPECT_FALSE(pushing.block->at_surface);
  // No rpm anywhere: no drive.
  const Case resting = ParseCase("string:\n  - {type: collar, od: 0.2, id: 0.07, length: 30}\n"
                                 "analyses:\n  transient: {}\n", "rest.yaml");
  EXPECT_FALSE(resting.analyses.transient->top_drive);
}

TEST(CaseReader, DefaultsWithoutAWell) {
  const Case c = ParseCase(R"(
string:
  - {type: collar, od: 0.0762, id: 0, length: 5.08}
supports: [{at: 0, fix: all}]
analyses: {modes: }
)", "beam.yaml");
  EXPECT_EQ(c.name, "beam");
  EXPECT_EQ(c.units, units::System::SI);
  EXPECT_FALSE(c.well);
  EXPECT_DOUBLE_EQ(c.input.gravity, 0.0);
  EXPECT_EQ(c.input.settings.elements_per_body, 10);
  EXPECT_DOUBLE_EQ(c.input.settings.bending_stiffness_factor, 1.0);  // the sections' own EI
  ASSERT_TRUE(c.analyses.modes);
  EXPECT_EQ(c.analyses.modes->count, 10);
  EXPECT_TRUE(c.input.supports[0].fixed[model::kRz]);
  EXPECT_NEAR(StringLength(c), 5.08, 1e-12);
}

// The message of the InputError a case raises, or "" when it reads.
std::string ErrorOf(const std::string& text, int* line = nullptr, std::string* key = nullptr) {
  try {
    ParseCase(text, "bad.yaml", DRILLFLEX_SOURCE_DIR "/tests/io");
  } catch (const InputError& error) {
    if (line) *line = error.location().line;
    if (key) *key = error.key_path();
    return error.what();
  }
  return "";
}

const char* kGoodString = "string:\n  - {type: collar, od: 8, id: 2.8125, length: 30}\n";

// `modes: {gyroscopic, campbell}`: the spin from operation.rpm, the speeds in rpm (rad/s inside).
TEST(CaseReader, GyroscopicModesAndCampbellRange) {
  const Case c = ParseCase(std::string(kGoodString) + "operation: {rpm: 120}\nanalyses:\n  modes:\n    gyroscopic: true\n"
                           "    campbell: {from: 0, to: 250, step: 10}\n",
                           "gyroscopic.yaml");
  ASSERT_TRUE(c.analyses.modes && c.analyses.modes->campbell);
  EXPECT_TRUE(c.analyses.modes->gyroscopic);
  EXPECT_NEAR(c.analyses.modes->rotary_speed, 120.0 * kPi / 30.0, 1e-12);
  EXPECT_NEAR(c.analyses.modes->campbell->from, 0.0, 1e-12);
  EXPECT_NEAR(c.analyses.modes->campbell->to, 250.0 * kPi / 30.0, 1e-12);
  EXPECT_NEAR(c.analyses.modes->campbell->step, 10.0 * kPi / 30.0, 1e-12);
}

// A transient's `excitations`: the vibration analysis's imbalance items (lb·in in field units);
// a bit's or motor's excitation, or an imbalance off the string, is refused with its key.
TEST(CaseReader, TransientImbalances) {
  const std::string head = std::string("units: field\n") + kGoodString + "analyses:\n  transient:\n    excitations:\n";
  const Case c = ParseCase(head + "      - {type: imbalance, at: 15, me: 50 lb*in}\n", "imbalance.yaml");
  ASSERT_EQ(c.analyses.transient->imbalances.size(), 1u);
  EXPECT_NEAR(c.analyses.transient->imbalances[0].at, 15 * kFt, 1e-12);
  EXPECT_NEAR(c.analyses.transient->imbalances[0].me, 50 * 0.45359237 * 0.0254, 1e-12);  // kg·m
  EXPECT_NE(ErrorOf(head + "      - {type: bit, harmonic: 3, lateral: 500}\n").find("imbalance excitations only"),
            std::string::npos);
  int line = 0;
  std::string key;
  EXPECT_NE(ErrorOf(head + "      - {type: imbalance, at: 40, me: 1 lb*in}\n", &line, &key).find("off the string"),
            std::string::npos);
  EXPECT_EQ(key, "analyses.transient.excitations[0].at");
}

// `model.contact.friction_velocity` (a velocity: ft/s in field units, any unit given) and a
// transient's `fluid_frequency` (Hz in the case, rad/s inside); unset by default.
TEST(CaseReader, FrictionVelocityAndFluidFrequency) {
  const std::string head = std::string("units: field\n") + kGoodString;
  const Case given = ParseCase(head + "model:\n  contact: {friction: 0.3, friction_velocity: 2 mm/s}\n"
                                      "analyses:\n  transient: {fluid_frequency: 3 Hz}\n",
                               "given.yaml");
  ASSERT_TRUE(given.input.settings.contact.friction_velocity.has_value());
  EXPECT_NEAR(*given.input.settings.contact.friction_velocity, 2e-3, 1e-15);
  ASSERT_TRUE(given.analyses.transient && given.analyses.transient->fluid_frequency);
  EXPECT_NEAR(*given.analyses.transient->fluid_frequency, 6.0 * kPi, 1e-12);
  const Case bare = ParseCase(head + "model:\n  contact: {friction_velocity: 0.01}\n", "bare.yaml");
  EXPECT_NEAR(*bare.input.settings.contact.friction_velocity, 0.01 * kFt, 1e-15);  // ft/s
  const Case unset = ParseCase(head + "analyses:\n  transient: {duration: 1 s}\n", "unset.yaml");
  EXPECT_FALSE(unset.input.settings.contact.friction_velocity.has_value());
  EXPECT_FALSE(unset.analyses.transient->fluid_frequency.has_value());
}

// `model.contact.penetration_fraction`: 0.02 by default, 0 turns the tight contacts' stiffness floor
// off, a fraction outside [0, 1) is refused naming the key.
TEST(CaseReader, ContactPenetrationFraction) {
  const std::string head = std::string("units: field\n") + kGoodString;
  EXPECT_DOUBLE_EQ(ParseCase(head, "default.yaml").input.settings.contact.penetration_fraction, 0.02);
  EXPECT_DOUBLE_EQ(ParseCase(head + "model:\n  contact: {penetration_fraction: 0}\n", "off.yaml")
                       .input.settings.contact.penetration_fraction,
                   0.0);
  int line = 0;
  std::string key;
  const std::string message = ErrorOf(head + "model:\n  contact: {penetration_fraction: 1.5}\n", &line, &key);
  EXPECT_NE(message.find("0 <= x < 1"), std::string::npos) << message;
  EXPECT_EQ(key, "model.contact.penetration_fraction");
}

// Ratings (issue 37): grade, custom yield, class and make-up torque per component; the design factor.
TEST(CaseReader, StringRatingsAndDesignFactor) {
  const Case c = ParseCase(
      "units: field\nstring:\n"
      "  - {type: collar, od: 6.75, id: 2.8125, length: 30, yield: 110 ksi, makeup_torque: 30000}\n"
      "  - {type: pipe, od: 5, id: 4.276, length: 30, grade: g105, class: premium, makeup_torque: 20000 ft*lbf}\n"
      "limits: {design_factor: 1.4}\n",
      "ratings.yaml");
  const auto& collar = c.input.string.components[0];
  const auto& pipe = c.input.string.components[1];
  constexpr double kKsi = 1000.0 * kLbf / (0.0254 * 0.0254);
  EXPECT_NEAR(*collar.yield_strength, 110.0 * kKsi, 1e-3);
  EXPECT_EQ(collar.grade, "");
  EXPECT_NEAR(*collar.makeup_torque, 30000.0 * kLbf * kFt, 1e-9);  // a bare number: ft*lbf in field units
  EXPECT_EQ(pipe.grade, "G-105");
  EXPECT_NEAR(*pipe.yield_strength, 105.0 * kKsi, 1e-3);
  EXPECT_EQ(pipe.pipe_class, model::PipeClass::Premium);
  EXPECT_NEAR(*pipe.makeup_torque, 20000.0 * kLbf * kFt, 1e-9);
  EXPECT_DOUBLE_EQ(c.limits.design_factor, 1.4);
  const Case plain = ParseCase(std::string(kGoodString), "plain.yaml");
  EXPECT_FALSE(plain.input.string.components[0].yield_strength);
  EXPECT_EQ(plain.input.string.components[0].pipe_class, model::PipeClass::New);
  EXPECT_DOUBLE_EQ(plain.limits.design_factor, 1.25);
}

// A tool joint's connection (issue 37): its API RP 7G make-up torque, 31 024.539 ft·lbf for NC50 on a
// 6-5/8 × 3-1/4 in joint by hand (tests/model/tool_joint_torque_test.cpp); casing wear's keys in SI inside.
TEST(CaseReader, ConnectionMakeupTorqueAndWearKeys) {
  const Case c = ParseCase(
      "units: field\nwell:\n  survey: [[0, 0, 0], [8000, 0, 0]]\n"
      "  hole:\n    - {to: 4500, diameter: 8.835, cased: true, wall: 0.395}\n    - {diameter: 8.5}\n  bit_md: 5000\n"
      "string:\n  - {type: pipe, od: 5, id: 4.276, length: 30, count: 10, joint_od: 6.625, joint_id: 3.25, connection: NC50}\n"
      "operation: {rpm: 120}\n"
      "limits: {wear: {factor: 5e-10, rop: 60 ft/h, from: 4000}}\n",
      "connection.yaml");
  const auto& pipe = c.input.string.components[0];
  EXPECT_EQ(pipe.connection, "NC50");
  EXPECT_NEAR(*pipe.makeup_torque, 31024.539 * kLbf * kFt, 0.02);
  ASSERT_TRUE(c.limits.wear);
  constexpr double kPsi = kLbf / (0.0254 * 0.0254);
  EXPECT_NEAR(c.limits.wear->wear_factor * kPsi, 5e-10, 1e-22);  // a bare number: 1/psi in field units
  EXPECT_NEAR(*c.limits.wear->rate_of_penetration, 60.0 * kFt / 3600.0, 1e-12);
  EXPECT_NEAR(*c.limits.wear->from_md, 4000.0 * kFt, 1e-9);
  EXPECT_NEAR(c.limits.wear->rotary_speed, 120.0 * 2.0 * 3.14159265358979323846 / 60.0, 1e-12);
  EXPECT_NEAR(*c.well->hole[0].wall, 0.395 * 0.0254, 1e-12);
}

// A connection by its common name: 4-1/2 IF is NC50 (the same thread), so the same joint's make-up torque,
// 31 024.539 ft·lbf by hand; 2-7/8 IF is NC31.
TEST(CaseReader, ConnectionsByTheirCommonNames) {
  const Case c = ParseCase(
      "units: field\nstring:\n"
      "  - {type: pipe, od: 2.875, id: 2.151, length: 30, joint_od: 4.125, joint_id: 2.125, connection: 2-7/8 IF}\n"
      "  - {type: pipe, od: 5, id: 4.276, length: 30, joint_od: 6.625, joint_id: 3.25, connection: 4-1/2 IF}\n",
      "aliases.yaml");
  EXPECT_EQ(c.input.string.components[0].connection, "NC31");
  EXPECT_EQ(c.input.string.components[1].connection, "NC50");
  EXPECT_NEAR(*c.input.string.components[1].makeup_torque, 31024.539 * kLbf * kFt, 0.02);
}

struct RejectedCase {
  const char* label;
  std::string text;
  int line;
  const char* key;
  const char* says;
};

void PrintTo(const RejectedCase& rejected, std::ostream* os) { *os << rejected.label; }

class RejectedInput : public ::testing::TestWithParam<RejectedCase> {};

TEST_P(RejectedInput, NamesFileLineKeyAndWhatWasExpected) {
  const RejectedCase& rejected = GetParam();
  int line = 0;
  std::string key;
  const std::string message = ErrorOf(rejected.text, &line, &key);
  ASSERT_FALSE(message.empty()) << rejected.label << ": the case was accepted";
  EXPECT_EQ(line, rejected.line) << message;
  EXPECT_EQ(key, rejected.key) << message;
  EXPECT_THAT(message, HasSubstr("bad.yaml:" + std::to_string(rejected.line) + ":")) << message;
  EXPECT_THAT(message, HasSubstr(rejected.says)) << message;
}

const std::string kWellHead = "units: field\nwell:\n  survey:\n    - [0, 0, 0]\n    - [1000, 10, 0]\n";

INSTANTIATE_TEST_SUITE_P(
    CaseReader, RejectedInput,
    ::testing::Values(
        RejectedCase{"unknown key", std::string(kGoodString) + "modle: {}\n", 3, "modle", "did you mean 'model'"},
        // A key twice in one map: YAML keeps both and the readers took the first, silently.
        RejectedCase{"operation given twice", std::string(kGoodString) + "operation: {wob: 10}\noperation: {wob: 20}\n", 4,
                     "operation", "'operation' is given twice in one map, at line 3 and at line 4"},
        RejectedCase{"a negative rpm", std::string(kGoodString) + "operation:\n  rpm: -1e9\n", 4, "operation.rpm",
                     "must not be negative"},
        RejectedCase{"a WOB of 1e12 lbf", "units: field\n" + std::string(kGoodString) + "operation:\n  wob: 1e12 lbf\n", 5,
                     "operation.wob", "expected at most 1000 klbf"},
        RejectedCase{"a nested key given twice", "units: field\nstring:\n  - {type: collar, od: 8, od: 7, length: 30}\n",
                     3, "string[0].od", "'od' is given twice in one map, on line 3, at columns 20 and 27"},
        // A modulus or density in the other system's unit: 30e6 read as Pa, 207e9 read as psi, 65.5 (ppg) as kg/m3.
        RejectedCase{"modulus in psi read as Pa", "materials:\n  steel: {E: 30e6, nu: 0.3, density: 7850}\n", 2,
                     "materials.steel.E", "between 0.1 and 1500 GPa (steel's is 207 GPa, 30e6 psi), got 3e+07 Pa"},
        RejectedCase{"modulus in Pa read as psi", "units: field\nmaterials:\n  steel: {E: 207e9, nu: 0.3, density: 65.5}\n", 3,
                     "materials.steel.E", "got 1.427e+15 Pa (2.07e+11 psi)"},
        // Ratings (issue 37): a yield outside 40-200 ksi, an unknown grade or class, a bad design factor.
        RejectedCase{"a yield of 250 ksi", "units: field\nstring:\n  - {type: pipe, od: 5, id: 4.276, length: 30, yield: 250 ksi}\n",
                     3, "string[0].yield", "between 40 and 200 ksi"},
        RejectedCase{"a yield in psi read as Pa", "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, yield: 105000}\n",
                     2, "string[0].yield", "got 0.01523 ksi"},
        RejectedCase{"an unknown grade", "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, grade: P-110}\n", 2,
                     "string[0].grade", "unknown grade 'P-110'; expected one of: E-75, X-95, G-105, S-135"},
        RejectedCase{"grade and yield", "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, grade: G-105, yield: 9e8}\n",
                     2, "string[0].yield", "either 'grade' or a custom 'yield'"},
        RejectedCase{"an unknown class", "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, class: worn}\n", 2,
                     "string[0].class", "expected 'new' or 'premium'"},
        RejectedCase{"an unknown connection",
                     "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, joint_od: 0.168, joint_id: 0.08, connection: NC51}\n", 2,
                     "string[0].connection",
                     "unknown connection 'NC51'; expected one of: NC26 (2-3/8 IF), NC31 (2-7/8 IF), NC38 (3-1/2 IF), "
                     "NC40 (4 FH), NC46 (4 IF), NC50 (4-1/2 IF) (or give 'makeup_torque')"},
        RejectedCase{"a regular connection",
                     "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, joint_od: 0.168, joint_id: 0.08, connection: 6-5/8 REG}\n", 2,
                     "string[0].connection", "the regular (REG) and full-hole (FH) connections other than 4 FH (NC40) are not supported"},
        RejectedCase{"a full-hole connection other than 4 FH",
                     "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, joint_od: 0.168, joint_id: 0.08, connection: 4-1/2 FH}\n", 2,
                     "string[0].connection", "expected one of: NC26 (2-3/8 IF), NC31 (2-7/8 IF)"},
        RejectedCase{"a connection without the joint's bore",
                     "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, joint_od: 0.168, connection: NC50}\n", 2,
                     "string[0].connection", "needs the tool joint's 'joint_od' and 'joint_id'"},
        RejectedCase{"a connection and a make-up torque",
                     "string:\n  - {type: pipe, od: 0.127, id: 0.1, length: 9, joint_od: 0.168, joint_id: 0.08, connection: NC50, "
                     "makeup_torque: 40000}\n", 2, "string[0].makeup_torque", "not both"},
        RejectedCase{"a wear factor in 1/Pa read as 1/psi",
                     "units: field\nwell:\n  survey: [[0, 0, 0], [8000, 0, 0]]\n  hole: [{to: 4500, diameter: 8.835, cased: true}, "
                     "{diameter: 8.5}]\n  bit_md: 5000\nstring:\n  - {type: pipe, od: 5, id: 4.276, length: 30}\n"
                     "operation: {rpm: 120}\nlimits: {wear: {factor: 7e-14, rotating_time: 100 h}}\n", 9,
                     "limits.wear.factor", "between 1e-13 and 1e-7 1/psi"},
        RejectedCase{"wear without a cased section",
                     "units: field\nwell:\n  survey: [[0, 0, 0], [8000, 0, 0]]\n  hole: 8.5\n  bit_md: 5000\n"
                     "string:\n  - {type: pipe, od: 5, id: 4.276, length: 30}\noperation: {rpm: 120}\n"
                     "limits: {wear: {factor: 5e-10, rotating_time: 100 h}}\n", 9, "limits.wear", "needs a cased hole section"},
        RejectedCase{"a wall on open hole",
                     "units: field\nwell:\n  survey: [[0, 0, 0], [8000, 0, 0]]\n  hole: [{diameter: 8.5, wall: 0.4}]\n  bit_md: 5000\n"
                     "string:\n  - {type: pipe, od: 5, id: 4.276, length: 30}\n", 4, "well.hole[0].wall", "cased: true"},
        RejectedCase{"a design factor below 1", std::string(kGoodString) + "limits: {design_factor: 0.8}\n", 3,
                     "limits.design_factor", "between 1 and 3"},
        RejectedCase{"density in ppg read as kg/m3", "materials:\n  steel: {E: 207e9, nu: 0.3, density: 65.5}\n", 2,
                     "materials.steel.density", "between 500 and 25000 kg/m3"},
        RejectedCase{"a toolface beyond 360 deg",
                     "string:\n  - {type: motor, od: 6.5, id: 4, length: 20, bend: 1.5, bend_to_bit: 5, toolface: 400}\n", 2,
                     "string[0].toolface", "between 0 and 360 deg"},
        RejectedCase{"a negative steerability", std::string(kGoodString) + "analyses:\n  tendency: {steerability: -1}\n", 4,
                     "analyses.tendency.steerability", "a number >= 0"},
        // A rotary steerable system's keys (point-the-bit: offset; push-the-bit: force), refused with what was expected.
        RejectedCase{"a point-the-bit offset of 4 deg",
                     std::string(kGoodString) + "analyses:\n  tendency:\n    rss: {type: point, at: 1, offset: 4}\n", 5,
                     "analyses.tendency.rss.offset", "between 0 and 3 deg"},
        RejectedCase{"a point-the-bit system with a force",
                     std::string(kGoodString) + "analyses:\n  tendency:\n    rss: {type: point, at: 1, offset: 0.5, force: 1000}\n",
                     5, "analyses.tendency.rss.force", "a point-the-bit system tilts the bit by its `offset`"},
        RejectedCase{"a push-the-bit system with an offset",
                     std::string(kGoodString) + "analyses:\n  tendency:\n    rss: {type: push, at: 1, force: 1000, offset: 1}\n",
                     5, "analyses.tendency.rss.offset", "`offset` (the bit's tilt) is a point-the-bit system's"},
        RejectedCase{"a point-the-bit toolface beyond 360 deg",
                     std::string(kGoodString) + "analyses:\n  tendency:\n    rss: {type: point, at: 1, offset: 0.5, toolface: 361}\n",
                     5, "analyses.tendency.rss.toolface", "between 0 and 360 deg"},
        RejectedCase{"a point-the-bit steer above 1",
                     std::string(kGoodString) + "analyses:\n  tendency:\n    rss: {type: point, at: 1, offset: 0.5, steer: 1.5}\n",
                     5, "analyses.tendency.rss.steer", "0 to 1"},
        RejectedCase{"a point-the-bit system without its offset",
                     std::string(kGoodString) + "analyses:\n  tendency:\n    rss: {type: point, at: 1}\n", 5,
                     "analyses.tendency.rss", "offset"},
        RejectedCase{"an unknown steerable system",
                     std::string(kGoodString) + "analyses:\n  tendency:\n    rss: {type: pull, at: 1}\n", 5,
                     "analyses.tendency.rss.type", "expected push (push-the-bit: pads) or point"},
        RejectedCase{"a bend on a collar", "string:\n  - {type: collar, od: 8, id: 2.8125, length: 30, bend: 1}\n", 2,
                     "string[0].bend", "unknown key"},
        RejectedCase{"zero bending stiffness factor", std::string(kGoodString) + "model: {bending_stiffness_factor: 0}\n",
                     3, "model.bending_stiffness_factor", "greater than zero"},
        RejectedCase{"huge bending stiffness factor", std::string(kGoodString) + "model: {bending_stiffness_factor: 1e4}\n",
                     3, "model.bending_stiffness_factor", "<= 1000"},
        RejectedCase{"zero friction velocity", std::string(kGoodString) + "model:\n  contact:\n    friction_velocity: 0 m/s\n",
                     5, "model.contact.friction_velocity", "greater than zero"},
        RejectedCase{"friction velocity not a velocity", std::string(kGoodString) + "model:\n  contact: {friction_velocity: 1 rpm}\n",
                     4, "model.contact.friction_velocity", "velocity"},
        RejectedCase{"negative fluid frequency", std::string(kGoodString) + "analyses:\n  transient:\n    fluid_frequency: -2 Hz\n",
                     5, "analyses.transient.fluid_frequency", "greater than zero"},
        RejectedCase{"unknown nested key", "units: field\nstring:\n  - {type: collar, od: 8, idd: 2, length: 30}\n", 3,
                     "string[0].idd", "did you mean 'id'"},
        RejectedCase{"missing key", "units: field\nstring:\n  - {type: collar, od: 8, length: 30}\n", 3,
                     "string[0]", "missing required key 'id'"},
        RejectedCase{"missing string", "name: x\n", 1, "", "missing required key 'string'"},
        RejectedCase{"wrong type", "units: field\nstring:\n  - {type: collar, od: [8], id: 2, length: 30}\n", 3,
                     "string[0].od", "expected a diameter"},
        RejectedCase{"ID >= OD", "units: field\nstring:\n  - {type: collar, od: 6.75, id: 7, length: 30}\n", 3,
                     "string[0].id", "must be smaller than 'od'"},
        RejectedCase{"zero length", "units: field\nstring:\n  - {type: collar, od: 6.75, id: 2, length: 0}\n", 3,
                     "string[0].length", "greater than zero"},
        RejectedCase{"negative diameter", "units: field\nstring:\n  - {type: collar, od: -6.75, id: 2, length: 3}\n", 3,
                     "string[0].od", "greater than zero"},
        RejectedCase{"wrong unit dimension", "string:\n  - {type: collar, od: 12.5 ppg, id: 2, length: 3}\n", 2,
                     "string[0].od", "density"},
        RejectedCase{"unknown component type", "string:\n  - {type: colar, od: 1, id: 0.5, length: 3}\n", 2,
                     "string[0].type", "did you mean 'collar'"},
        RejectedCase{"survey MD backwards", kWellHead + "    - [900, 12, 0]\n  hole: 12.25\n" + kGoodString, 6,
                     "well.survey[2]", "strictly increase"},
        RejectedCase{"inclination out of range", kWellHead + "    - [2000, 181, 0]\n  hole: 12.25\n" + kGoodString, 6,
                     "well.survey[2]", "between 0 and 180"},
        RejectedCase{"negative hole friction", kWellHead + "  hole: [{diameter: 12.25, friction: -0.1}]\n" + kGoodString, 6,
                     "well.hole[0].friction", "friction coefficient from 0 to 2"},
        RejectedCase{"hole section cased not a bool", kWellHead + "  hole: [{diameter: 12.25, cased: maybe}]\n" + kGoodString,
                     6, "well.hole[0].cased", "expected true or false"},
        RejectedCase{"hole smaller than string", kWellHead + "  hole: 7.5\n" + kGoodString, 8, "string[0]",
                     "does not fit the hole"},
        RejectedCase{"bit beyond survey", kWellHead + "  hole: 12.25\n  bit_md: 1200\n" + kGoodString, 7,
                     "well.bit_md", "beyond the last survey station"},
        RejectedCase{"unreadable survey file", "units: field\nwell:\n  survey_file: no-such.csv\n  hole: 12.25\n" +
                                                   std::string(kGoodString), 3, "well.survey_file",
                     "cannot read the survey file"},
        RejectedCase{"unknown unit", "string:\n  - {type: collar, od: 8 furlong, id: 0, length: 3}\n", 2,
                     "string[0].od", "furlong"},
        RejectedCase{"bad units system", "units: imperial\n" + std::string(kGoodString), 1, "units",
                     "expected SI or field"},
        RejectedCase{"load off the string", std::string(kGoodString) + "loads:\n  - {at: 40, force: [0, 1, 0]}\n", 4,
                     "loads[0].at", "off the string"},
        RejectedCase{"bad dof", std::string(kGoodString) + "supports:\n  - {at: 0, fix: [x, w]}\n", 4,
                     "supports[0].fix[1]", "unknown degree of freedom 'w'"},
        RejectedCase{"invalid yaml", "string: [\n  - {", 2, "", "not valid YAML"},
        RejectedCase{"bad mode kind", std::string(kGoodString) + "analyses:\n  modes: {kind: bending}\n", 4,
                     "analyses.modes.kind", "lateral"},
        RejectedCase{"campbell without gyroscopic", std::string(kGoodString) + "analyses:\n  modes: {campbell: {to: 250}}\n",
                     4, "analyses.modes.campbell", "needs 'gyroscopic: true'"},
        RejectedCase{"gyroscopic axial modes", std::string(kGoodString) + "analyses:\n  modes: {kind: axial, gyroscopic: true}\n",
                     4, "analyses.modes.gyroscopic", "kind all or lateral"},
        RejectedCase{"campbell range reversed",
                     std::string(kGoodString) + "analyses:\n  modes: {gyroscopic: true, campbell: {from: 100, to: 50}}\n", 4,
                     "analyses.modes.campbell.to", "above 'from'"},
        RejectedCase{"spectral radius above 1", std::string(kGoodString) + "analyses:\n  transient: {rho_infinity: 1.5}\n",
                     4, "analyses.transient.rho_infinity", "between 0 and 1"},
        RejectedCase{"negative vtk frames", std::string(kGoodString) + "analyses:\n  transient: {vtk_frames: -1}\n", 4,
                     "analyses.transient.vtk_frames", "between 0 and 10000 frames"},
        RejectedCase{"fractional vtk frames", std::string(kGoodString) + "analyses:\n  transient: {vtk_frames: 2.5}\n",
                     4, "analyses.transient.vtk_frames", "a whole number"},
        RejectedCase{"bad transient start", std::string(kGoodString) + "analyses:\n  transient: {start: rest}\n", 4,
                     "analyses.transient.start", "'equilibrium' or 'reference'"},
        RejectedCase{"initial load off the string",
                     std::string(kGoodString) + "analyses:\n  transient:\n    initial_loads:\n      - {at: 45, force: [0, 1, 0]}\n",
                     6, "analyses.transient.initial_loads[0].at", "off the string"},
        RejectedCase{"static below kinetic friction",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {law: friction, static_torque: 2000,\n"
                                                "               kinetic_torque: 2500}\n",
                     5, "analyses.transient.bit_rock.static_torque", "must exceed the kinetic one"},
        RejectedCase{"unknown bit-rock law",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {law: drag}\n", 5,
                     "analyses.transient.bit_rock.law", "'detournay' or 'friction'"},
        RejectedCase{"Detournay without specific energy",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {law: detournay, cutting_ratio: 0.6}\n",
                     5, "analyses.transient.bit_rock", "missing required key 'specific_energy'"},
        RejectedCase{"friction key in a Detournay law",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {law: detournay, specific_energy: 9000,\n"
                                                "               cutting_ratio: 0.6, static_torque: 1}\n",
                     6, "analyses.transient.bit_rock.static_torque", "unknown key 'static_torque'"},
        RejectedCase{"bottom contact under Detournay's law",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {law: detournay, specific_energy: 9000,\n"
                                                "               cutting_ratio: 0.6, bottom: {}}\n",
                     6, "analyses.transient.bit_rock.bottom", "does not go with law 'detournay'"},
        RejectedCase{"bottom motion without a frequency",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {bottom: {motion: {amplitude: 1}}}\n",
                     5, "analyses.transient.bit_rock.bottom.motion", "missing required key 'frequency'"},
        RejectedCase{"negative bottom damping",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {bottom: {damping_ratio: -0.1}}\n",
                     5, "analyses.transient.bit_rock.bottom.damping_ratio", "0 or more"},
        RejectedCase{"misspelt bottom key",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {bottom: {stifness: 1e6}}\n",
                     5, "analyses.transient.bit_rock.bottom.stifness", "did you mean 'stiffness'"},
        RejectedCase{"side cutting of no resistance",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {side_cutting: {resistance: 0}}\n",
                     5, "analyses.transient.bit_rock.side_cutting.resistance", "greater than zero"},
        RejectedCase{"bit-rock section with nothing in it",
                     std::string(kGoodString) + "analyses:\n  transient:\n    bit_rock: {stick_speed: 1}\n",
                     5, "analyses.transient.bit_rock", "expected a 'law'"},
        RejectedCase{"top drive with speed and torque",
                     std::string(kGoodString) + "analyses:\n  transient:\n    top_drive: {rpm: 100, torque: 5000}\n",
                     5, "analyses.transient.top_drive", "not both"},
        RejectedCase{"top drive without a speed", std::string(kGoodString) + "analyses:\n  transient: {top_drive: {ramp: 2}}\n",
                     4, "analyses.transient.top_drive", "no speed"},
        RejectedCase{"negative ramp", std::string(kGoodString) + "analyses:\n  transient: {top_drive: {rpm: 60, ramp: -1}}\n",
                     4, "analyses.transient.top_drive.ramp", "must not be negative"},
        RejectedCase{"block without a setting", std::string(kGoodString) + "analyses:\n  transient: {block: {}}\n",
                     4, "analyses.transient.block", "neither 'velocity' nor 'hook_load'"},
        RejectedCase{"block line of no stiffness",
                     std::string(kGoodString) + "analyses:\n  transient: {block: {velocity: 1, stiffness: 0}}\n", 4,
                     "analyses.transient.block.stiffness", "greater than zero"},
        RejectedCase{"block line with a hook load",
                     std::string(kGoodString) + "analyses:\n  transient: {block: {hook_load: 10, stiffness: 1e5}}\n", 4,
                     "analyses.transient.block.stiffness", "goes with a block 'velocity'"},
        RejectedCase{"unknown drive key", std::string(kGoodString) + "analyses:\n  transient: {top_drive: {rpms: 60}}\n",
                     4, "analyses.transient.top_drive.rpms", "did you mean 'rpm'"},
        RejectedCase{"string longer than well", kWellHead + "  hole: 12.25\nstring:\n  - {type: pipe, od: 5, id: 4, length: 2000}\n",
                     8, "string", "longer than the well"},
        // The case_file fuzz target's bounds (fuzz/README.md): cases that read, and then would not fit in memory.
        RejectedCase{"string of 3e8 bodies", "string:\n  - {type: collar, od: 0.2, id: 0.07, length: 1e9}\n", 2,
                     "string", "into 3.33e+08 bodies"},
        RejectedCase{"string of 1e303 m", "string:\n  - {type: collar, od: 0.2, id: 0.07, length: 1e300, count: 1000}\n", 2,
                     "string", "at most 20000; give a longer body_length"},
        RejectedCase{"trajectory table of 1e15 rows",
                     "well:\n  survey:\n    - [0, 0, 0]\n    - [1e9, 0, 0]\n  hole: 0.3\n  output_step: 1e-6\n" +
                         std::string(kGoodString),
                     6, "well.output_step", "the trajectory table would have 1e+15 rows"},
        // Found by fuzz/case_file: five times 4444444444 in, 5.6e8 m, read; the body could not be reduced.
        RejectedCase{"diameter of 5.6e8 m", "string:\n  - {type: pipe, od: 5 4444444444in, id: 4.276 in, length: 8}\n", 2,
                     "string[0].od", "expected a diameter of at most 100 m"}),
    [](const ::testing::TestParamInfo<RejectedCase>& info) {
      std::string name = info.param.label;
      for (char& ch : name) if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

TEST(CaseReader, SurveyFileRelativeToTheCaseWithHeader) {
  const auto directory = std::filesystem::temp_directory_path() / "drillflex-io-test";
  std::filesystem::create_directories(directory);
  {
    std::ofstream csv(directory / "survey.csv");
    csv << "md_ft,inc_deg,azi_deg\n0,0,0\n1000,0,0\n2000,20,90\n";
    std::ofstream yaml(directory / "case.yaml");
    yaml << "units: field\nwell:\n  survey_file: survey.csv\n  hole: 12.25\n" << kGoodString;
  }
  const Case c = ReadCase((directory / "case.yaml").string());
  ASSERT_EQ(c.well->survey.size(), 3u);
  EXPECT_NEAR(c.well->survey[2].md, 2000 * kFt, 1e-9);
  EXPECT_NEAR(c.well->survey[2].azimuth, kPi / 2, 1e-12);
  EXPECT_NEAR(c.well->bit_md, 2000 * kFt, 1e-9);
}

TEST(CaseReader, SurveyFileErrorsNameTheCsvLine) {
  const auto directory = std::filesystem::temp_directory_path() / "drillflex-io-test2";
  std::filesystem::create_directories(directory);
  {
    std::ofstream csv(directory / "survey.csv");
    csv << "md,inc,azi\n0,0,0\n1000,0,0\n900,20,90\n";
    std::ofstream yaml(directory / "case.yaml");
    yaml << "units: field\nwell:\n  survey_file: survey.csv\n  hole: 12.25\n" << kGoodString;
  }
  try {
    ReadCase((directory / "case.yaml").string());
    FAIL() << "accepted a survey whose MD goes backwards";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("survey.csv:4"));
    EXPECT_THAT(error.what(), HasSubstr("strictly increase"));
  }
}

TEST(CaseReader, SurveyFileMustBeARegularFile) {
  // A directory opens as an empty stream, and /dev/zero or a FIFO would be read without end.
  const auto directory = std::filesystem::temp_directory_path() / "drillflex-io-test3";
  std::filesystem::create_directories(directory / "survey.csv");
  for (const std::string given : {"survey.csv", "/dev/zero"}) {
    try {
      ParseCase("units: field\nwell:\n  survey_file: " + given + "\n  hole: 12.25\n" + kGoodString, "a.yaml",
                directory.string());
      FAIL() << "read the survey file " << given;
    } catch (const InputError& error) {
      EXPECT_EQ(error.key_path(), "well.survey_file");
      EXPECT_THAT(error.what(), HasSubstr("not a regular file"));
    }
  }
}

TEST(CaseReader, UnitsWithTheirOwnUnitOverrideTheSystem) {
  const Case si = ParseCase("string:\n  - {type: collar, od: 8 in, id: 2.8125 in, length: 30 ft}\n", "a.yaml");
  const Case field = ParseCase("units: field\nstring:\n  - {type: collar, od: 8, id: 2.8125, length: 30}\n", "b.yaml");
  EXPECT_DOUBLE_EQ(si.input.string.components[0].outer_diameter, field.input.string.components[0].outer_diameter);
  EXPECT_DOUBLE_EQ(si.input.string.components[0].length, field.input.string.components[0].length);
}

}  // namespace case_reader_test
}  // namespace drillflex::io
