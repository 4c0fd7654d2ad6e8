// Survey stations as the case reader takes them, inline or from a CSV file: each checked on its own
// and against the one before it.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "units/units.hpp"
#include "well/survey.hpp"

namespace drillflex::io {

// A station with its azimuth brought into [0, 2π).
well::SurveyStation NormalizedStation(double md, double inclination, double azimuth);

// Calls `fail` with what is wrong: a negative MD, an inclination outside [0, 180] deg, an MD not
// past the previous station's (`previous` may be null).
void CheckStation(const well::SurveyStation& station, const well::SurveyStation* previous,
                  const std::function<void(const std::string&)>& fail);

// The stations of a survey CSV's text: three columns MD, inclination, azimuth, bare numbers in
// `system`'s units or with their own; a header line, blank lines and '#' comments allowed. Throws
// InputError at "file:line" with the key path well.survey_file. Fewer than two stations is left to
// the caller (it names the case's key).
std::vector<well::SurveyStation> ParseSurveyCsv(std::string_view text, const std::string& file,
                                                units::System system);

}  // namespace drillflex::io
