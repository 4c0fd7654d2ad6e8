#include "fe/material.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/error.hpp"

namespace drillflex::fe {

Material Steel() { return {"steel", 2.1e11, 0.3, 7850.0}; }
Material NonMagneticSteel() { return {"nonmag", 1.93e11, 0.3, 7900.0}; }
Material Brass() { return {"brass", 1.0e11, 0.33, 8500.0}; }
Material Aluminium() { return {"aluminium", 7.0e10, 0.33, 2800.0}; }

std::optional<Material> FindBuiltInMaterial(std::string_view name) {
  std::string key(name);
  std::transform(key.begin(), key.end(), key.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (key == "steel") return Steel();
  if (key == "nonmag") return NonMagneticSteel();
  if (key == "brass") return Brass();
  if (key == "aluminium" || key == "aluminum") return Aluminium();
  return std::nullopt;
}

std::vector<std::string> BuiltInMaterialNames() {
  return {"steel", "nonmag", "brass", "aluminium"};
}

void ValidateMaterial(const Material& material) {
  const auto fail = [&](const std::string& what) {
    std::string message = "material '";
    message.append(material.name).append("': ").append(what);
    throw InputError({}, "material", message);
  };
  if (!(material.youngs_modulus > 0.0) || !std::isfinite(material.youngs_modulus)) {
    fail("Young's modulus must be positive");
  }
  if (!(material.density > 0.0) || !std::isfinite(material.density))
    fail("density must be positive");
  if (!(material.poisson_ratio > -1.0 && material.poisson_ratio < 0.5)) {
    fail("Poisson's ratio must lie in (-1, 0.5)");
  }
}

}  // namespace drillflex::fe
