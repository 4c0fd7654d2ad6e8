#include "analyses/mwd_sag.hpp"

#include <algorithm>
#include <cmath>

namespace drillflex::analyses {
namespace {

double InclinationOf(const Vec3& down) { return std::atan2(std::hypot(down.x(), down.y()), down.z()); }

double AzimuthOf(const Vec3& down) {
  const double azimuth = std::atan2(down.y(), down.x());
  return azimuth < 0.0 ? azimuth + 2.0 * kPi : azimuth;
}

}  // namespace

std::optional<double> MwdSensorAt(const model::StringConfig& string, std::optional<double> mwd_at) {
  if (mwd_at) return mwd_at;
  double s = 0.0;
  for (const model::Component& component : string.components) {
    if (component.type == model::ComponentType::Mwd) return s + 0.5 * component.length;
    s += component.length * component.count;
  }
  return std::nullopt;
}

std::optional<MwdSag> ComputeMwdSag(std::span<const StaticNodeResult> nodes, const well::Trajectory& path,
                                    double sensor_s) {
  // The station nearest the sensor, with one on each side (joints repeat a station's s: the nearest
  // distinct ones are taken).
  if (nodes.size() < 3) return std::nullopt;
  std::size_t k = 0;
  for (Index i = 0; i < std::ssize(nodes); ++i) {
    if (std::abs(nodes[i].s - sensor_s) < std::abs(nodes[k].s - sensor_s)) k = i;
  }
  std::size_t below = k, above = k;
  while (below > 0 && nodes[below].s >= nodes[k].s) --below;
  while (above + 1 < nodes.size() && nodes[above].s <= nodes[k].s) ++above;
  if (!(nodes[below].s < nodes[k].s) || !(nodes[above].s > nodes[k].s) || !nodes[k].has_wall) return std::nullopt;
  // Down-hole: from the station above to the one below.
  const Vec3 axis = (nodes[below].position - nodes[above].position).normalized();
  MwdSag sag;
  sag.s = nodes[k].s;
  sag.md = nodes[k].md;
  sag.axis_inclination = InclinationOf(axis);
  sag.hole_inclination = path.Inclination(sag.md);
  sag.sag = sag.axis_inclination - sag.hole_inclination;
  sag.axis_azimuth = AzimuthOf(axis);
  sag.hole_azimuth = path.Azimuth(sag.md);
  return sag;
}

}  // namespace drillflex::analyses
