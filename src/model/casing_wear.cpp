#include "model/casing_wear.hpp"

#include <algorithm>
#include <cmath>

namespace drillflex::model {
namespace {

constexpr double kPi = 3.14159265358979323846;

double Clamped(double cosine) { return std::clamp(cosine, -1.0, 1.0); }

}  // namespace

double WornVolumePerLength(double wear_factor, double side_force_per_length, double joint_diameter,
                           double rotary_speed, double time) {
  const double sliding_distance = kPi * joint_diameter * (std::abs(rotary_speed) / (2.0 * kPi)) * time;  // m
  return wear_factor * std::abs(side_force_per_length) * sliding_distance;
}

double GrooveArea(double bore_radius, double joint_radius, double depth) {
  const double r = joint_radius, big = bore_radius;
  if (depth <= 0.0) return 0.0;
  if (depth >= 2.0 * r) return kPi * r * r;
  const double d = big - r + depth;
  const double lens = r * r * std::acos(Clamped((d * d + r * r - big * big) / (2.0 * d * r))) +
                      big * big * std::acos(Clamped((d * d + big * big - r * r) / (2.0 * d * big))) -
                      0.5 * std::sqrt(std::max(0.0, (-d + r + big) * (d + r - big) * (d - r + big) * (d + r + big)));
  return std::max(0.0, kPi * r * r - lens);
}

double GrooveDepth(double bore_radius, double joint_radius, double area) {
  if (area <= 0.0) return 0.0;
  double low = 0.0, high = 2.0 * joint_radius;
  if (GrooveArea(bore_radius, joint_radius, high) <= area) return high;
  while (high - low > 1e-12) {
    const double middle = 0.5 * (low + high);
    (GrooveArea(bore_radius, joint_radius, middle) < area ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

}  // namespace drillflex::model
