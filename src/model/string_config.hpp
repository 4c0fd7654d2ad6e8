// The drill string, model settings, supports, loads and operating point as a case describes them:
// plain data in SI (m, kg, N, Pa, rad, s). Read by io/, consumed by the model builder.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "fe/fe_kinds.hpp"

namespace drillflex::model {

enum class ComponentType { Bit, Stabilizer, Collar, Hwdp, Pipe, Mwd, Lwd, Jar, Motor, Sub, Crossover };

// API RP 7G's pipe classes: new, or premium (the wall worn uniformly to 80 % of its nominal
// thickness, the bore kept: model/string_limits.hpp RatedSection).
enum class PipeClass { New, Premium };

// One entry of the string list (from the bit upward). `count` repeats it.
struct Component {
  ComponentType type = ComponentType::Collar;
  std::string name;             // as the user called it, or the type name
  double outer_diameter = 0.0;  // m: body OD
  double inner_diameter = 0.0;  // m: bore
  double length = 0.0;          // m: one item (count repeats it)
  std::string material = "steel";
  int count = 1;
  // Stabilizer: blade OD and blade length (m); the blades sit at mid-length by default.
  std::optional<double> blade_diameter;
  std::optional<double> blade_length;
  // Drill pipe and HWDP: tool joints (m); a joint every `joint_spacing` (default one per item).
  std::optional<double> joint_diameter;
  std::optional<double> joint_inner_diameter;
  std::optional<double> joint_length;
  std::optional<double> joint_spacing;
  // Mud motor: bend angle (rad) of the bent housing, its distance from the bit (m), toolface (rad),
  // and the motor speed per flow rate (rad per m³).
  std::optional<double> bend_angle;
  std::optional<double> bend_to_bit;
  std::optional<double> toolface;
  std::optional<double> speed_per_flow;
  std::optional<int> lobes;  // rotor lobes
  // Ratings (model/string_limits.hpp): the minimum yield strength, Pa, from an API grade or given
  // (unset: unknown; the limits then take the lowest grade's for steel), the grade's name ("" for a
  // given yield or none), the class of the body's wall, and the connections' make-up torque, N·m
  // (as given; unset: no torque limit).
  std::optional<double> yield_strength;
  std::string grade;
  PipeClass pipe_class = PipeClass::New;
  std::optional<double> makeup_torque;
  // Drill pipe and HWDP: the tool joints' rotary-shouldered connection ("NC50"), whose API RP 7G make-up
  // torque (model/tool_joint_torque.hpp) is the make-up torque above when none is given; "" none.
  std::string connection;
  int source_line = 0;       // line in the case file, for messages
};

// The largest diameter of a component that can touch the wall: blade, tool joint or body.
double ContactDiameter(const Component& component);

// Tool-joint defaults where a pipe entry does not give them (API RP 7G range 2 joints).
inline constexpr double kDefaultJointSpacing = 9.144;  // m (30 ft): one joint per pipe length
inline constexpr double kDefaultJointLength = 0.4572;  // m (18 in): box plus pin

// Cross-section areas (m²) averaged along a component, tool joints smeared over their
// spacing: the material area sets the mass, the outer and bore areas the displaced and internal fluid.
struct AveragedAreas {
  double material = 0.0;
  double outer = 0.0;
  double bore = 0.0;
};
AveragedAreas AverageAreas(const Component& component);

struct FluidConfig {
  double density = 0.0;                   // kg/m³, annulus
  double viscosity = 0.0;                 // Pa·s
  std::optional<double> internal_density; // kg/m³, inside the string (default: same as annulus)
  double added_mass_coefficient_override = -1.0;  // < 0: from the confinement (method.md §7)
};

struct ContactSettings {
  // The wall's stiffness per metre of string in contact, N/m per m: a contact circle standing for
  // a length l of string (model/contact_lengths.hpp) has k_n = stiffness × l.
  double stiffness = 1.0e8;
  // A contact of small radial clearance c (a stabilizer's blades) is made at least as stiff as its
  // section's weight over 30 ft needs to sink into the wall by this fraction of c (0: the stiffness
  // per metre alone; model/build_defaults.hpp WallContactStiffness).
  double penetration_fraction = 0.02;
  double damping_ratio = 0.1;
  double friction = 0.25;        // tangential (rotating) Coulomb coefficient
  std::optional<double> axial_friction;  // sliding along the hole, default = friction
  // The friction's regularization velocity v_ε, m/s (model/wall_contact.hpp): below it the friction
  // is viscous. Unset: each contact's from its circle's radius, kFrictionRegularizationSpin × R_c
  // (model/builder.hpp; the paper sets v_ε from the characteristic size of the contacting bodies).
  std::optional<double> friction_velocity;
};

// What holds the top of a string in a well sideways when the case gives no supports: the pipe above
// it (model/string_above.hpp), nothing (free to move sideways and to tilt, lying on the wall), or a
// guide (its tilt held along the hole's axis at the top, free to move sideways and to lie on the wall:
// a guided end, the top MADSim and other BHA programs give a BHA cut from its string).
enum class TopCondition { StringAbove, Free, Guided };

struct ModelSettings {
  double body_length = 3.0;      // m, longest flexible body
  int elements_per_body = 10;
  int modes_per_body = 6;        // H: fixed-interface normal modes per body
  double coupling_factor = 1000.0;  // measured: docs/model-study.md
  double structural_damping = 0.01;  // modal damping ratio
  ContactSettings contact;
  fe::MassKind mass = fe::MassKind::kConsistent;
  fe::BeamTheory beam = fe::BeamTheory::kEulerBernoulli;
  bool rotary_inertia = true;  // bending rotary inertia ρI of the beam sections
  // Multiplies every section's bending stiffness E I (not E A, G J or the inertia): the soft-string
  // limit (EI → 0) and sensitivity studies; 1, the sections' own.
  double bending_stiffness_factor = 1.0;
  TopCondition top = TopCondition::StringAbove;
};

// Degrees of freedom in the string frame: x along the string (up-hole), y right, z high side.
enum Dof { kX = 0, kY = 1, kZ = 2, kRx = 3, kRy = 4, kRz = 5 };

struct Support {
  double at = 0.0;                   // m from the bit end
  std::array<bool, 6> fixed{};       // indexed by Dof
  double stiffness_scale = 1.0;      // multiplies the support's stiffness (continuation of releases)
  int source_line = 0;
};

// A point load (at) or a distributed load (from..to), forces and moments in the string frame.
struct Load {
  bool distributed = false;
  double at = 0.0;                   // m, point loads
  double from = 0.0, to = 0.0;       // m, distributed loads
  Vec3 force = Vec3::Zero();         // N (point)
  Vec3 moment = Vec3::Zero();        // N·m (point)
  Vec3 force_per_length = Vec3::Zero();   // N/m (distributed)
  Vec3 moment_per_length = Vec3::Zero();  // N·m/m (distributed)
  int source_line = 0;
};

// An imbalance m·e fixed to the string at `at` (the nearest node), its offset toward the high side
// of the undeformed placement (string frame z): model/imbalance_element.hpp.
struct Imbalance {
  double at = 0.0;  // m from the bit
  double me = 0.0;  // kg·m
};

struct Operation {
  double weight_on_bit = 0.0;   // N, compression at the bit
  double rotary_speed = 0.0;    // surface rotary speed, rad/s
  double torque_on_bit = 0.0;   // N·m
  std::optional<double> flow_rate;  // m³/s
  std::optional<double> hook_load;  // N
};

struct StringConfig {
  std::vector<Component> components;
};

const char* ComponentTypeName(ComponentType type);

// The string's length from the bit to its top, m: Σ length × count.
double StringLength(const StringConfig& string);

}  // namespace drillflex::model
