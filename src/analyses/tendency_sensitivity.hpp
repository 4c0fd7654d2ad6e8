// The steady build and turn rates against the handles a directional driller has on a BHA (issue 34,
// item 3): the WOB (× 0.5, 0.75, 1.25, 1.5), the bit's inclination (±5°, ±10°, kept within 0–90°:
// the case's hole at the bit turned about its right-hand axis) and the stabilizers' gauge (every
// blade's OD less 1/16 and 1/8 in: under-gauge blades steer). Each point a tendency of its own
// (analyses/tendency_analysis.hpp), its search started from the base's steady curvature; a point whose
// tendency fails is NaN, the others stand.
#pragma once

#include "analyses/tendency_analysis.hpp"

namespace drillflex::analyses {

TendencySensitivities ComputeTendencySensitivities(const model::ModelInput& input, const ModelFactory& build,
                                                   const StaticSettings& statics, const TendencySettings& settings,
                                                   const TendencyResult& base);

}  // namespace drillflex::analyses
