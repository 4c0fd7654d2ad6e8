#include "fe/material.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "fe/section.hpp"

namespace drillflex::fe {
namespace material_test {

TEST(Material, BuiltInsAndShearModulus) {
  const auto steel = FindBuiltInMaterial("Steel");
  ASSERT_TRUE(steel.has_value());
  EXPECT_DOUBLE_EQ(steel->youngs_modulus, 2.1e11);
  EXPECT_DOUBLE_EQ(steel->density, 7850.0);
  // G = E / (2 (1 + ν)) = 2.1e11 / 2.6.
  EXPECT_NEAR(steel->shear_modulus(), 8.076923076923077e10, 1e-3);
  EXPECT_DOUBLE_EQ(FindBuiltInMaterial("nonmag")->youngs_modulus, 1.93e11);
  EXPECT_DOUBLE_EQ(FindBuiltInMaterial("brass")->density, 8500.0);
  EXPECT_DOUBLE_EQ(FindBuiltInMaterial("aluminum")->youngs_modulus, 7.0e10);
  EXPECT_FALSE(FindBuiltInMaterial("unobtainium").has_value());
  for (const std::string& name : BuiltInMaterialNames()) {
    EXPECT_TRUE(FindBuiltInMaterial(name).has_value()) << name;
  }
}

TEST(Material, ValidationRejectsNonsense) {
  EXPECT_NO_THROW(ValidateMaterial(Steel()));
  EXPECT_THROW(ValidateMaterial({"x", -1.0, 0.3, 7850.0}), InputError);
  EXPECT_THROW(ValidateMaterial({"x", 2e11, 0.5, 7850.0}), InputError);
  EXPECT_THROW(ValidateMaterial({"x", 2e11, 0.3, 0.0}), InputError);
}

TEST(Section, HollowProperties) {
  // 5 in × 4.276 in drill pipe body (in metres).
  const HollowSection pipe{0.127, 0.1086104};
  const double pi = 3.14159265358979323846;
  const double od = 0.127, id = 0.1086104;
  EXPECT_NEAR(pipe.area(), pi / 4 * (od * od - id * id), 1e-18);
  EXPECT_NEAR(pipe.second_moment(), pi / 64 * (od * od * od * od - id * id * id * id), 1e-20);
  EXPECT_DOUBLE_EQ(pipe.polar_moment(), 2.0 * pipe.second_moment());
  EXPECT_NEAR(pipe.outer_area() - pipe.bore_area(), pipe.area(), 1e-16);
}

TEST(Section, CowperShearCoefficientLimits) {
  // Solid rod: 6(1+ν)/(7+6ν) (Cowper 1966); ν = 0.3 → 7.8/8.8.
  EXPECT_NEAR((HollowSection{0.1, 0.0}.shear_coefficient(0.3)), 7.8 / 8.8, 1e-15);
  // Thin-walled tube: m → 1 gives 2(1+ν)/(4+3ν) = 2.6/4.9.
  EXPECT_NEAR((HollowSection{0.1, 0.1 * (1 - 1e-9)}.shear_coefficient(0.3)), 2.6 / 4.9, 1e-8);
}

TEST(Section, ValidationRejectsNonsense) {
  EXPECT_THROW(ValidateSection({0.1, 0.1}), InputError);
  EXPECT_THROW(ValidateSection({-0.1, 0.0}), InputError);
  EXPECT_THROW(ValidateSection({0.1, -0.01}), InputError);
  EXPECT_NO_THROW(ValidateSection({0.1, 0.0}));
}

}  // namespace material_test
}  // namespace drillflex::fe
