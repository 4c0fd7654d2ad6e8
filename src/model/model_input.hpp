// What a model is built from (model/builder.hpp BuildSystemModel): the string, the model's settings,
// materials, supports and loads, the fluid, the well and the operation; SI throughout. io/ makes it
// from a case (io/model_input.hpp), the analyses vary copies of it.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fe/material.hpp"
#include "model/bit_rock.hpp"
#include "model/drives.hpp"
#include "model/load_parameters.hpp"
#include "model/spring_elements.hpp"
#include "model/string_config.hpp"
#include "model/wellbore.hpp"

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
  // The well the string lies in (bit at bit_md), held once and shared read-only by the model built
  // from it (its wall contacts) and the analyses; none: straight along +x from the origin. With a
  // hole (not empty): wall contact at every node.
  std::shared_ptr<const Wellbore> well;
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

}  // namespace drillflex::model
