// Wellbore contact (method.md §6): a contact circle of radius R_c at node k of a body, inside the
// hole of radius R_h(s) = D(s)/2 around the well path.
//
// Geometry at the node position x = r_k:
//   s*  : the MD whose normal plane contains x, (x − p(s*))·t(s*) = 0 (Trajectory::FindClosest,
//         warm-started from the previous answer); beyond an end of the path, the path is
//         continued straight along its end tangent.
//   e = x − p(s*) (⊥ t), ρ = |e|, n = e/ρ (from the hole axis toward the wall),
//   δ = ρ + R_c − R_h(s*)  (penetration; < 0 is the clearance).
// Normal force N = max(0, k_n δ + c_n δ̇) when δ > 0, on the node along −n; δ̇ = ∇δ·ṙ_k with
//   ∇δ = n − R_h'(s*) t/(1 − e·κ)   (ds*/dx = tᵀ/(1 − e·κ), κ = dt/ds: curvature vector).
// Friction (regularized Coulomb) at the contact point x + R_c n, whose velocity is
//   v_c = ṙ_k + ω_k × (R_c n)        (ω_k the node's global angular velocity),
// or, with prescribed sliding (static torque and drag), v_c = −V t + Ω R_c (t × n):
//   F_t = −N (μ_a v_a t + μ_t v_θ e_θ) / max(|v_t|, v_ε),
// with v_t = v_c − (n·v_c) n, v_a = t·v_c (axial), v_θ = e_θ·v_c, e_θ = t × n (around the string):
// for μ_a = μ_t = μ this is −μ N v_t/max(|v_t|, v_ε); for μ_a ≠ μ_t the axial and circumferential
// parts of the sliding velocity are resisted with their own coefficient (the friction is then not
// exactly opposite to v_t). The friction acts at the contact point: moment R_c n × F_t on the node.
//
// Design choices (documented, measured in tests/model/wall_contact_test.cpp):
//  * The normal force acts along −n (method.md §6) also where the hole is tapered; the true wall
//    normal of a cone leans by the slope R_h', so the axial push of a taper (~R_h' N) is left out.
//    The potential ½ k_n δ² therefore matches the elastic force exactly where R_h' = 0.
//  * Onset: the max(0, ·) kink at δ = 0 (and where k_n δ + c_n δ̇ < 0) is not smoothed: the force
//    is continuous in δ (k_n δ → 0) and its tangent jumps from 0 to k_n ∇δ ∇δᵀ, which Newton
//    handles like an active-set method (contacts switch on/off between iterations). With c_n > 0
//    the force jumps by c_n δ̇ at impact (the spec's Kelvin–Voigt law).
//  * The friction regularization switches at |v_t| = v_ε between the viscous (−μ N v/v_ε) and the
//    Coulomb branch: C⁰, with a kink there.
//  * Prescribed sliding replaces the state's contact velocity in the friction law (the friction
//    then depends on position only, through t and n); the normal damping still uses the state.
//
// Exact derivatives with respect to r_k, ṙ_k and ω_k (curvature of the hole: dt/dx = κ tᵀ/c,
// dn/dx = (I − n nᵀ − t tᵀ/c)/ρ, d(1/c)/dx = κᵀ/c² with c = 1 − e·κ and dκ/ds = −|κ|² t on a
// circular arc; the hole-diameter slope; the friction terms), mapped to the body by
// model/node_force.hpp.
//
// Threading: the warm start s* is kept in a relaxed std::atomic<double> (it is only a hint for
// the closest-point search, never part of the answer), so one element may even be evaluated by
// several threads at once; everything else is const. Result() is a pure function of the state.
#pragma once

#include <atomic>
#include <limits>
#include <memory>
#include <optional>

#include "model/force_element.hpp"
#include "model/node_force.hpp"
#include "model/wellbore.hpp"

