// The two generators of randomized static cases as validation::GeneratedCase (robustness_runner.hpp):
// the first (validation/robustness_cases.hpp: build and turn wells, 1–3 stabilizers) and the second
// (validation/robustness_bha_cases.hpp: motors, packed, pendulum and slick BHAs, vertical holes,
// drops and turns, rotating or not).
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

#include "robustness_bha_cases.hpp"
#include "robustness_cases.hpp"
#include "robustness_runner.hpp"

namespace drillflex::validation {

inline constexpr int kCasesPerGenerator = 200;

inline constexpr const char* kFirstGeneratorHeader =
    "seed,inclination_deg,dls_deg_per_100ft,clearance_in,hole_in,wob_klbf,stabilizers,bha_ft,string_ft";

inline GeneratedCase FirstGeneratorCase(int index) {
  const RobustnessCase c = MakeRobustnessCase(index);
  return {fmt::format("case-{:03d}", index), ToYaml(c),
          fmt::format("{},{:.3f},{:.3f},{:.4f},{},{:.3f},{},{:.2f},{:.2f}", kRobustnessSeed + index,
                      c.final_inclination_deg, c.max_dls_deg_per_100ft, c.clearance_in, c.hole_in, c.wob_klbf,
                      c.stabilizers, c.bha_length_ft, c.string_length_ft)};
}

inline constexpr const char* kSecondGeneratorHeader =
    "seed,well,bha,inclination_deg,dls_deg_per_100ft,hole_in,bend_deg,toolface_deg,wob_klbf,rpm,mud_ppg,string_ft";

inline GeneratedCase SecondGeneratorCase(int index) {
  const BhaCase c = MakeBhaCase(index);
  return {fmt::format("case-b{:03d}", index), ToYaml(c),
          fmt::format("{},{},{},{:.3f},{:.3f},{},{:.3f},{:.1f},{:.3f},{:.1f},{:.2f},{:.2f}", kBhaSeed + index,
                      WellShapeName(c.shape), BhaKindName(c.kind), c.inclination_deg, c.dls_deg_per_100ft,
                      c.hole_in, c.bend_deg, c.toolface_deg, c.wob_klbf, c.rpm, c.mud_ppg, c.string_length_ft)};
}

// 0, step, 2 step, … below kCasesPerGenerator.
inline std::vector<int> EveryNthCase(int step) {
  std::vector<int> indices;
  for (int i = 0; i < kCasesPerGenerator; i += step) indices.push_back(i);
  return indices;
}

}  // namespace drillflex::validation
