// Reads the drives of `analyses.transient` (model/drives.hpp):
//   top_drive: {rpm: 120, ramp: 2 s}   or   {torque: 15000 ft*lbf, ramp: 1 s}
//   block:     {velocity: 0.5 m/s, ramp: 1 s}   or   {hook_load: 250 klbf, ramp: 1 s}
// A top drive without rpm or torque turns at operation.rpm; without `top_drive` a transient whose
// operation has rpm > 0 gets that speed drive with the default ramp. A block without velocity or
// hook_load holds operation.hook_load (a tension, ≥ 0: settings_section.cpp); the block's own
// hook_load may be negative, a compression: the block pushes the top down-hole with that force.
#include <fmt/format.h>

#include "io/case_sections.hpp"

namespace drillflex::io {

using units::Quantity;

namespace {

double RampTime(const YamlView& node, double default_ramp) {
  const double ramp = node.QuantityOr("ramp", Quantity::Time, default_ramp);
  if (ramp < 0.0) node.Child("ramp").Fail("the ramp time must not be negative (0: a step at t = 0)");
  return ramp;
}

}  // namespace

model::TopDrive ReadTopDrive(const YamlView& node, const model::Operation& operation) {
  node.ExpectMap("a top drive {rpm, ramp} or {torque, ramp}");
  node.AllowOnlyKeys({"rpm", "torque", "ramp"});
  if (node.Has("rpm") && node.Has("torque")) {
    node.Fail("give the top drive either 'rpm' (a speed it ramps to) or 'torque' (a torque it applies), not both");
  }
  model::TopDrive drive;
  if (node.Has("torque")) {
    drive.mode = model::TopDriveMode::Torque;
    drive.setting.target = node.Quantity("torque", Quantity::Moment);
    drive.setting.ramp_time = RampTime(node, 0.0);
    return drive;
  }
  drive.mode = model::TopDriveMode::Speed;
  if (node.Has("rpm")) {
    drive.setting.target = node.Quantity("rpm", Quantity::RotarySpeed);
  } else if (operation.rotary_speed != 0.0) {
    drive.setting.target = operation.rotary_speed;
  } else {
    node.Fail("the top drive has no speed: give 'rpm' (or 'torque') here, or 'rpm' under 'operation'");
  }
  drive.setting.ramp_time = RampTime(node, model::kDefaultTopDriveRamp);
  return drive;
}

model::BlockDrive ReadBlock(const YamlView& node, const model::Operation& operation) {
  node.ExpectMap("the block {velocity, ramp, stiffness} or {hook_load, ramp}");
  node.AllowOnlyKeys({"velocity", "hook_load", "ramp", "stiffness"});
  if (node.Has("velocity") && node.Has("hook_load")) {
    node.Fail("give the block either 'velocity' (+ pulling out, - running in) or 'hook_load', not both");
  }
  model::BlockDrive block;
  if (node.Has("velocity")) {
    block.mode = model::BlockMode::Velocity;
    block.setting.target = node.Quantity("velocity", Quantity::Velocity);
    block.setting.ramp_time = RampTime(node, model::kDefaultTopDriveRamp);
    block.line_stiffness = node.OptionalPositive("stiffness", Quantity::Stiffness);
    return block;
  }
  if (node.Has("stiffness")) {
    node.Child("stiffness").Fail("a hook load is a set force: 'stiffness' (the line's) goes with a block 'velocity'");
  }
  block.mode = model::BlockMode::HookLoad;
  if (node.Has("hook_load")) {
    block.setting.target = node.Quantity("hook_load", Quantity::Force);
  } else if (operation.hook_load) {
    block.setting.target = *operation.hook_load;
    block.at_surface = true;
  } else {
    node.Fail("the block has neither 'velocity' nor 'hook_load' (nor is there 'hook_load' under 'operation')");
  }
  block.setting.ramp_time = RampTime(node, 0.0);
  return block;
}

}  // namespace drillflex::io
