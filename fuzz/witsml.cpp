// Fuzz target: a WITSML document's text -> io::ReadWitsml (1.4.1.1 or 2.0 trajectory, tubular,
// wbGeometry), its content as drillflex input (SurveyOf, HoleOf, ComponentOf), and the imported case's
// text (ImportedCaseText) read back by io::ParseCase, as `drillflex import` does before it writes.
// The readers' documented answer to bad input is an InputError; any other exception, a sanitizer
// report, a timeout, or content that reads but is not what the reader promises (a non-finite value,
// MDs not increasing, an angle out of range, a component without a positive OD and length) is a
// finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "io/case.hpp"
#include "io/witsml.hpp"
#include "io/witsml_case.hpp"

namespace {

using namespace drillflex;

[[noreturn]] void Finding(const char* what, double value) {
  std::fprintf(stderr, "the document reads, but %s: %g\n", what, value);
  std::abort();
}

void CheckSurvey(const std::vector<well::SurveyStation>& survey) {
  for (std::size_t i = 0; i < survey.size(); ++i) {
    const well::SurveyStation& s = survey[i];
    if (!std::isfinite(s.md) || (i > 0 && !(s.md > survey[i - 1].md))) Finding("a station's MD (m) is", s.md);
    if (!(s.inclination >= 0.0 && s.inclination <= kPi + 1e-12)) Finding("an inclination (rad) is", s.inclination);
    if (!(std::isfinite(s.azimuth))) Finding("an azimuth (rad) is", s.azimuth);
  }
}

void CheckContent(const io::WitsmlDocument& document) {
  for (const io::WitsmlTrajectory& trajectory : document.trajectories) CheckSurvey(io::SurveyOf(trajectory));
  for (const io::WitsmlGeometry& geometry : document.geometries) {
    for (const well::HoleSection& section : io::HoleOf(geometry)) {
      if (!(section.diameter > 0.0 && std::isfinite(section.diameter))) Finding("a hole diameter (m) is", section.diameter);
    }
  }
  for (const io::WitsmlTubular& tubular : document.tubulars) {
    for (const io::WitsmlComponent& item : tubular.components) {
      const model::Component component = io::ComponentOf(item);
      if (!(component.outer_diameter > 0.0 && std::isfinite(component.outer_diameter))) {
        Finding("a component's OD (m) is", component.outer_diameter);
      }
      if (!(component.length > 0.0 && std::isfinite(component.length))) Finding("a component's length (m) is", component.length);
      if (component.count < 1) Finding("a component's count is", component.count);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  io::WitsmlDocument document;
  try {
    document = io::ReadWitsml(text, "fuzz.xml");
  } catch (const InputError&) {
    return 0;
  }
  CheckContent(document);
  // The import: a case's text from the document, read back as drillflex import reads it.
  try {
    const std::string case_text = io::ImportedCaseText({document});
    io::ParseCase(case_text, "imported.yaml", "/nonexistent-fuzz-directory");
  } catch (const InputError&) {
  }
  return 0;
}
