// The string's limits over a transient run (issue 37) in results.json: the envelope of every output
// sample (analyses/limits_envelope.hpp, read as the run goes, whether or not it keeps VTK frames).
#pragma once

#include "analyses/limits_envelope.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"

namespace drillflex::pipeline {

// results.json `transient.limits`: `samples` (how many were read; `frames`, its former name, the same),
// `design_factor`, `nodes` (per station: s, md, and per limit its largest utilisation over the samples,
// `<limit>_utilisation`, 0 where the limit does not apply, and `<limit>_time`, when), `summary` (per limit
// and the `closest`: the largest over every station and sample, where and at which `time`) and `history`
// (`time`, every sample's; per limit that applies the largest over the stations at each; `closest`, the
// name of the closest limit, whose history that one is).
void AddTransientLimits(const io::Case& c, const analyses::LimitsEnvelope& envelope, io::ResultFiles& files);

}  // namespace drillflex::pipeline
