#include "analyses/bit_tendency.hpp"

#include <cmath>

namespace drillflex::analyses {

double TendencyThreshold(double side_force) {
  return kTendencyRelativeThreshold * std::abs(side_force) + kTendencyForceFloor;
}

BitTendency ClassifyBitTendency(const BitReport& bit) {
  BitTendency tendency;
  tendency.threshold = TendencyThreshold(bit.side_force);
  if (bit.build_force > tendency.threshold) {
    tendency.inclination = InclinationTendency::Build;
  } else if (bit.build_force < -tendency.threshold) {
    tendency.inclination = InclinationTendency::Drop;
  }
  if (bit.walk_force > tendency.threshold) {
    tendency.azimuth = AzimuthTendency::Right;
  } else if (bit.walk_force < -tendency.threshold) {
    tendency.azimuth = AzimuthTendency::Left;
  }
  return tendency;
}

std::string_view TendencyName(InclinationTendency tendency) {
  switch (tendency) {
    case InclinationTendency::Build: return "build";
    case InclinationTendency::Drop: return "drop";
    case InclinationTendency::Hold: return "hold";
  }
  return "hold";
}

std::string_view TendencyName(AzimuthTendency tendency) {
  switch (tendency) {
    case AzimuthTendency::Right: return "right";
    case AzimuthTendency::Left: return "left";
    case AzimuthTendency::None: return "none";
  }
  return "none";
}

}  // namespace drillflex::analyses
