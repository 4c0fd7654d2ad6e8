// Lateral fluid forces on a pipe vibrating in a concentric hole filled with a viscous fluid
// (method.md §7, validation.md V5). SI: m, rad/s, kg/m³, m²/s; per length: kg/m, N·s/m².
//
// A rigid rod of radius a vibrates laterally, x = Re(X e^{iωt}), in a rigid concentric cylinder
// of radius b (α = b/a) filled with fluid of density ρ and kinematic viscosity ν. The exact 2-D
// linear (small-amplitude) solution of Chen, Wambsganss & Jendrzejczyk (1976), "Added mass and
// damping of a vibrating rod in confined viscous fluids", J. Appl. Mech. 43:325, gives the fluid
// force on the rod per length
//   f = ρ π a² ω² X H(α, S),   S = ω a²/ν (Stokes number),   H = C_m − i C_v,
// i.e. the force of an added mass per length m_a = C_m ρ π a² and of a viscous damping per
// length c = C_v ρ π a² ω: f = −m_a ẍ − c ẋ. Both coefficients depend on α and S; as S → ∞ the
// fluid is inviscid, C_m → (α² + 1)/(α² − 1) and C_v → 0.
#pragma once

#include <complex>

namespace drillflex::fe {

struct AnnulusFluidCoefficients {
  double added_mass = 0.0;  // C_m (dimensionless), m_a = C_m ρ π a²
  double damping = 0.0;     // C_v (dimensionless), c = C_v ρ π a² ω
};

// Above this Stokes number the inviscid limit is returned (the viscous corrections to C_m and
// C_v are O(S^{−1/2}) ≈ 1e-7 relative there).
inline constexpr double kInviscidStokesNumber = 1e14;

// C_m = (α² + 1)/(α² − 1) of inviscid potential flow, α = b/a > 1 (Chen et al. 1976, S → ∞;
// written (D_h² + D_p²)/(D_h² − D_p²) in method.md §7). Throws LogicError unless α > 1.
double InviscidAddedMassCoefficient(double radius_ratio);

// S = ω a²/ν. Throws LogicError unless a > 0, ω ≥ 0, ν > 0.
double StokesNumber(double rod_radius, double circular_frequency, double kinematic_viscosity);

// H = C_m − i C_v for the confined rod (the 4×4 solution of Chen et al. 1976); S = +∞ or
// S > kInviscidStokesNumber gives the inviscid value. Throws LogicError unless α > 1 and S > 0.
std::complex<double> ConfinedForceRatio(double radius_ratio, double stokes_number);

// H of an isolated cylinder in unbounded fluid (Stokes 1851, "On the effect of the internal
// friction of fluids on the motion of pendulums", Trans. Camb. Phil. Soc. 9:8; the α → ∞ limit
// of ConfinedForceRatio): H = 1 + 4 K₁(β)/(β K₀(β)), β = sqrt(iS). Throws LogicError unless S > 0.
std::complex<double> UnconfinedForceRatio(double stokes_number);

// {C_m, C_v} for a rod of radius a in a hole of radius b > a at circular frequency ω of a fluid
// of kinematic viscosity ν; ν = 0 (inviscid) gives {(α²+1)/(α²−1), 0} at any ω ≥ 0. Throws
// LogicError on a ≤ 0, b ≤ a, ω < 0, ν < 0, or ω = 0 with ν > 0 (no steady limit of C_m, C_v).
AnnulusFluidCoefficients ComputeAnnulusFluidCoefficients(double rod_radius, double hole_radius,
                                                      double circular_frequency,
                                                      double kinematic_viscosity);

// m_a = C_m ρ π a², kg/m.
double AddedMassPerLength(const AnnulusFluidCoefficients& coefficients, double fluid_density,
                          double rod_radius);
// c = C_v ρ π a² ω, N·s/m² (force per length per velocity).
double DampingPerLength(const AnnulusFluidCoefficients& coefficients, double fluid_density,
                        double rod_radius, double circular_frequency);

}  // namespace drillflex::fe
