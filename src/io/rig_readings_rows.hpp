// What the readers of rig readings share (internal to io/): a cell's number, a unit's factor to SI for
// the quantity a column holds, the depth check, and the last step, keeping the rows the roadmap models.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/rig_readings.hpp"
#include "units/units.hpp"

namespace drillflex::io {

// The whole text as a finite number ("1343.0", " 99 "), else none.
std::optional<double> ParseNumber(std::string_view text);

// The factor to SI of `unit` for `quantity`; calls `fail` (which throws) with what is wrong: an empty,
// unknown or malformed unit, or one of another kind.
double FactorToSi(std::string_view unit, units::Quantity quantity, const std::function<void(const std::string&)>& fail);

// What is wrong with a bit depth for `options` (below 0, beyond deepest_md), else "".
std::string DepthProblem(double bit_md, const RigReadingsOptions& options);

// The readings of `rows` that the roadmap models (drilling, rotating, pick_up, slack_off), the others
// counted in a warning by activity. Throws InputError at `where` (`no_rows` saying why) when none is left.
RigReadings KeptReadings(const std::string& file, const std::vector<RigReading>& rows,
                         std::vector<std::string> warnings, const SourceLocation& where, const std::string& no_rows);

}  // namespace drillflex::io
