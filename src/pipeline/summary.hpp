// What a run found, in words and in the case's units: the summaries the command line prints after
// each analysis (and the Python module's str() of a result).
#pragma once

#include <ostream>
#include <string>

#include "io/case.hpp"
#include "pipeline/case_run.hpp"
#include "units/units.hpp"

namespace drillflex::pipeline {

// A value in the case's units with its unit ("1629.6 lbf"); never "-0" (a zero's sign says nothing
// to an engineer).
std::string Show(const io::Case& c, double si, units::Quantity quantity, int digits = 5);

// The summary of one finished analysis of `results` (nothing when it did not run).
void WriteSummary(std::ostream& out, const io::Case& c, Analysis analysis, const CaseResults& results);

void WriteStatic(std::ostream& out, const io::Case& c, const analyses::StaticResult& result);
// The modes with the first lateral mode's critical RPM against the rule of thumb.
void WriteModes(std::ostream& out, const analyses::ModesResult& result);
void WriteCriticalRpm(std::ostream& out, const io::Case& c, const analyses::ModesResult& result);
void WriteCampbell(std::ostream& out, const analyses::CampbellResult& result);
void WriteVibration(std::ostream& out, const io::Case& c, const analyses::VibrationResult& result);
void WriteBuckling(std::ostream& out, const io::Case& c, const analyses::BucklingResult& result);
// `driven`: a top drive, a block or a bit-rock law does work on the string; `block`: a block drive
// holds the top (its force is the hook load).
void WriteTransient(std::ostream& out, const io::Case& c, const analyses::TransientResult& result, bool driven,
                    bool block);
// The string's limits over a transient's samples: each limit's largest utilisation, where and when.
void WriteTransientLimits(std::ostream& out, const io::Case& c, const analyses::LimitsEnvelope& envelope);

}  // namespace drillflex::pipeline
