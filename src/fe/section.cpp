#include "fe/section.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"

namespace drillflex::fe {

double HollowSection::area() const {
  return kPi * (outer_diameter * outer_diameter - inner_diameter * inner_diameter) / 4.0;
}

double HollowSection::second_moment() const {
  const double od2 = outer_diameter * outer_diameter;
  const double id2 = inner_diameter * inner_diameter;
  return kPi * (od2 * od2 - id2 * id2) / 64.0;
}

double HollowSection::polar_moment() const { return 2.0 * second_moment(); }

double HollowSection::bore_area() const { return kPi * inner_diameter * inner_diameter / 4.0; }

double HollowSection::outer_area() const { return kPi * outer_diameter * outer_diameter / 4.0; }

double HollowSection::shear_coefficient(double poisson_ratio) const {
  const double m = inner_diameter / outer_diameter;
  const double m2 = m * m;
  const double a = (1.0 + m2) * (1.0 + m2);
  const double nu = poisson_ratio;
  return 6.0 * (1.0 + nu) * a / ((7.0 + 6.0 * nu) * a + (20.0 + 12.0 * nu) * m2);
}

void ValidateSection(const HollowSection& section) {
  const bool valid = std::isfinite(section.outer_diameter) &&
                     std::isfinite(section.inner_diameter) && section.outer_diameter > 0.0 &&
                     section.inner_diameter >= 0.0 &&
                     section.inner_diameter < section.outer_diameter;
  if (!valid) {
    std::string message = "need OD > 0 and 0 <= ID < OD, got OD = ";
    message.append(std::to_string(section.outer_diameter))
        .append(" m, ID = ")
        .append(std::to_string(section.inner_diameter))
        .append(" m");
    throw InputError({}, "section", message);
  }
}

}  // namespace drillflex::fe
