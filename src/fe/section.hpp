// Hollow circular cross-section of a uniform drill-string section (method.md §2). SI: m, m², m⁴.
#pragma once

namespace drillflex::fe {

struct HollowSection {
  double outer_diameter = 0.0;  // OD, m
  double inner_diameter = 0.0;  // ID (bore), m; 0 for a solid rod

  // Steel area A = π (OD² − ID²) / 4, m².
  double area() const;
  // Second moment of area about any diameter I = π (OD⁴ − ID⁴) / 64, m⁴.
  double second_moment() const;
  // Polar moment J = 2 I (torsion constant of a circular tube), m⁴.
  double polar_moment() const;
  // Bore (inside) area A_i = π ID² / 4, m² (internal fluid).
  double bore_area() const;
  // Outside area A_o = π OD² / 4, m² (displaced annulus fluid, buoyancy).
  double outer_area() const;
  // Timoshenko shear coefficient κ of a thick-walled circular tube, Cowper (1966), J. Appl. Mech.
  // 33:335, Table 1 with m = ID/OD:
  //   κ = 6 (1 + ν)(1 + m²)² / [(7 + 6ν)(1 + m²)² + (20 + 12ν) m²]
  // (solid rod, m = 0: 6(1+ν)/(7+6ν); thin tube, m → 1: 2(1+ν)/(4+3ν)).
  double shear_coefficient(double poisson_ratio) const;
};

// Throws InputError (no file position) unless OD > 0 and 0 ≤ ID < OD.
void ValidateSection(const HollowSection& section);

}  // namespace drillflex::fe
