// The rig's readings (hook load, surface torque, WOB, rotary speed at a bit depth, with what the rig was
// doing) from a readings CSV or a WITSML 1.4.1.1 or 2.0 `log`, in SI, for the roadmap's broomstick and
// the calibration. docs/case-format.md "Rig readings" has the contract.
//
// CSV (../shared/spec/case-format.md "Rig readings"): a header, a line of units ("-" for none), one row
// a reading; columns bit_md, activity, hook_load, surface_torque (may be empty), wob, rpm in any order,
// further columns ignored; blank lines and '#' comments allowed.
// WITSML log: the curves by mnemonic (RigReadingsOptions::mnemonics overrides them), the rows
// classified by io/rig_activity.hpp; rows lacking a value the reading needs are left out and counted.
//
// Only drilling, rotating, pick_up and slack_off rows are returned; the others are counted in a warning.
// Bad input throws InputError naming the file, the line, the column (CSV) or curve (log) and what was
// expected; nothing partial is returned.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/rig_activity.hpp"

namespace drillflex::io {

struct RigReading {
  double bit_md = 0.0;  // m
  RigActivity activity = RigActivity::kDrilling;
  double hook_load = 0.0;                // N
  std::optional<double> surface_torque;  // N·m; none where not read
  double weight_on_bit = 0.0;            // N
  double rotary_speed = 0.0;             // rad/s
  int line = 0;                          // the CSV line, or the XML line of the row's data
};

struct RigReadingsOptions {
  std::optional<double> deepest_md;  // m: the well's bottom; a bit_md beyond it (or < 0) is refused
  // WITSML curves in place of the usual mnemonics, by what they hold: bit_md, hole_md, block_position,
  // hook_load, surface_torque, weight_on_bit, rotary_speed ({"hook_load": "HKLX"}). Any other key is
  // refused.
  std::map<std::string, std::string> mnemonics;
  // N: a log's rows with a lower hook load are in slips; none: InSlipsHookLoad of the log's hook loads.
  std::optional<double> in_slips_hook_load;
  // The classification's other thresholds (its in_slips_hook_load is the one above).
  RigActivityThresholds thresholds;
};

struct RigReadings {
  std::string file;
  std::vector<RigReading> rows;       // drilling, rotating, pick_up and slack_off rows only, in the file's order
  std::vector<std::string> warnings;  // "240 rows left out: 200 in_slips, 40 other"
};

// Reads a readings CSV or a WITSML log (1.4.1.1 or 2.0), told apart by content (XML starts with '<').
// Throws InputError.
RigReadings ReadRigReadings(const std::string& path, const RigReadingsOptions& options = {});
// The same from text in memory; `file` names it in messages.
RigReadings ParseRigReadings(std::string_view text, const std::string& file, const RigReadingsOptions& options = {});
RigReadings ParseRigReadingsCsv(std::string_view text, const std::string& file, const RigReadingsOptions& options);
RigReadings ParseRigReadingsWitsml(std::string_view text, const std::string& file, const RigReadingsOptions& options);

}  // namespace drillflex::io
