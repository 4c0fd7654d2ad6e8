// Fuzz target: a rig readings file's text -> io::ParseRigReadingsCsv and io::ParseRigReadingsWitsml
// (1.4.1.1 and 2.0 logs), the first with the well's bottom at 5000 m, the second with a mnemonic
// override. The readers' documented answer to bad input is an InputError; any other exception, a
// sanitizer report, a timeout, or readings that come back but are not what the reader promises (none at
// all, a value not finite or negative, a depth outside the well, an activity the roadmap does not model,
// a row without its line) is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "core/error.hpp"
#include "io/rig_readings.hpp"

namespace {

using namespace drillflex;

[[noreturn]] void Finding(const char* what, double value) {
  std::fprintf(stderr, "the readings read, but %s: %g\n", what, value);
  std::abort();
}

void Check(const io::RigReadings& readings, const io::RigReadingsOptions& options) {
  if (readings.rows.empty()) Finding("they hold no row", 0.0);
  for (const io::RigReading& row : readings.rows) {
    if (!(std::isfinite(row.bit_md) && row.bit_md >= 0.0)) Finding("a bit depth (m) is", row.bit_md);
    if (options.deepest_md && row.bit_md > *options.deepest_md + 1e-3) {
      Finding("a bit depth beyond the well (m) is", row.bit_md);
    }
    if (!(std::isfinite(row.hook_load) && row.hook_load >= 0.0)) Finding("a hook load (N) is", row.hook_load);
    if (!(std::isfinite(row.weight_on_bit) && row.weight_on_bit >= 0.0)) Finding("a WOB (N) is", row.weight_on_bit);
    if (!(std::isfinite(row.rotary_speed) && row.rotary_speed >= 0.0)) {
      Finding("a rotary speed (rad/s) is", row.rotary_speed);
    }
    if (row.surface_torque && !(std::isfinite(*row.surface_torque) && *row.surface_torque >= 0.0)) {
      Finding("a surface torque (N*m) is", *row.surface_torque);
    }
    if (!io::IsModelledActivity(row.activity)) {
      Finding("an activity not modelled is kept, number", static_cast<int>(row.activity));
    }
    if (row.line < 1) Finding("a row's line is", row.line);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  io::RigReadingsOptions csv_options;
  csv_options.deepest_md = 5000.0;
  try {
    Check(io::ParseRigReadingsCsv(text, "fuzz.csv", csv_options), csv_options);
  } catch (const InputError&) {}
  io::RigReadingsOptions log_options;
  log_options.mnemonics = {{"hook_load", "HKLX"}};
  for (const io::RigReadingsOptions& options : {io::RigReadingsOptions{}, log_options}) {
    try {
      Check(io::ParseRigReadingsWitsml(text, "fuzz.xml", options), options);
    } catch (const InputError&) {}
  }
  return 0;
}
