// The string's ratings and limit loads (model/string_limits.hpp) against hand computations from their
// sources: API RP 7G's tables for 5 in 19.50 lb/ft E-75 drill pipe (new and premium tensile yield,
// torsional yield), the von Mises stress of a tube, Dawson & Paslay's and Chen's buckling loads.
#include "model/string_limits.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace drillflex::model {
namespace string_limits_test {

constexpr double kInch = 0.0254;               // m
constexpr double kPoundForce = 4.4482216152605;  // N
constexpr double kFootPound = kPoundForce * 0.3048;  // N·m

// 5 in 19.50 lb/ft drill pipe: OD 5 in, ID 4.276 in (API RP 7G Table 2).
Component FiveInchPipe(PipeClass pipe_class) {
  Component pipe;
  pipe.type = ComponentType::Pipe;
  pipe.outer_diameter = 5.0 * kInch;
  pipe.inner_diameter = 4.276 * kInch;
  pipe.pipe_class = pipe_class;
  return pipe;
}

TEST(StringLimits, GradesAreTheApiMinimumYields) {
  ASSERT_TRUE(FindSteelGrade("E-75"));
  EXPECT_DOUBLE_EQ(FindSteelGrade("E-75")->yield, 75000.0 * kPoundForce / (kInch * kInch));
  EXPECT_NEAR(FindSteelGrade("x95")->yield, 95000.0 * kPoundForce / (kInch * kInch), 1.0);
  EXPECT_NEAR(FindSteelGrade("G-105")->yield, 105000.0 * kPoundForce / (kInch * kInch), 1.0);
  EXPECT_NEAR(FindSteelGrade("s-135")->yield, 135000.0 * kPoundForce / (kInch * kInch), 1.0);
  EXPECT_FALSE(FindSteelGrade("P-110"));
}

// Premium class: wall 0.362 in × 0.8 = 0.2896 in on the 4.276 in bore, OD 4.8552 in.
TEST(StringLimits, PremiumClassKeepsTheBoreAndEightyPercentOfTheWall) {
  const fe::HollowSection premium = RatedSection(FiveInchPipe(PipeClass::Premium));
  EXPECT_NEAR(premium.outer_diameter / kInch, 4.8552, 1e-12);
  EXPECT_NEAR(premium.inner_diameter / kInch, 4.276, 1e-12);
  const fe::HollowSection fresh = RatedSection(FiveInchPipe(PipeClass::New));
  EXPECT_DOUBLE_EQ(fresh.outer_diameter, 5.0 * kInch);
}

// API RP 7G Table 2 and 3 (5 in 19.50 lb/ft E-75): tensile yield 395 595 lbf new, 311 535 lbf premium;
// torsional yield 41 167 ft·lbf new (RP 7G's 0.096167 J Y/D; von Mises' 1/√3 gives 41 192, 0.06 % more).
TEST(StringLimits, TensionCapacityMatchesApiTables) {
  const double yield = FindSteelGrade("E-75")->yield;
  EXPECT_NEAR(TensionCapacity(RatedSection(FiveInchPipe(PipeClass::New)), yield, 0.0) / kPoundForce, 395595.0, 1.0);
  EXPECT_NEAR(TensionCapacity(RatedSection(FiveInchPipe(PipeClass::Premium)), yield, 0.0) / kPoundForce, 311535.0,
              1.0);
  const fe::HollowSection section = RatedSection(FiveInchPipe(PipeClass::New));
  // The torque that leaves no tension capacity: within 0.1 % of RP 7G's torsional yield.
  EXPECT_GT(TensionCapacity(section, yield, 41167.0 * 0.999 * kFootPound), 0.0);
  EXPECT_EQ(TensionCapacity(section, yield, 41167.0 * 1.001 * kFootPound), 0.0);
  // With 20 000 ft·lbf and the design factor 1.25: A √((Y/1.25)² − 3 τ²), by hand 1 118 829.7 N.
  EXPECT_NEAR(TensionCapacity(section, yield / 1.25, 20000.0 * kFootPound), 1118829.67, 0.5);
}

// Tension 1 MN, torque 30 kN·m, bending 10 kN·m on 5 in × 4.276 in: by hand A = 3.40296e-3 m²,
// I = 5.93927e-6 m⁴, σ = N/A + M c/I, τ = T c/(2I), √(σ² + 3τ²) = 487.628 MPa.
TEST(StringLimits, VonMisesOfATubeUnderTensionTorqueAndBending) {
  const fe::HollowSection section = RatedSection(FiveInchPipe(PipeClass::New));
  EXPECT_NEAR(VonMisesStress(section, 1.0e6, 30000.0, 10000.0), 487628157.5, 1.0);
  // Compression loads the worst fibre alike; signs of torque and moment do not matter.
  EXPECT_NEAR(VonMisesStress(section, -1.0e6, -30000.0, -10000.0), 487628157.5, 1.0);
}

// 5 in pipe (EI = 2.1e11 Pa × I) with 6.625 in tool joints in an 8.5 in hole (r = 0.9375 in), w = 250
// N/m, 30°: by hand F_s = 2 √(EI w sin θ / r) = 161 829.9 N; F_h = 2√2 √(EI w sin θ / r) = 228 862.0 N.
TEST(StringLimits, DawsonPaslayAndChenLoadsByHand) {
  const double stiffness = 2.1e11 * RatedSection(FiveInchPipe(PipeClass::New)).second_moment();
  const double sinusoidal = SinusoidalBucklingLoad(stiffness, 250.0, 30.0 * kDegree, 0.9375 * kInch);
  EXPECT_NEAR(sinusoidal, 161829.90, 0.05);
  EXPECT_NEAR(HelicalBucklingLoad(sinusoidal), 228862.04, 0.05);
  EXPECT_EQ(SinusoidalBucklingLoad(stiffness, 250.0, 0.0, 0.9375 * kInch), 0.0);  // vertical: none
}

}  // namespace string_limits_test
}  // namespace drillflex::model
