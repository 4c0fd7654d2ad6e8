// The drives at the top of the string in a transient run (method.md §8, surface conditions): the
// top drive turns the top at a set speed (ramped up from rest) or applies a set torque; the block
// moves the top axially at a set velocity (ramped) or holds it by a set hook load. Plain data, SI.
//
// Signs, as a drilling engineer reads them: a speed or torque is positive clockwise looking
// down-hole (right-hand about the down-hole axis, i.e. about −x of the string frame); the block
// velocity is positive pulling out (up-hole, +x of the string frame); the hook load is the tension
// the hook holds (pulling up-hole; a negative one pushes the top down-hole).
#pragma once

#include <algorithm>
#include <optional>

namespace drillflex::model {

// A quantity ramped linearly from 0 at t = 0 to `target` at t = ramp_time, then held:
//   value(t) = target · min(t / ramp_time, 1),
//   integral(t) = ∫₀ᵗ value = target t² / (2 ramp_time) for t < ramp_time, else target (t − ramp_time/2).
// ramp_time = 0 is a step at t = 0.
struct LinearRamp {
  double target = 0.0;
  double ramp_time = 0.0;  // s, ≥ 0

  double Value(double t) const {
    if (t <= 0.0) return ramp_time > 0.0 ? 0.0 : target;
    return t < ramp_time ? target * t / ramp_time : target;
  }
  double Integral(double t) const {
    if (t <= 0.0) return 0.0;
    return t < ramp_time ? 0.5 * target * t * t / ramp_time : target * (t - 0.5 * ramp_time);
  }
};

enum class TopDriveMode {
  Speed,   // the top's spin follows the angle ∫ speed dt through a stiff torsional spring
  Torque,  // a set torque on the top
};

struct TopDrive {
  TopDriveMode mode = TopDriveMode::Speed;
  LinearRamp setting;  // rad/s (Speed) or N·m (Torque), clockwise looking down-hole
};

enum class BlockMode {
  Velocity,  // the top's axial position follows ∫ velocity dt through a stiff axial spring
  HookLoad,  // a set axial force at the top (tension; negative: compression, pushing the top down-hole)
};

struct BlockDrive {
  BlockMode mode = BlockMode::Velocity;
  LinearRamp setting;  // m/s up-hole (Velocity) or N (HookLoad)
  // The target is operation.hook_load, the hook's tension at the surface: the block then holds the
  // model's top with it less the string above's weight (analyses::TransientModelInput).
  bool at_surface = false;
  // Velocity only. The axial stiffness of what lies between the moving block and the top, N/m: the
  // drill line and derrick of a rig, the screw, frame and load cell of a test rig. Unset: as stiff as
  // the hook support the block replaces (the top follows the block to within its force over ~1e10 N/m).
  std::optional<double> line_stiffness = std::nullopt;
  // The top's axial displacement from its reference at the start equilibrium, m (up-hole +;
  // analyses::PlaceBlockAtStart): a line softer than the hold starts stretched by as much as the
  // hold was, so the top carries the same force at t = 0 and nothing jumps.
  double start_top_displacement = 0.0;
};

// The default ramp of a top-drive speed when the case gives none, s.
inline constexpr double kDefaultTopDriveRamp = 2.0;

}  // namespace drillflex::model
