// Linear-elastic isotropic materials of drill-string components, and the built-in ones a case file
// may name. SI units: Pa, kg/m³.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drillflex::fe {

struct Material {
  std::string name;
  double youngs_modulus = 0.0;  // E, Pa
  double poisson_ratio = 0.0;   // ν, -
  double density = 0.0;         // ρ, kg/m³

  // G = E / (2 (1 + ν)) for an isotropic material, Pa.
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

// Built-ins (typical handbook values):
//   steel      E = 2.10e11 Pa, ν = 0.30, ρ = 7850 kg/m³ (method.md §2 default)
//   nonmag     E = 1.93e11 Pa, ν = 0.30, ρ = 7900 kg/m³ (austenitic non-magnetic collar steel)
//   brass      E = 1.00e11 Pa, ν = 0.33, ρ = 8500 kg/m³
//   aluminium  E = 7.00e10 Pa, ν = 0.33, ρ = 2800 kg/m³
Material Steel();
Material NonMagneticSteel();
Material Brass();
Material Aluminium();

// The built-in material of that name ("steel", "nonmag", "brass", "aluminium"; "aluminum" is
// accepted too; case-insensitive), or nothing. The case reader turns nothing into an InputError.
std::optional<Material> FindBuiltInMaterial(std::string_view name);

// The names FindBuiltInMaterial accepts (for error messages).
std::vector<std::string> BuiltInMaterialNames();

// Throws InputError (no file position) when a material cannot make a beam: E, ρ > 0, -1 < ν < 0.5.
void ValidateMaterial(const Material& material);

}  // namespace drillflex::fe
