// What the builder gives a model that the case does not: the supports of a string in a well, the
// stiffness and damping of its couplings and supports, the wall friction's regularization, the bit's
// bottom stiffness. The builder's parts use them (model/build_parts.hpp); so do analyses that hold a
// support or a coupling to the same standard.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "model/bit_rock.hpp"
#include "model/body.hpp"
#include "model/string_config.hpp"

namespace drillflex::model {

// The supports a string in a well gets when the case gives none (method.md §8, the static BHA
// convention): the bit held laterally at the hole centre with its tilt and axial motion free (it
// carries the WOB as an applied force), and the top held axially by the hook and in torsion by the
// rotary table, free to lie on the wall.
std::vector<Support> DefaultWellSupports(double string_length);

// Coupling stiffness of a body's section (method.md §5): c·(EA/ℓ, 12EI/ℓ³, 12EI/ℓ³, GJ/ℓ, EI/ℓ, EI/ℓ).
Vec6 SectionCouplingStiffness(const Body& body, double factor);

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

// The normal stiffness of a wall contact circle standing for `circle_length` m of string, N/m: the
// wall's stiffness per metre × that length, and at least w ℓ_w / (f c): the stiffness under which the
// weight of its section over ℓ_w sinks it by the fraction f (ContactSettings::penetration_fraction) of
// its radial clearance c (at least kLeastContactClearance). ℓ_w = `carried_length`: for a point
// contact (a stabilizer's blades, a tool joint) about a span of string, kContactWeightSpan; for a
// body's circle its own length (it carries its share of a distributed load). The penalty's penetration is a numerical compliance, not the
// formation's: at 1e8 N/m a metre alone the bundled example's near-bit stabilizer (c = 1/32 in) sank
// 31 % of its clearance and its bit side force was 6 % below the rigid wall's; a 13 in collar's
// stabilizer (c = 0.1 in) sank 150 % and its side force was 41 % low (docs/validation.md V4).
double WallContactStiffness(const ContactSettings& contact, double circle_length, double weight_per_length,
                            double clearance, double carried_length);
// m: the clearance the stiffness floor takes for a tighter contact (1/64 in; a full-gauge blade has 0).
inline constexpr double kLeastContactClearance = 0.0254 / 64.0;
// m: the span of string whose weight a point contact carries, for its stiffness floor (30 ft: a joint).
inline constexpr double kContactWeightSpan = 9.144;

// Damping ratio of the coupling and support springs, with the element masses of the joined bodies.
inline constexpr double kCouplingDampingRatio = 0.05;
// Supports are this many times stiffer than a coupling of the same section.
inline constexpr double kSupportStiffnessFactor = 10.0;

// The stiffness of the bit's bottom contact, N/m: the case's, or by default as stiff as the
// model's supports (kSupportStiffnessFactor × c·EA/ℓ of the bit body: the bottom is the string's
// axial support at the bit; model/bit_bottom.hpp).
double BitBottomStiffness(const BitBottomParameters& bottom, const Body& bit, const ModelSettings& settings);

}  // namespace drillflex::model
