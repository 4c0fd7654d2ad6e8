// Where things are along a string and what it weighs: the component and the contact diameter at a
// distance from the bit, the radial clearance in the well, a bent housing's built-in rotation, and the
// buoyed weights the static balance and the pipe above take. Queries of the input alone (no model).
#pragma once

#include <optional>

#include "core/types.hpp"
#include "model/body.hpp"
#include "model/model_input.hpp"

namespace drillflex::model {

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

}  // namespace drillflex::model
