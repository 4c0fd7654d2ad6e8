// The pipe above the modelled string's top (issue 33, item 3): a string cut below the surface is held
// at its top by the pipe above, which lies on the wall of the hole with the top's axial force. That
// pipe is a semi-infinite beam (the top section's EI) on an elastic foundation k = |q| / r: q the
// lateral load per length that presses it onto the wall (its buoyed weight's part across the hole,
// w sin α on the low side, plus the tension's pull T κ toward the centre of a curved hole's arc), r
// the radial clearance of its joints; the restoring force per length of a turn around the hole is
// k times the turn's arc. Its end, displaced by u around the hole and tilted by θ = du/dx (x up-hole,
// into the pipe above), stores
//   2Π = EI (P S u² + 2 P u θ + S θ²),  P = √(k/EI),  S = √(T/EI + 2P)
// (EI y⁗ − T y″ + k y = 0 decaying up-hole; its roots a, b have a b = P and a + b = S; Hetényi
// 1946 for T = 0: the end's stiffness with the tilt free is k/(2β), β = (k/4EI)^¼). S is real while
// the compression −T stays below 2 √(k EI), Dawson & Paslay's F_sin: a modelled string joined to it
// buckles where a long pipe does. Up off the wall nothing but the tension holds it (P = 0 there: a
// tilt stiffness √(T EI), no lateral one). A pipe above compressed beyond F_sin lies buckled and
// holds the top no more (the element then adds nothing), nor does one in compression without a
// foundation (a vertical hole).
//
// Where it lies: in the direction of q, turned around the hole by the friction's climb when the
// string rotates (tan φ = μ_t Ω R_c / max(|v|, v_ε), as the wall contacts' friction for the same
// sliding: model/wall_contact.hpp), toward x × q for Ω > 0. The spring acts on the top node's place
// around the hole from there (the hole's axis projects onto that point) and on its tilt, both from its
// reference placement on the hole's axis, in the string frame there (model/coupling_kinematics.hpp).
//
// T is the top's tension at rest, from the axial balance of the modelled string under the parameter
// block's loads: λ (w_f W − WOB), W the modelled string's buoyed weight along the hole (Σ w ΔTVD);
// the friction's drag on a moving string is left out (it moves T by a fraction; the stiffness goes
// as its square root).
#pragma once

#include <optional>
#include <string>

#include "model/coupling_kinematics.hpp"
#include "model/force_element.hpp"

namespace drillflex::model {

struct StringAboveParameters {
  double bending_rigidity = 0.0;   // EI of the pipe above (the top section's), N·m²
  double weight_per_length = 0.0;  // its buoyed weight, N/m (at weight factor 1)
  // Gravity's unit direction across the hole at the top, in the top's string frame (y, z): its
  // length is sin α.
  Eigen::Vector2d gravity_across = Eigen::Vector2d::Zero();
  Eigen::Vector2d curvature = Eigen::Vector2d::Zero();  // the hole's dt/ds at the top, (y, z), 1/m
  double clearance = 0.0;      // r: the hole's radius less the joints' (or body's) radius at the top, m
  double axial_weight = 0.0;   // W: the modelled string's buoyed weight along the hole, N
  double weight_on_bit = 0.0;  // the WOB the top's balance takes when the parameter block gives none, N
  // A block holding the top by a hook load sets its tension instead (× the load factor), N.
  std::optional<double> top_tension;
  // The friction's climb: the case's coefficients, the joints' radius R_c, the regularization
  // velocity v_ε, and the static's prescribed sliding as built (ModelInput::static_sliding).
  WallFriction friction;
  bool cased = false;  // the top in cased hole (a parameter block's cased-hole friction applies)
  double contact_radius = 0.0;           // m
  double regularization_velocity = 0.0;  // m/s
  std::optional<PrescribedSliding> sliding;
};

// The pipe above's end stiffness in one plane, on (u, θ): [[K_uu, K_uθ], [K_uθ, K_θθ]] (N/m, N, N·m).
struct EndStiffness {
  double uu = 0.0, u_theta = 0.0, theta_theta = 0.0;
};
// Of a foundation k (N/m²) and a tension T (N, > 0; < 0 compression): zero where the pipe above cannot hold.
EndStiffness SemiInfiniteBeamEndStiffness(double bending_rigidity, double foundation, double tension);

class StringAboveElement : public ForceElement {
 public:
  // Holds `node` of `body` (the top) about `position` with the string frame `frame` (columns x, y, z).
  StringAboveElement(const Body* body, Index node, const Vec3& position, const Mat3& frame,
                     const StringAboveParameters& parameters);
  std::string Describe() const override;
  // The top's tension T (N) under a parameter block.
  double Tension(const LoadParameters& load) const;
  // Where the pipe above lies under a parameter block: the unit direction d from the hole's axis to
  // it (string frame y, z) and its foundation k (N/m²).
  struct Lying {
    Eigen::Vector2d direction = Eigen::Vector2d(0.0, -1.0);
    double foundation = 0.0;
  };
  Lying LyingOf(const LoadParameters& load) const;
  // T + F_sin, N: the pipe above stands (> 0) or lies buckled (≤ 0; F_sin = 2 √(k EI), 0 without a
  // foundation).
  double BucklingMargin(const LoadParameters& load) const;
  // The force and moment the pipe above exerts on the top, in the string frame at the top (N, N·m).
  Vec6 Reaction(const ElementState& state) const;
  // The 6 × 6 stiffness on the support strain (x, y, z, rx, ry, rz).
  Eigen::Matrix<double, 6, 6> Stiffness(const LoadParameters& load) const;
  const StringAboveParameters& parameters() const { return parameters_; }

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState& state) const override;

 private:
  CouplingKinematics Kinematics(const ElementState& state) const;
  Index node_;
  BodyPose ground_;
  StringAboveParameters parameters_;
};

}  // namespace drillflex::model
