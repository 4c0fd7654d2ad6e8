// The drilling fluid's lateral inertia and damping for the linear vibration analyses
// (method.md §7, validation.md V5), as matrices in the velocity coordinates of the bodies that
// are added to the linearized M and D. The static model is not affected: the weight and buoyancy
// of the fluid stay in the buoyed weight (model/builder.hpp BuoyedWeightPerLength), and the
// SystemModel's own mass matrix carries the steel only.
//
// Lumped per node over its tributary length L_k (half an element at a body's end node, a whole
// one inside; the two bodies at a joint each add their half), laterally only (across the body's
// x axis):
//   internal fluid   m_i = ρ_f,i A_i L_k            (moves with the pipe; A_i averaged over tool joints)
//   annulus          m_a = C_m(ω) ρ_f π a² L_k,     c_a = C_v(ω) ρ_f π a² ω L_k
// with a = OD/2 of the body (not the blades or tool joints) and b = D_h/2 the hole radius at the
// node's MD (bit MD − s), C_m, C_v from fe/annulus_fluid.hpp (Chen, Wambsganss & Jendrzejczyk
// 1976; the inviscid C_m = (D_h² + OD²)/(D_h² − OD²) at zero viscosity). Without a well there is
// no annulus term, only the internal fluid. `fluid.added_mass_coefficient` replaces C_m (and
// then C_v = 0).
//
// Node k's lateral velocity, body frame (method.md §4): rows y, z of
//   t_k = Aᵀ ṙ + ω × u_k + Φ_k η̇ = J_k v_b,   J_k = [Aᵀ, −ũ_k, Φ_k],
// so a lateral mass m adds m J_latᵀ J_lat to M and a lateral damping c adds c J_latᵀ J_lat to D.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "model/model_input.hpp"
#include "model/system_model.hpp"

namespace drillflex::model {

struct LateralFluidNode {
  Index body = 0;
  Index node = 0;
  double internal_mass = 0.0;  // ρ_f,i A_i L_k, kg
  double length = 0.0;         // tributary length L_k, m
  double rod_radius = 0.0;     // a = OD/2, m
  double hole_radius = 0.0;    // b = D_h/2, m; 0: no hole (no annulus term)
};

struct LateralFluid {
  double density = 0.0;              // annulus fluid ρ_f, kg/m³
  double kinematic_viscosity = 0.0;  // ν = μ/ρ_f, m²/s
  double added_mass_override = -1.0; // C_m given by the case (< 0: from the confinement)
  std::vector<LateralFluidNode> nodes;

  bool empty() const { return nodes.empty(); }
  // The annulus terms change with ω (a viscous fluid and no C_m override).
  bool frequency_dependent() const { return kinematic_viscosity > 0.0 && added_mass_override < 0.0; }
};

// The fluid of a model built from `input` (empty without `input.fluid`).
LateralFluid MakeLateralFluid(const ModelInput& input, const SystemModel& model);
// The same for the bodies of a model being built.
LateralFluid MakeLateralFluid(const ModelInput& input, const std::vector<Body>& bodies);

// Gives every body its fluid lumps for the time domain (Body::fluid_lateral_mass, _damping;
// model/fluid_inertia.hpp): each node's ComputeNodeFluidTerms at the circular frequency ω (rad/s).
// Throws LogicError for ω ≤ 0 when the annulus terms depend on ω (a viscous fluid without a C_m).
void AttachLateralFluid(const ModelInput& input, double circular_frequency, std::vector<Body>& bodies);

// Lateral mass (kg) and damping (N·s/m) of node `index` at the circular frequency ω (rad/s):
// internal fluid plus annulus. At ω = 0 a viscous annulus takes its inviscid C_m (the ω → ∞
// limit; the eigenproblem's first guess) and no damping.
struct NodeFluidTerms {
  double mass = 0.0;
  double damping = 0.0;
};
NodeFluidTerms ComputeNodeFluidTerms(const LateralFluid& fluid, std::size_t index, double circular_frequency);

// The 2 × (6 + n_f) lateral rows of J_k of a fluid node at q (the body's velocity block).
MatX LateralNodeJacobian(const SystemModel& model, const std::vector<BodyPose>& poses, const LateralFluidNode& node);

struct LateralFluidMatrices {
  SparseMat mass;     // Σ m_k J_latᵀ J_lat, n_v × n_v
  SparseMat damping;  // Σ c_k J_latᵀ J_lat
};
// Which fluid: both, the bore's (constant in ω) or the annulus's.
enum class FluidPart { All, Internal, Annulus };
// The matrices at q and ω.
LateralFluidMatrices ComputeLateralFluidMatrices(const SystemModel& model, const LateralFluid& fluid, const VecX& q,
                                              double circular_frequency, FluidPart part = FluidPart::All);

// The annulus of the nodes that share a rod and hole radius (a component in one hole section):
// C_m and C_v are the same for all of them, so M_a(ω) = Σ_g C_m,g(ω) U_g and
// D_a(ω) = Σ_g C_v,g(ω) ω U_g with U_g = Σ_k ρ_f π a² L_k J_latᵀ J_lat (the mass at C_m = 1), built once.
struct AnnulusGroup {
  double rod_radius = 0.0, hole_radius = 0.0;  // m
  SparseMat unit_mass;                         // U_g, kg
};
std::vector<AnnulusGroup> ComputeAnnulusGroups(const SystemModel& model, const LateralFluid& fluid, const VecX& q);
LateralFluidMatrices ComputeAnnulusMatrices(const std::vector<AnnulusGroup>& groups, const LateralFluid& fluid,
                                         double circular_frequency);

// |J_lat,k v|² of every fluid node for a velocity vector v (a mode): vᵀ M_f v = Σ m_k s_k.
std::vector<double> LateralNodeSquares(const SystemModel& model, const LateralFluid& fluid, const VecX& q,
                                       const VecX& v);

}  // namespace drillflex::model
