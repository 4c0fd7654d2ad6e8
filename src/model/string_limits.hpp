// The string's ratings and the limit loads an answer is read against (issue 37): the API grades'
// minimum yield strengths, the rated (class) section of a component's body, the von Mises stress of a
// tube under tension, torque and bending, its tension capacity under torque, and Dawson & Paslay's
// sinusoidal and Chen, Lin & Cheatham's helical buckling loads. SI throughout (Pa, N, N·m, m).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fe/section.hpp"
#include "model/string_config.hpp"

namespace drillflex::model {

// 1 ksi = 1000 lbf/in², exactly (1 lbf = 4.4482216152605 N, 1 in = 0.0254 m).
inline constexpr double kPascalPerKsi = 1000.0 * 4.4482216152605 / (0.0254 * 0.0254);
// The case's design factor by default: the allowable stress is yield / design factor.
inline constexpr double kDefaultDesignFactor = 1.25;
// A given yield strength outside these is refused (every drill-string steel lies inside).
inline constexpr double kLeastYield = 40.0 * kPascalPerKsi;
inline constexpr double kLargestYield = 200.0 * kPascalPerKsi;
// Premium class (API RP 7G): the wall at 80 % of its nominal thickness.
inline constexpr double kPremiumWallFraction = 0.8;

// The API drill-pipe grades (API 5DP / RP 7G) and their minimum yield strengths: E-75 75 ksi,
// X-95 95 ksi, G-105 105 ksi, S-135 135 ksi. The lowest, E-75, is the default for steel of unknown grade.
struct SteelGrade {
  const char* name;
  double yield;  // Pa
};
const std::vector<SteelGrade>& SteelGrades();
// The grade named `name` (as listed, case-insensitive, the dash optional: "g105"), or none.
std::optional<SteelGrade> FindSteelGrade(std::string_view name);
inline constexpr const char* kDefaultGrade = "E-75";

// A component's pipe class as a word ("new", "premium").
const char* PipeClassName(PipeClass pipe_class);

// The section a component's body is rated with: its OD and ID new; premium class the OD reduced so
// that the wall is 80 % of nominal, the ID kept: OD_p = ID + 0.8 (OD − ID) (API RP 7G's premium
// class: uniform wear of the outside).
fe::HollowSection RatedSection(const Component& component);

// The von Mises stress at the outer fibre (c = OD/2) of a tube, Pa: normal σ = |N|/A + M c/I (the
// bending fibre on the side of the axial stress), torsional shear τ = |T| c/J, σ_vm = √(σ² + 3τ²)
// (the distortion-energy criterion; the transverse shear is zero at the outer fibre).
double VonMisesStress(const fe::HollowSection& section, double axial_force, double torque, double bending_moment);

// The tension at which a tube under a torque T reaches the allowable stress σ_a (yield / design
// factor) by von Mises: A √(σ_a² − 3 τ²), τ = |T| (OD/2)/J; 0 when the torque alone reaches it.
double TensionCapacity(const fe::HollowSection& section, double allowable_stress, double torque);

// Dawson & Paslay's (1984, "Drillpipe buckling in inclined holes", JPT 36(10)) sinusoidal buckling
// load of a pipe lying on the low side of an inclined hole: F_s = 2 √(E I w sin θ / r), N, with E I
// the bending stiffness (N·m²), w the buoyed weight per length (N/m), θ the inclination and r the
// radial clearance (m). 0 in a vertical hole, infinite without clearance.
double SinusoidalBucklingLoad(double bending_stiffness, double weight_per_length, double inclination,
                              double radial_clearance);
// Chen, Lin & Cheatham's (1990, "Tubing and casing buckling in horizontal wells", JPT 42(2)) helical
// buckling load: F_h = 2√2 √(E I w sin θ / r) = √2 F_s, N (theirs is 2√2 √(E I w / r) in the
// horizontal hole, where Dawson–Paslay's is 2 √(E I w / r); w sin θ is the weight across an inclined
// hole). Mitchell (1999, "Buckling analysis in deviated wells: a practical method", SPE Drilling &
// Completion 14(1)) puts helical buckling between 1.4 F_p and 2.8 F_p (F_p = F_s, Paslay–Dawson's): ≈ √2 F_s,
// the least load that holds a helix (the limit on unloading, Chen's), and ≈ 2√2 F_s, the limit on
// loading, where a sinusoidal buckle turns helical. This is the lower, Chen's; the buckling analysis's
// screen (analyses/buckling_analysis.cpp, buckling.dawson_paslay.helical_load) reports Mitchell's
// loading limit 2√2 F_s (docs/validation.md V11).
double HelicalBucklingLoad(double sinusoidal_load);
// The vertical hole's loads, where the weight across the hole (w sin θ) and Dawson–Paslay's load with
// it vanish and the string's own weight holds it straight: Lubinski's (1950, "A study of the buckling of
// rotary drilling strings", API Drilling and Production Practice) sinusoidal 1.94 (E I w²)^(1/3) and Wu
// & Juvkam-Wold's (1993, "Study of helical buckling of pipes in horizontal wells", SPE 25503) helical
// 5.55 (E I w²)^(1/3), N. A station's load is the larger of these and the inclined hole's.
double VerticalSinusoidalBucklingLoad(double bending_stiffness, double weight_per_length);
double VerticalHelicalBucklingLoad(double bending_stiffness, double weight_per_length);

}  // namespace drillflex::model
