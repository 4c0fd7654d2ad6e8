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
// (washouts, tapers).
struct HoleSection {
  std::optional<double> to_md;
  double diameter = 0.0;
  std::optional<double> diameter_at_end;
};

}  // namespace drillflex::well
