// The stability map: the case's transient at every top-drive RPM × WOB, each run's drilling regime
// (pipeline/drilling_regime.hpp: smooth, torsional oscillation, stick-slip; forward or backward whirl)
// drawn as a coloured map: the window where the string neither whirls nor sticks and slips.
#pragma once

#include <string>
#include <vector>

#include "io/case.hpp"
#include "io/result_files.hpp"
#include "pipeline/sweep_run.hpp"

namespace drillflex::pipeline {

// The runs of the map: every combination of `rpm_values` and `wob_values` (a sweep's VALUES: "60,120"
// or "40:200:20 rpm"; "10:40:10 klbf"), RPM varying slowest. Each sets `operation.rpm` and
// `operation.wob`, and the transient's top drive's `rpm` when the case drives it at a speed (the
// top drive's own setting would override the operation's). InputError naming `analyses.transient`
// when the case has no transient.
std::vector<SweepCombination> StabilityCombinations(const io::Case& c, const std::string& rpm_values,
                                                    const std::string& wob_values);

// sweep.csv and sweep.json of the rows (ComposeSweepFiles), sweep.json with the map (`stability`: each
// run's RPM and WOB in the case's output units, its regime, severity and whirl), and report.html with
// the map when `report`.
io::ResultFiles ComposeStabilityFiles(const io::Case& c, const std::vector<SweepRow>& rows,
                                      const std::string& directory, bool report, double run_seconds);

}  // namespace drillflex::pipeline
