// Two-node 3-D beam element along its local x-axis, 6 DOF per node in the order
//   (u, v, w, θx, θy, θz) of node 1, then the same of node 2 (12 × 12 matrices).
// Sign convention (right-handed, small rotations): θz = +dv/dx (bending in the x-y plane) and
// θy = −dw/dx (bending in the x-z plane). The x-z blocks are therefore the x-y blocks with the
// rotation DOFs sign-flipped: B_xz = S B_xy S, S = diag(1, −1, 1, −1).
// Round sections only (the same I about y and z).
// References: J. S. Przemieniecki, "Theory of Matrix Structural Analysis" (1968): stiffness with
// shear deformation, consistent mass with shear and rotary inertia, geometric stiffness; the
// shear-dependent interpolation is the one of Friedman & Kosmatka, Comput. Struct. 47 (1993) 473.
// Φ = 12 E I / (κ G A L²) is the shear parameter; Φ = 0 gives the Euler–Bernoulli element with
// Hermite cubics. tests/fe/beam_element_test.cpp checks every closed form against Gauss
// quadrature of that interpolation.
#pragma once

#include <Eigen/Core>

#include "fe/fe_kinds.hpp"
#include "fe/material.hpp"
#include "fe/section.hpp"

namespace drillflex::fe {

using Mat12 = Eigen::Matrix<double, 12, 12>;

// Rotary inertia of a lumped node (element-level choice, see ElementLumpedMass).
enum class LumpedRotaryInertia {
  kSection,            // ρ J L/2 (torsion), ρ I L/2 (bending): the cross-sections' own inertia
  kSectionAndSegment,  // plus (ρA + m_lat)(L/2)³/3 on θy, θz: the half-segment's mass moment
};

// Everything a uniform element needs. SI units.
struct BeamElementProperties {
  double length = 0.0;                   // L, m
  double area = 0.0;                     // A, m²
  double second_moment = 0.0;            // I about y and z, m⁴
  double polar_moment = 0.0;             // J, m⁴
  double youngs_modulus = 0.0;           // E, Pa
  double shear_modulus = 0.0;            // G, Pa
  double density = 0.0;                  // ρ, kg/m³
  double shear_coefficient = 1.0;        // κ (Timoshenko only)
  double lateral_mass_per_length = 0.0;  // extra mass moving with v and w only (fluid), kg/m
  bool bending_rotary_inertia = true;  // ρ I terms of θy, θz (false: Euler–Bernoulli inertia)
  // Multiplies the bending stiffness E I only (not E A, G J or the rotary inertia ρ I): the string's
  // soft-string limit EI → 0 and sensitivity studies. 1: the section's own.
  double bending_stiffness_factor = 1.0;

  // The bending rigidity the element bends with, E I × bending_stiffness_factor, N·m².
  double bending_rigidity() const { return youngs_modulus * second_moment * bending_stiffness_factor; }
};

// Properties of an element of length `length` cut from a section of a material.
BeamElementProperties MakeElementProperties(const HollowSection& section, const Material& material,
                                            double length);

// Φ = 12 E I / (κ G A L²) for Timoshenko, 0 for Euler–Bernoulli.
double ShearParameter(const BeamElementProperties& properties, BeamTheory theory);

// Elastic stiffness: axial EA/L, torsion GJ/L, bending EI/((1+Φ)L³)·[12, 6L, −12, 6L; …].
Mat12 ElementStiffness(const BeamElementProperties& properties, BeamTheory theory);

// Consistent mass: axial ρAL/6·[2 1; 1 2], torsion ρJL/6·[2 1; 1 2], bending translation
// (ρA + m_lat) ∫NᵀN and rotary inertia ρI ∫N_θᵀN_θ with the element's own (shear-dependent)
// interpolation (Przemieniecki 1968).
Mat12 ElementConsistentMass(const BeamElementProperties& properties, BeamTheory theory);

// Lumped (diagonal) mass: half the element's mass on each node, ρAL/2 on u and
// (ρA + m_lat)L/2 on v, w; rotary inertia per `rotary` (bending terms only when
// bending_rotary_inertia is set; the torsional ρJL/2 always).
Mat12 ElementLumpedMass(const BeamElementProperties& properties, LumpedRotaryInertia rotary);

// Geometric stiffness per unit axial force N (tension positive): K_G/N = ∫ N'ᵀ N' dx of the lateral
// interpolation, in both bending planes; the element's tangent stiffness is K + N·K_G. Axial and
// torsional (Wagner) terms are left out: they only shift axial/torsional frequencies by O(N/EA).
Mat12 ElementGeometricStiffness(const BeamElementProperties& properties, BeamTheory theory);

// Geometric stiffness per unit torque T (the moment about x the part beyond x exerts, the internal
// torque's sign): dᵀ K_T d = −∫ (v′w″ − w′v″) dx over the lateral interpolation (both planes; the
// same shear-dependent v, w fields as ElementGeometricStiffness, by 3-point Gauss quadrature, exact
// for these cubics). Why: a bent rod's material twist is κ_x = θx′ − ½ (θ × θ′)_x (Simo 1985, the
// curvature of a rotation field to second order; θz = v′, θy = −w′), so the torsional energy
// ½ GJ ∫ κ_x² holds the coupling T · (−½ ∫ (v′w″ − w′v″)) = ½ T dᵀ K_T d, which turns a straight
// rod under torque into a helix (Greenhill: pinned ends buckle at N = −(π²EI/L² − T²/(4EI))).
// Zero on the axial and torsional DOFs; symmetric, with zero diagonal blocks per plane.
Mat12 ElementTorqueGeometricStiffness(const BeamElementProperties& properties, BeamTheory theory);

}  // namespace drillflex::fe
