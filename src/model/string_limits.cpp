#include "model/string_limits.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace drillflex::model {

const std::vector<SteelGrade>& SteelGrades() {
  static const std::vector<SteelGrade> grades = {{"E-75", 75.0 * kPascalPerKsi},
                                                 {"X-95", 95.0 * kPascalPerKsi},
                                                 {"G-105", 105.0 * kPascalPerKsi},
                                                 {"S-135", 135.0 * kPascalPerKsi}};
  return grades;
}

std::optional<SteelGrade> FindSteelGrade(std::string_view name) {
  const auto squeeze = [](std::string_view text) {
    std::string out;
    for (const char c : text) {
      if (c != '-' && c != ' ') out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    }
    return out;
  };
  const std::string wanted = squeeze(name);
  for (const SteelGrade& grade : SteelGrades()) {
    if (squeeze(grade.name) == wanted) return grade;
  }
  return std::nullopt;
}

const char* PipeClassName(PipeClass pipe_class) {
  return pipe_class == PipeClass::Premium ? "premium" : "new";
}

fe::HollowSection RatedSection(const Component& component) {
  fe::HollowSection section{component.outer_diameter, component.inner_diameter};
  if (component.pipe_class == PipeClass::Premium) {
    // The wall (OD − ID)/2 at 80 %, worn from the outside: OD_p = ID + 0.8 (OD − ID).
    section.outer_diameter =
        component.inner_diameter + kPremiumWallFraction * (component.outer_diameter - component.inner_diameter);
  }
  return section;
}

double VonMisesStress(const fe::HollowSection& section, double axial_force, double torque, double bending_moment) {
  const double c = 0.5 * section.outer_diameter;
  const double normal = std::abs(axial_force) / section.area() + std::abs(bending_moment) * c / section.second_moment();
  const double shear = std::abs(torque) * c / section.polar_moment();
  return std::sqrt(normal * normal + 3.0 * shear * shear);
}

double TensionCapacity(const fe::HollowSection& section, double allowable_stress, double torque) {
  const double shear = std::abs(torque) * 0.5 * section.outer_diameter / section.polar_moment();
  const double left = allowable_stress * allowable_stress - 3.0 * shear * shear;
  return left > 0.0 ? section.area() * std::sqrt(left) : 0.0;
}

double SinusoidalBucklingLoad(double bending_stiffness, double weight_per_length, double inclination,
                              double radial_clearance) {
  const double lateral = std::abs(weight_per_length) * std::abs(std::sin(inclination));
  if (lateral <= 0.0) return 0.0;
  // No room to buckle into: no lateral load buckles the pipe.
  if (radial_clearance <= 0.0) return std::numeric_limits<double>::infinity();
  return 2.0 * std::sqrt(bending_stiffness * lateral / radial_clearance);
}

double HelicalBucklingLoad(double sinusoidal_load) { return std::sqrt(2.0) * sinusoidal_load; }

double VerticalSinusoidalBucklingLoad(double bending_stiffness, double weight_per_length) {
  return 1.94 * std::cbrt(bending_stiffness * weight_per_length * weight_per_length);
}

double VerticalHelicalBucklingLoad(double bending_stiffness, double weight_per_length) {
  return 5.55 * std::cbrt(bending_stiffness * weight_per_length * weight_per_length);
}

}  // namespace drillflex::model
