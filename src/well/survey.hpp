// A directional survey and the hole-diameter profile: plain data in SI (m, rad).
#pragma once

#include <optional>
#include <vector>

namespace drillflex::well {

// One survey station: measured depth (m), inclination from vertical (rad, 0..π) and azimuth from
// north toward east (rad).
struct SurveyStation {
  double md = 0.0;
  double inclination = 0.0;
  double azimuth = 0.0;
};

// A hole section: the diameter (m) from the end of the previous section down to `to_md` (m);
// the last section has no `to_md` and runs to the bottom. With `diameter_at_end` set, the
// diameter varies linearly along the section from `diameter` to `diameter_at_end`
// (washouts, tapers). A cased section (inside casing or a liner) and a section's own wall friction
// coefficients (none: the case's `model.contact` friction) let torque and drag tell cased from open
// hole (model/hole_friction.hpp).
struct HoleSection {
  std::optional<double> to_md;
  double diameter = 0.0;
  std::optional<double> diameter_at_end;
  bool cased = false;
  std::optional<double> friction = std::nullopt;        // μ around the string (rotating), and along it unless...
  std::optional<double> axial_friction = std::nullopt;  // ...this gives μ along the hole axis
  std::optional<double> wall = std::nullopt;            // a cased section's casing wall thickness, m (wear)
};

}  // namespace drillflex::well
