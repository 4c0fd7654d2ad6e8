// Fatigue of rotating drill pipe in a dogleg (issue 37): API RP 7G's allowable bending stress under
// tension (its endurance limit with the tension's correction) and Lubinski's (1961, "Maximum permissible
// dog-legs in rotary boreholes", JPT 13(2); Hansford & Lubinski 1964; RP 7G section 8) bending stress of
// pipe between tool joints in a dogleg, and the maximum permissible dogleg that follows. SI throughout.
#pragma once

namespace drillflex::model {

// RP 7G's (after Lubinski 1961) largest bending stress a rotating pipe body carries without fatigue
// damage under a tensile stress σ_t (Pa; compression counts as none), for a steel of minimum yield
// `yield` (Pa):
//   grade E (yield below X-95's 95 ksi):  σ_b = 19 500 − (10/67) σ_t − (0.6/670²) (σ_t − 33 500)²  psi
//   grade S-135 (RP 7G):                  σ_b = 20 000 (1 − σ_t / 145 000)                         psi
// and for X-95 and G-105 the S line's Goodman form 20 000 psi (1 − σ_t/σ_u) with their minimum tensile
// strengths σ_u (API 5DP: 105 and 115 ksi). 0 where the tension alone uses it up.
double AllowableBendingStress(double tensile_stress, double yield);

// Lubinski's factor KL / tanh(KL), K = √(T / (E I)), L half the distance between tool joints (m): how much
// the pipe body's bending stress exceeds a pipe following the hole's curvature, E D κ / 2, because the
// tool joints hold the body off the wall and the tension pulls it straight between them. 1 without
// tension.
double LubinskiFactor(double tension, double bending_stiffness, double half_joint_spacing);

// The pipe body's bending stress in a dogleg of curvature κ (1/m) under a tension T (N):
// σ_b = E D κ / 2 · KL / tanh(KL) (RP 7G section 8), Pa. E the modulus (Pa), D the body's OD (m).
double DoglegBendingStress(double curvature, double youngs_modulus, double outer_diameter, double tension,
                           double bending_stiffness, double half_joint_spacing);

// Lubinski's maximum permissible dogleg: the curvature (1/m) at which DoglegBendingStress reaches the
// allowable bending stress σ_b: κ = 2 σ_b / (E D) · tanh(KL) / (KL) (RP 7G's c = 432 000/π · σ_b/(E D) ·
// tanh(KL)/(KL) in °/100 ft with D in inches).
double MaxPermissibleCurvature(double allowable_bending_stress, double youngs_modulus, double outer_diameter,
                               double tension, double bending_stiffness, double half_joint_spacing);

}  // namespace drillflex::model
