// Hole profile: piecewise constant and linear sections, boundaries, the minimum over a range.
#include "well/hole.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

namespace drillflex::well {
namespace hole_test {

// Casing 0.25 m to 1000 m, a washout growing linearly 0.22 → 0.30 m over 1000–1100 m, a
// narrowing taper 0.24 → 0.20 m over 1100–1500 m, then 0.2159 m (8.5 in) open hole.
HoleProfile Profile() {
  return HoleProfile({{1000.0, 0.25, std::nullopt},
                      {1100.0, 0.22, 0.30},
                      {1500.0, 0.24, 0.20},
                      {std::nullopt, 0.2159, std::nullopt}});
}

TEST(HoleProfile, PiecewiseConstantAndLinear) {
  const HoleProfile hole = Profile();
  EXPECT_FALSE(hole.empty());
  EXPECT_EQ(hole.Diameter(-10.0), 0.25);
  EXPECT_EQ(hole.Diameter(0.0), 0.25);
  EXPECT_EQ(hole.Diameter(999.0), 0.25);
  EXPECT_EQ(hole.Diameter(1000.0), 0.25);  // a boundary belongs to the section above
  EXPECT_NEAR(hole.Diameter(1000.0 + 1e-9), 0.22, 1e-12);
  EXPECT_NEAR(hole.Diameter(1025.0), 0.22 + 0.25 * 0.08, 1e-15);
  EXPECT_NEAR(hole.Diameter(1100.0), 0.30, 1e-15);
  EXPECT_NEAR(hole.Diameter(1300.0), 0.22, 1e-15);
  EXPECT_NEAR(hole.Diameter(1500.0), 0.20, 1e-15);
  EXPECT_EQ(hole.Diameter(1500.5), 0.2159);
  EXPECT_EQ(hole.Diameter(1e6), 0.2159);
}

TEST(HoleProfile, MinDiameterOverRanges) {
  const HoleProfile hole = Profile();
  EXPECT_EQ(hole.MinDiameter(100.0, 900.0), 0.25);
  EXPECT_EQ(hole.MinDiameter(100.0, 1000.0), 0.25);             // stops on the boundary
  EXPECT_NEAR(hole.MinDiameter(100.0, 1000.5), 0.22, 1e-15);    // past it: the washout's start
  EXPECT_NEAR(hole.MinDiameter(1050.0, 1080.0), 0.26, 1e-15);   // inside a growing section
  EXPECT_NEAR(hole.MinDiameter(1080.0, 1050.0), 0.26, 1e-15);   // bounds in either order
  EXPECT_NEAR(hole.MinDiameter(1050.0, 1300.0), 0.22, 1e-15);   // taper at 1300 m
  EXPECT_NEAR(hole.MinDiameter(1050.0, 1400.0), 0.21, 1e-15);
  EXPECT_NEAR(hole.MinDiameter(1050.0, 2000.0), 0.20, 1e-15);   // the taper's end beats 8.5 in
  EXPECT_NEAR(hole.MinDiameter(1600.0, 2000.0), 0.2159, 1e-15);
  EXPECT_NEAR(hole.MinDiameter(1200.0, 1200.0), hole.Diameter(1200.0), 1e-15);
  // Against dense sampling: never above any sampled value, and equal to the smallest within
  // the sampling's resolution (slope ≤ 0.08 m / 100 m, step 0.01 m).
  for (double from : {0.0, 950.0, 1010.0, 1099.0, 1450.0}) {
    for (double to : {1000.0, 1060.0, 1120.0, 1499.0, 3000.0}) {
      if (to <= from) continue;
      double sampled = 1.0;
      for (double md = from; md <= to; md += 0.01) sampled = std::min(sampled, hole.Diameter(md));
      sampled = std::min(sampled, hole.Diameter(to));
      const double found = hole.MinDiameter(from, to);
      EXPECT_LE(found, sampled + 1e-15) << from << " .. " << to;
      EXPECT_NEAR(found, sampled, 1e-5) << from << " .. " << to;
    }
  }
}

TEST(HoleProfile, SingleSectionAndLinearLastSection) {
  const HoleProfile single({{std::nullopt, 0.3111, std::nullopt}});
  EXPECT_EQ(single.Diameter(0.0), 0.3111);
  EXPECT_EQ(single.MinDiameter(0.0, 5000.0), 0.3111);
  // A last section with its own to_md: linear to there, then constant.
  const HoleProfile taper({{100.0, 0.3, std::nullopt}, {300.0, 0.3, 0.2}});
  EXPECT_NEAR(taper.Diameter(200.0), 0.25, 1e-15);
  EXPECT_NEAR(taper.Diameter(400.0), 0.2, 1e-15);
  // A linear first section starts at MD 0.
  const HoleProfile first({{200.0, 0.4, 0.3}, {std::nullopt, 0.2, std::nullopt}});
  EXPECT_NEAR(first.Diameter(50.0), 0.375, 1e-15);
  EXPECT_NEAR(first.Diameter(-50.0), 0.4, 1e-15);
}

TEST(HoleProfile, RejectsInvalidSections) {
  EXPECT_THROW(HoleProfile().Diameter(10.0), LogicError);
  EXPECT_THROW(HoleProfile({{std::nullopt, 0.2, std::nullopt}, {std::nullopt, 0.2, std::nullopt}}), LogicError);
  EXPECT_THROW(HoleProfile({{100.0, 0.2, std::nullopt}, {100.0, 0.2, std::nullopt}}), LogicError);
  EXPECT_THROW(HoleProfile({{0.0, 0.2, std::nullopt}, {std::nullopt, 0.2, std::nullopt}}), LogicError);
  EXPECT_THROW(HoleProfile({{std::nullopt, -0.2, std::nullopt}}), LogicError);
  EXPECT_THROW(HoleProfile({{std::nullopt, 0.2, 0.3}}), LogicError);
  EXPECT_THROW(HoleProfile({{100.0, 0.2, 0.0}, {std::nullopt, 0.2, std::nullopt}}), LogicError);
}

}  // namespace hole_test
}  // namespace drillflex::well
