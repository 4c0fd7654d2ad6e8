// Builds the SystemModel of a string: components -> uniform sections -> flexible bodies (each at
// most `body_length`, split evenly) -> Craig–Bampton reductions (cached by section) -> couplings
// between consecutive bodies, supports, loads and gravity. Without a well the string lies straight
// along +x from the origin (the bit end at x = 0), the string frame is the global frame.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cms/reduction_cache.hpp"
#include "fe/material.hpp"
#include "model/bit_rock.hpp"
#include "model/drives.hpp"
#include "model/spring_elements.hpp"
#include "model/string_config.hpp"
#include "model/wall_contact.hpp"
#include "model/system_model.hpp"
#include "well/trajectory.hpp"

namespace drillflex::model {

struct ModelInput {
  StringConfig string;
  ModelSettings settings;
  std::map<std::string, fe::Material> materials;
  std::vector<Support> supports;
  std::vector<Load> loads;
  // Loads (as `loads`) that act only where the parameter block's initial_load_factor says (a
  // transient's start equilibrium: its initial_loads); 0 in every analysis by default.
  std::vector<Load> initial_loads;
  double gravity = 0.0;              // m/s², along global +z
  std::optional<FluidConfig> fluid;
  // The well the string lies in (bit at bit_md); none: straight along +x from the origin.
  std::optional<well::Trajectory> trajectory;
  std::vector<well::HoleSection> hole;  // with a trajectory: wall contact at every node
  double bit_md = 0.0;
  Operation operation;  // WOB and torque on bit act at the bit (s = 0)
  // The string's motion for the wall friction of a static analysis (torque and drag): with it, every
  // wall contact's friction follows this prescribed sliding (model/wall_contact.hpp); without it,
  // the friction follows the state's velocities (none at rest).
  std::optional<PrescribedSliding> static_sliding;
  // The rock's reaction on the bit node as a law of its motion (model/bit_rock.hpp; a transient's
  // `bit_rock`); a radius of 0 is taken as half the OD of the first component. Its law replaces the
  // operation's torque on bit, and Detournay's law or a bottom contact its WOB; side cutting
  // replaces the lateral hold of the supports at the bit node.
  std::optional<BitRockParameters> bit_rock;
  // The drives at the top node (s = the string length) of a transient run (model/drives.hpp):
  // each replaces the hold of the supports at the top in its direction (the top drive: rx; the
  // block: x), with a spring as stiff as that support (kSupportStiffnessFactor).
  std::optional<TopDrive> top_drive;
  std::optional<BlockDrive> block;
  // Imbalances turning with the string (a transient's `excitations`; model/imbalance_element.hpp).
  std::vector<Imbalance> imbalances;
  // Set (a transient's model): the drilling fluid moves with the bodies sideways, as lumps of lateral
  // mass and damping at their nodes (model/fluid_inertia.hpp), the annulus's C_m and C_v taken at
  // this circular frequency, rad/s (model/lateral_fluid.hpp ComputeNodeFluidTerms; 0: the inviscid
  // C_m and no damping, allowed only for an inviscid fluid or a given C_m). Unset: the model's mass
  // is the steel's, and the linear analyses add the fluid themselves.
  std::optional<double> transient_fluid_frequency;
};

// The supports a string in a well gets when the case gives none (method.md §8, the static BHA
// convention): the bit held laterally at the hole centre with its tilt and axial motion free (it
// carries the WOB as an applied force), and the top held axially by the hook and in torsion by the
// rotary table, free to lie on the wall.
std::vector<Support> DefaultWellSupports(double string_length);

// Coupling stiffness of a body's section (method.md §5): c·(EA/ℓ, 12EI/ℓ³, 12EI/ℓ³, GJ/ℓ, EI/ℓ, EI/ℓ).
Vec6 SectionCouplingStiffness(const Body& body, double factor);

// Buoyed weight per length of a body's section, N/m (method.md §7): g (ρ_s A − ρ_f A_o + ρ_f,i A_i).
double BuoyedWeightPerLength(const Body& body, const ModelInput& input);
// The same for a component's section (tool joints averaged in, as its bodies carry them).
double BuoyedWeightPerLength(const Component& component, const ModelInput& input);

// The buoyed weight along the hole of the string above the model's top, N: its top component
// continued to the surface (MD 0), hanging as a frictionless soft string, w · TVD(top). 0 without a
// trajectory.
double StringAboveWeight(const ModelInput& input);

// The buoyed weight along the hole of the modelled string, N: Σ w (TVD at its bottom − TVD at its
// top) over its components. 0 without a trajectory.
double ModelledStringAxialWeight(const ModelInput& input);

// The WOB a surface hook load leaves on the bit, N: the buoyed weight along the hole of the modelled
// string (Σ w ΔTVD over its components) and of the string above (StringAboveWeight), less the hook
// load. Frictionless soft string: in the static model a string at rest carries no friction and a
// rotating one's acts around it, so the axial balance is exact there.
double WeightOnBitFromHookLoad(const ModelInput& input, double hook_load);

// The component at a distance s (m) from the bit: at a connection the lower one, except on top of
// the bit (the upper one).
const Component& ComponentAt(const StringConfig& string, double s);

// The diameter that touches the wall at a distance s (m) from the bit: blade, tool joint or body
// (the geometry; the contact circles of the model are model/contact_circles.hpp).
double ContactDiameterAt(const StringConfig& string, double s);

// The radial clearance at a distance s (m) from the bit in the input's well (m): the hole's radius at
// that MD less the contact circle's (ContactDiameterAt); none without a well and hole.
std::optional<double> RadialClearanceAt(const ModelInput& input, double s);

// The built-in relative rotation of the coupling at `s` (m from the bit): a motor's bent housing
// when its bend sits there (bend angle about x × d, d the toolface direction in the string frame,
// the bit side pointing toward d), else the identity. Bodies are cut at every bend.
Mat3 BentHousingRotation(const StringConfig& string, double s);

// What the builder made, beside the model itself: where each support and load went.
struct BuiltModel {
  SystemModel system;
  std::vector<int> support_elements;  // element index of each case support
  std::vector<int> contact_elements;  // element index of each wall contact, from the bit upward
  int top_drive_element = -1;         // element index of the top drive (-1: none)
  int block_element = -1;             // element index of the block (-1: none)
  double force_scale = 0.0;           // a typical applied force, N (Newton tolerance)
  int bit_rock_element = -1;          // element index of the bit-rock interaction (−1: none)
  int bit_bottom_element = -1;        // element index of the bit's bottom contact (−1: none)
  int bit_side_element = -1;          // element index of the bit's side cutting (−1: none)
  int string_above_element = -1;      // element index of the pipe above the top (−1: none)
};

// The wall contacts' friction regularization velocity v_ε (method.md §6: below it the friction is
// viscous) by default, per contact: v_ε = Ω_ε R_c, R_c the contact circle's radius. The paper
// (Pogorelov et al., ESDA 2012, §2.3) sets v_ε "equal to [...] where [...] is the characteristic size
// (radius) of contacting bodies"; its factor is lost from the text we have. Taken (drillflex's own
// choice, not the paper's): Ω_ε = 0.01 rad/s (0.1 rpm), the bit-rock law's stick speed
// (model/bit_rock.hpp kDefaultStickSpeed): a section
// turning slower than 0.1 rpm on the wall slides viscously, whatever its size. For the 8 in collar of
// V8 that is 1.02 mm/s, the 1 mm/s drillflex used for every contact before. The case's
// `model.contact.friction_velocity` replaces it (ContactSettings::friction_velocity).
inline constexpr double kFrictionRegularizationSpin = kDefaultStickSpeed;  // Ω_ε, rad/s

// Damping ratio of the coupling and support springs, with the element masses of the joined bodies.
inline constexpr double kCouplingDampingRatio = 0.05;
// Supports are this many times stiffer than a coupling of the same section.
inline constexpr double kSupportStiffnessFactor = 10.0;

// The stiffness of the bit's bottom contact, N/m: the case's, or by default as stiff as the
// model's supports (kSupportStiffnessFactor × c·EA/ℓ of the bit body: the bottom is the string's
// axial support at the bit; model/bit_bottom.hpp).
double BitBottomStiffness(const BitBottomParameters& bottom, const Body& bit, const ModelSettings& settings);

BuiltModel BuildSystemModel(const ModelInput& input, cms::ReductionCache& cache);

}  // namespace drillflex::model
