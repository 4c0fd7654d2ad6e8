// The bit's tendency in words from constructed bit reports: every branch, and the threshold
// F_min = 1 % of the side force + 50 N on both sides of its edge.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analyses/bit_tendency.hpp"

namespace drillflex::analyses {
namespace bit_tendency_test {

BitReport Bit(double build, double walk) {
  BitReport bit;
  bit.build_force = build;
  bit.walk_force = walk;
  bit.side_force = std::hypot(build, walk);
  return bit;
}

TEST(BitTendency, ThresholdIsOnePercentOfTheSideForcePlusFiftyNewtons) {
  EXPECT_DOUBLE_EQ(TendencyThreshold(0.0), 50.0);
  EXPECT_DOUBLE_EQ(TendencyThreshold(10000.0), 150.0);
  EXPECT_DOUBLE_EQ(TendencyThreshold(-10000.0), 150.0);
  EXPECT_DOUBLE_EQ(ClassifyBitTendency(Bit(3000.0, 4000.0)).threshold, 100.0);  // side force 5000 N
}

TEST(BitTendency, EveryBranch) {
  struct Case {
    double build, walk;
    InclinationTendency inclination;
    AzimuthTendency azimuth;
  };
  const Case cases[] = {
      {1000.0, 0.0, InclinationTendency::Build, AzimuthTendency::None},
      {-1000.0, 0.0, InclinationTendency::Drop, AzimuthTendency::None},
      {0.0, 1000.0, InclinationTendency::Hold, AzimuthTendency::Right},
      {0.0, -1000.0, InclinationTendency::Hold, AzimuthTendency::Left},
      {1000.0, -1000.0, InclinationTendency::Build, AzimuthTendency::Left},
      {-1000.0, 1000.0, InclinationTendency::Drop, AzimuthTendency::Right},
      {0.0, 0.0, InclinationTendency::Hold, AzimuthTendency::None},
      // Round-off of the bit support (tens of N) is no tendency.
      {30.0, -30.0, InclinationTendency::Hold, AzimuthTendency::None},
  };
  for (const Case& c : cases) {
    const BitTendency tendency = ClassifyBitTendency(Bit(c.build, c.walk));
    EXPECT_EQ(tendency.inclination, c.inclination) << c.build << ", " << c.walk;
    EXPECT_EQ(tendency.azimuth, c.azimuth) << c.build << ", " << c.walk;
  }
}

// A side force of 10 000 N: the threshold is 150 N; a component of 140 N is none, of 160 N is one.
TEST(BitTendency, AComponentMustExceedTheThreshold) {
  const double side = 10000.0;
  auto with = [&](double build, double walk) {
    BitReport bit;
    bit.side_force = side;
    bit.build_force = build;
    bit.walk_force = walk;
    return ClassifyBitTendency(bit);
  };
  EXPECT_EQ(with(140.0, 0.0).inclination, InclinationTendency::Hold);
  EXPECT_EQ(with(160.0, 0.0).inclination, InclinationTendency::Build);
  EXPECT_EQ(with(-140.0, 0.0).inclination, InclinationTendency::Hold);
  EXPECT_EQ(with(-160.0, 0.0).inclination, InclinationTendency::Drop);
  EXPECT_EQ(with(0.0, 140.0).azimuth, AzimuthTendency::None);
  EXPECT_EQ(with(0.0, 160.0).azimuth, AzimuthTendency::Right);
  EXPECT_EQ(with(0.0, -140.0).azimuth, AzimuthTendency::None);
  EXPECT_EQ(with(0.0, -160.0).azimuth, AzimuthTendency::Left);
}

TEST(BitTendency, Names) {
  EXPECT_EQ(std::string(TendencyName(InclinationTendency::Build)), "build");
  EXPECT_EQ(std::string(TendencyName(InclinationTendency::Drop)), "drop");
  EXPECT_EQ(std::string(TendencyName(InclinationTendency::Hold)), "hold");
  EXPECT_EQ(std::string(TendencyName(AzimuthTendency::Right)), "right");
  EXPECT_EQ(std::string(TendencyName(AzimuthTendency::Left)), "left");
  EXPECT_EQ(std::string(TendencyName(AzimuthTendency::None)), "none");
}

}  // namespace bit_tendency_test
}  // namespace drillflex::analyses
