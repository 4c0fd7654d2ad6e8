// Fuzz target: a survey CSV's text -> io::ParseSurveyCsv, in SI and in field units. Bad input must
// end in an InputError; any other exception, a sanitizer report, a timeout or a station read with a
// non-finite or out-of-range value is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "core/error.hpp"
#include "core/types.hpp"
#include "io/survey_csv.hpp"

namespace {

using namespace drillflex;

void CheckStations(const std::vector<well::SurveyStation>& stations) {
  for (std::size_t i = 0; i < stations.size(); ++i) {
    const auto& s = stations[i];
    const bool ok = std::isfinite(s.md) && s.md >= 0.0 && s.inclination >= 0.0 && s.inclination <= kPi + 1e-12 &&
                    s.azimuth >= 0.0 && s.azimuth < 2.0 * kPi && (i == 0 || s.md > stations[i - 1].md);
    if (!ok) {
      std::fprintf(stderr, "station %zu read as MD %g m, inclination %g rad, azimuth %g rad\n", i, s.md,
                   s.inclination, s.azimuth);
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const units::System system : {units::System::SI, units::System::Field}) {
    try {
      CheckStations(io::ParseSurveyCsv(text, "fuzz.csv", system));
    } catch (const InputError&) {
    }
  }
  return 0;
}