namespace drillflex::model {

struct WallContactParameters {
  double contact_radius = 0.0;        // R_c, m (half the contact diameter: body, tool joint, blade)
  double normal_stiffness = 0.0;      // k_n, N/m (> 0)
  double normal_damping = 0.0;        // c_n, N·s/m (≥ 0)
  double axial_friction = 0.0;        // μ_a, along the hole axis
  double tangential_friction = 0.0;   // μ_t, around the string (rotation)
  bool cased = false;                 // in cased hole: a parameter block's cased-hole friction applies
  double regularization_velocity = 0.0;  // v_ε, m/s (> 0 when a friction coefficient is > 0)
  std::optional<PrescribedSliding> prescribed_sliding;  // none: friction from the state's velocities
};

// The contact at a state, for output.
struct WallContactResult {
  bool in_contact = false;      // N > 0
  double md = 0.0;              // s*: MD of the hole cross-section through the node, m
  double penetration = 0.0;     // δ, m (< 0: clearance)
  double offset = 0.0;          // ρ = |e|: distance of the node from the hole axis, m
  double hole_diameter = 0.0;   // D(s*), m
  double normal_force = 0.0;    // N ≥ 0, N
  Vec3 normal = Vec3::Zero();   // n: unit, from the hole axis toward the contact (global); 0 at ρ = 0
  Vec3 contact_point = Vec3::Zero();   // x + R_c n (global), m
  Vec3 friction_force = Vec3::Zero();  // F_t on the string (global), N
  Vec3 force = Vec3::Zero();           // −N n + F_t on the node (global), N
  Vec3 moment = Vec3::Zero();          // R_c n × F_t on the node (global), N·m
  double axial_friction = 0.0;  // t·F_t, N (> 0 down-hole)
  double torque = 0.0;          // t·moment, N·m (about the down-hole tangent)
  // Direction of n from the high side toward the right, looking down-hole, rad in [0, 2π):
  // 0 high side, π/2 right, π low side, 3π/2 left (0 when ρ = 0).
  double high_side_angle = 0.0;
};

class WallContactElement : public ForceElement {
 public:
  // The contact circle at `node` of `body` in `wellbore` (not null; shared by the model).
  // `md_guess`: a starting MD for the first closest-point search (e.g. bit_md − s of the node);
  // NaN: the start of the path. Throws LogicError on an invalid parameter, an empty hole
  // profile, or a node outside the body.
  WallContactElement(const Body* body, Index node, std::shared_ptr<const Wellbore> wellbore,
                     const WallContactParameters& parameters, double md_guess = kNoGuess);

  std::string Describe() const override;
  Index node() const { return node_; }
  const WallContactParameters& parameters() const { return parameters_; }  // as built
  // The parameters under a parameter block: its friction coefficients, factor and sliding.
  WallContactParameters EffectiveParameters(const LoadParameters& load) const;
  const std::shared_ptr<const Wellbore>& wellbore() const { return wellbore_; }  // shared with the model's input

  // Normal force, friction, contact MD and high-side angle at a state (thread-safe).
  WallContactResult Result(const ElementState& state) const;

  static constexpr double kNoGuess = std::numeric_limits<double>::quiet_NaN();

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  // ½ k_n δ² for δ > 0 (the elastic part of the normal force).
  double DoPotentialEnergy(const ElementState& state) const override;
  // The elastic part's difference, and with friction (a rotating string's prescribed sliding, which
  // has no potential) minus its work over the step by the trapezoidal rule, ½(F_t,from + F_t,to)·Δx
  // + ½(M_from + M_to)·Δψ (model::NodeMoveBetween): the static solver's merit for a string whose
  // friction acts around it, exact to second order in the step.
  double DoPotentialEnergyChange(const ElementState& from, const ElementState& to) const override;
  // δ, k_n and ∂δ/∂v = L_kᵀ ∇δ (L_k the node's translation Jacobian, ∇δ = n − R_h' t/c), also
  // where the circle does not touch (δ < 0: the gap); on the hole axis (ρ = 0) the gradient is zero.
  bool DoPenalty(const ElementState& state, double& value, double& stiffness, VecX& gradient) const override;

 private:
  Index node_;
  std::shared_ptr<const Wellbore> wellbore_;
  WallContactParameters parameters_;
  mutable std::atomic<double> md_hint_;
};

}  // namespace drillflex::model
