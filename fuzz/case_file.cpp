// Fuzz target: a case file's text -> io::ParseCase, and a small case that reads -> the model builder.
// The reader's documented answer to bad input is an InputError (the builder may also stop with a
// SolverError); any other exception, a sanitizer report, a timeout, or a case that reads but would
// not fit in memory (a string of non-finite length, a model of over 1e5 bodies, a trajectory table of
// over 1e7 rows) or gives a non-finite trajectory is a finding. survey_file is resolved in an empty
// directory (no file is read).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>

#include <unistd.h>

#include "cms/reduction_cache.hpp"
#include "io/case.hpp"
#include "io/trajectory_table.hpp"
#include "model/builder.hpp"

namespace {

using namespace drillflex;

// A new empty directory, removed when the fuzzer exits (after -max_total_time, not after a crash).
std::string EmptyDirectory() {
  static char path[] = "/tmp/drillflex-fuzz-XXXXXX";
  if (mkdtemp(path) == nullptr) {
    std::perror("mkdtemp");
    std::abort();
  }
  std::atexit([] { rmdir(path); });
  return path;
}

[[noreturn]] void Finding(const char* what, double value) {
  std::fprintf(stderr, "the case reads, but %s: %g\n", what, value);
  std::abort();
}

// About how many bodies the builder cuts the string into (model/builder.cpp CutBodies).
double BodyCount(const io::Case& c) {
  double bodies = static_cast<double>(c.input.supports.size());
  for (const auto& component : c.input.string.components) {
    bodies += std::ceil(component.length * component.count / c.input.settings.body_length) + 1.0;
  }
  return bodies;
}

// Rows of `drillflex well`'s trajectory table (io/trajectory_table.cpp).
double TrajectoryRows(const io::WellConfig& well) {
  double rows = 1.0;
  for (std::size_t i = 0; i + 1 < well.survey.size(); ++i) {
    rows += std::ceil((well.survey[i + 1].md - well.survey[i].md) / well.output_step);
  }
  return rows;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string directory = EmptyDirectory();
  io::Case c;
  try {
    c = io::ParseCase(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml", directory);
  } catch (const InputError&) {
    return 0;
  }
  // What a case that reads must not be: the reader refuses what would not fit in memory.
  const double length = io::StringLength(c);
  if (!std::isfinite(length) || !(length > 0.0)) Finding("its string's length in m is", length);
  const double bodies = BodyCount(c);
  if (!(bodies <= 1e5)) Finding("the model would have this many bodies", bodies);
  if (c.well) {
    const double rows = TrajectoryRows(*c.well);
    if (!(rows <= 1e7)) Finding("the trajectory table would have this many rows", rows);
    if (rows <= 2000) {
      for (const auto& row : io::TrajectoryTable(*c.well)) {
        if (!std::isfinite(row.north + row.east + row.tvd + row.dogleg_severity)) Finding("a trajectory row at MD", row.md);
      }
    }
  }
  // Builds only what builds in a few milliseconds: the fuzzer's speed is its reach.
  if (c.input.settings.elements_per_body > 12 || bodies > 40.0) return 0;
  try {
    cms::ReductionCache cache;
    const model::BuiltModel built = model::BuildSystemModel(c.input, cache);
    if (!std::isfinite(built.force_scale)) {
      std::fprintf(stderr, "the model builds with a force scale of %g N\n", built.force_scale);
      std::abort();
    }
  } catch (const InputError&) {
  } catch (const SolverError&) {
  }
  return 0;
}
