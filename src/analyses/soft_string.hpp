// The soft-string torque-and-drag model of Johancsik, Friesen & Dawson (SPE 11380, 1984, "Torque
// and drag in directional wells — prediction and measurement"): the hook load and surface torque of
// a string pulled out (pick-up), run in (slack-off) or rotated in a well, from the survey alone in
// one pass from the bit up (no bodies, no solve). The stiff-string static
// (analyses/static_analysis.hpp) is the reference model; this one is the industry's quick estimate
// and a check on it.
//
// The string is cut into elements at every survey station, at every component boundary, at every
// hole section's end (a section's friction: cased or open hole, model/hole_friction.hpp) and at the
// surface (the trajectory's start MD), the top component continued up to it when the string is
// shorter than the bit MD (the string above the surface, when it is longer, is left out). From the
// bit upward, each element of length L (m) with tension T (N, tension positive) at its lower end,
// T = −WOB at the bit, buoyed weight W = w L (w = model::BuoyedWeightPerLength of its component, tool
// joints averaged in), and inclination I and azimuth A (rad) at its lower and upper ends
// (minimum curvature, well::Trajectory), Ī = (I_lower + I_upper)/2, carries (SPE 11380):
//   N  = √( (T ΔA sin Ī)² + (T ΔI + W sin Ī)² )        the wall's normal force on the element, N
//   ΔT = W cos Ī ± μ_a N                               + pick-up, − slack-off, no ± rotating
//   ΔM = μ_t N r                                       rotating only, r = model::ContactDiameter / 2
// and the torque at the bit is the TOB.
//
// Signs: ΔI = I_upper − I_lower and ΔA = A_upper − A_lower (wrapped to (−π, π]) are the changes
// over the element in the direction of the computation, from its lower (deeper) end to its upper end.
// In a build section the inclination grows with MD, so ΔI < 0 there and a tension T > 0 lessens the
// low-side load W sin Ī: tension pulls the string to the inside of a bend (the high side of a build,
// against the weight), compression pushes it to the outside. To first order in the angles N is the
// length of the lateral force the string puts on the wall,
//   N ≈ | T (t_lower − t_upper) + W ĝ⊥ |,
// t the unit tangent down the hole (t_upper − t_lower with tangents pointing up the string, from the
// bit), ĝ⊥ = ĝ − (ĝ·t̄) t̄ the part of the unit gravity vector normal to the hole: with
// t_lower − t_upper ≈ −ΔI h − ΔA sin Ī r (h the high side, r the right) and ĝ⊥ = −sin Ī h, its high-side
// component is −(T ΔI + W sin Ī) and its right component −T ΔA sin Ī.
//
// Azimuth at a vertical end (sin I < 1e-9): undefined, taken as the other end's (the minimum-curvature
// arc leaving or reaching vertical lies in the vertical plane of its inclined end's azimuth), and 0 when
// both are vertical. The formula is first order in ΔI and ΔA: through a turn near vertical (large ΔA
// at small sin Ī) it needs stations close enough that ΔA stays small, as Johancsik's survey tables had.
//
// Assumptions (SPE 11380): the string is a cable — no bending stiffness, so it follows the hole's
// axis and touches the wall continuously on the side its lateral load points to (the low side, or
// the inside of a bend under tension); Coulomb friction, μ_a against axial sliding and μ_t against
// rotation, with no combined motion (pick-up and slack-off slide without rotating and carry no
// friction torque; rotating carries no axial friction); the fluid acts only through buoyancy. Left
// out: the stiffness of the BHA and of the pipe in sharp doglegs (the stiff-string static has it),
// the clearance and the contact at tool joints and blades only (r is the contact radius but N is
// spread over the element), buckling under compression (its extra wall force, Mitchell's helix),
// viscous drag and pressure-area effects of the flow, the helical path of combined motion (rotating
// while tripping), and the climb of a rotating string up the wall: its friction then carries part of
// the lateral load, N = w sin I / √(1 + μ_t²) in a straight hole, 3 % less torque at μ_t = 0.25 than
// this model's (docs/validation.md V7; the stiff-string static has it).
#pragma once

#include <optional>
#include <vector>

#include "model/builder.hpp"
#include "model/load_parameters.hpp"

namespace drillflex::analyses {

// Pulling out (pick-up), running in (slack-off), or rotating in place (off or on bottom).
enum class SoftStringMotion { PickUp, SlackOff, Rotating };

struct SoftStringOperation {
  SoftStringMotion motion = SoftStringMotion::Rotating;
  // In open hole (everywhere when no hole section is cased):
  double axial_friction = 0.0;       // μ_a along the hole (pick-up, slack-off), ≥ 0
  double tangential_friction = 0.0;  // μ_t around the string (rotating: torque), ≥ 0
  double weight_on_bit = 0.0;        // N, compression at the bit (0 off bottom; < 0 pulls the bit)
  double torque_on_bit = 0.0;        // N·m, the torque at the bit (carried in every motion)
  // > 0: the elements between the cuts are further split evenly into pieces no longer than this (m),
  // so that the result does not depend on how far apart the survey's stations are (the scheme takes
  // each element's lower-end tension and mean inclination: first order in its length). 0: the
  // cuts alone, Johancsik's own elements.
  double max_element_length = 0.0;
  // Rotating: the string climbs the wall until the friction carries part of its lateral load L, so
  // that the wall's normal and friction forces together balance it, N √(1 + μ_t²) = L, and the
  // torque is μ_t L r / √(1 + μ_t²) (the stiff string's static has the climb; docs/validation.md V7).
  // False: Johancsik's N = L.
  bool wall_climb = false;
  // In the hole sections marked cased: these coefficients; none: each cased section's own (its
  // `friction`, else the case's model.contact: model/hole_friction.hpp).
  std::optional<model::WallFriction> cased_friction = std::nullopt;
};

// One element end, from the bit upward.
struct SoftStringStation {
  double s = 0.0;             // m from the bit along the string
  double md = 0.0;            // m, measured depth
  double axial_force = 0.0;   // N, tension positive
  double torque = 0.0;        // N·m, positive the rig's sense (clockwise looking down-hole)
  double normal_force = 0.0;  // N, the wall's on the element below this station (0 at the bit)
};

struct SoftStringResult {
  std::vector<SoftStringStation> stations;  // bit first, surface last
  double hook_load = 0.0;                   // N, tension at the surface (the trajectory's start MD)
  double surface_torque = 0.0;              // N·m
};

// The soft-string axial force and torque along `input`'s string in its well: `input.well`, the
// string from the bit upward with the bit at `input.bit_md`, its materials, fluid and gravity (the
// buoyed weight: model::BuoyedWeightPerLength). `input.operation` is not read: `operation` gives the
// motion, friction factors, WOB and TOB. Throws InputError (key "well") without a trajectory, with a
// bit MD not below its start ("well.bit_md"), "string" for no components, and
// "string[i].material" for a material `input.materials` lacks; LogicError for a negative or
// non-finite friction factor or a non-finite WOB or TOB (the caller checks those).
SoftStringResult ComputeSoftString(const model::ModelInput& input, const SoftStringOperation& operation);

}  // namespace drillflex::analyses
