// What analyses vary through a built model instead of building it again (../shared/spec/
// td-speed.md "Build once, vary parameters"): one model of a string serves the static's load
// stepping and friction continuation, the roadmap's pick-up, slack-off, rotating and on-bottom runs
// at every friction factor, the buckling load path and the transient's start. Every element reads
// the block from its ElementState (model/force_element.hpp). A default block is the model as it was
// built from its ModelInput (the case); a bare number is a load factor.
#pragma once

#include <optional>

namespace drillflex::model {

// A prescribed motion of the string for the friction direction of a static torque-and-drag run
// (model/wall_contact.hpp).
struct PrescribedSliding {
  double axial_speed = 0.0;   // m/s along the string axis; > 0 up-hole (pulling out), < 0 running in
  double rotary_speed = 0.0;  // rad/s about the down-hole tangent t; > 0 clockwise looking down-hole
};

// The wall's Coulomb friction coefficients.
struct WallFriction {
  double axial = 0.0;       // along the hole axis (pulling out, running in)
  double tangential = 0.0;  // around the string (rotating)
};

// Where the wall friction's sliding direction comes from.
enum class SlidingMode {
  kAsBuilt,     // each contact's own: the case's static_sliding (ModelInput), or the state's velocities
  kVelocities,  // the state's velocities (none at rest: no friction in a static)
  kPrescribed,  // LoadParameters::sliding
};

struct LoadParameters {
  LoadParameters(double load = 1.0) : load_factor(load) {}  // NOLINT(google-explicit-constructor)
  LoadParameters(double load, double friction) : load_factor(load), friction_factor(friction) {}

  // Load groups. The load factor scales every applied load (load stepping, buckling's multiplier);
  // each group's factor or value scales or replaces its own part on top of it.
  double load_factor = 1.0;
  double weight_factor = 1.0;        // gravity with the fluid's buoyancy (the buoyed weight)
  double case_load_factor = 1.0;     // the case's point and distributed loads
  double initial_load_factor = 0.0;  // a transient's initial loads: in its start equilibrium only
  std::optional<double> weight_on_bit;  // N, up-hole on the bit; none: the case's
  std::optional<double> torque_on_bit;  // N·m; none: the case's

  // The wall friction: coefficients in open and in cased hole (none: each contact's own, its hole
  // section's or the case's: model/hole_friction.hpp), a factor on them (the continuation from a
  // string at rest to a moving one, static-solver.md §6) and the sliding.
  double friction_factor = 1.0;
  std::optional<WallFriction> open_hole_friction;
  std::optional<WallFriction> cased_hole_friction;
  // The same coefficients in open and cased hole.
  void SetWallFriction(const WallFriction& friction) { open_hole_friction = cased_hole_friction = friction; }
  bool OverridesFriction() const { return open_hole_friction || cased_hole_friction; }
  SlidingMode sliding_mode = SlidingMode::kAsBuilt;
  PrescribedSliding sliding;  // with SlidingMode::kPrescribed

  // Stiffness: the couplings between bodies, and the supports that hold the bit's node (the bit
  // held at the hole centre on bottom; 0 leaves it free, off bottom).
  double coupling_factor = 1.0;
  double bit_support_factor = 1.0;
};

}  // namespace drillflex::model
