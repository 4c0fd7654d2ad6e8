// A WITSML log as a table (internal to io/): the 1.4.1.1 and 2.0 readers (io/rig_readings_witsml.cpp)
// bring their documents to it, and ReadingsOfLog finds the curves, converts the values and classifies
// the rows (io/rig_readings_log.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/rig_readings.hpp"

namespace drillflex::io {

// Where a part of the document is, for messages: "file:line:column: path: ...".
struct LogPlace {
  SourceLocation location;
  std::string path;  // the element's path from the root ("logs/log[uid=l1]/logCurveInfo[uid=HKLD]")
};

struct LogCurve {
  std::string mnemonic;
  std::string uom;                        // as written; "" when the document gives none
  std::optional<std::string> null_value;  // a cell equal to it (as text or number) has no value
  LogPlace place;                         // the element declaring it
};

struct LogRow {
  int line = 0;
  std::vector<std::string> cells;  // one a curve, as text; "" for no value (empty, JSON null)
};

struct LogTable {
  std::string name;  // "log 'F-5 time'", "ChannelSet 'surface'"
  LogPlace place;    // the log (1.4.1.1) or ChannelSet (2.0)
  LogPlace data;     // the element holding the rows
  std::vector<LogCurve> curves;
  std::optional<std::size_t> index;  // the index curve, where the document names it
  std::vector<LogRow> rows;          // each with a cell a curve
};

// The readings of every row of `table` that has the values a reading needs, each classified
// (io/rig_activity.hpp); rows left out are counted in `warnings`. Throws InputError for a curve
// missing altogether, a unit not known or of the wrong kind, an unreadable value or a depth outside the
// well.
std::vector<RigReading> ReadingsOfLog(const LogTable& table, const RigReadingsOptions& options,
                                      std::vector<std::string>& warnings);

}  // namespace drillflex::io
