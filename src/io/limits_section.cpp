// Reads `limits:`: the design factor (analyses/string_limits.hpp) and the casing wear run
// (model/casing_wear.hpp, pipeline/casing_wear_run.hpp).
#include <fmt/format.h>

#include <algorithm>

#include "io/case_sections.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

// White & Dawson's wear factors lie between about 0.1 and 100 × 1e-10 1/psi (steel joints on casing in
// water-based and oil-based muds, with and without hardbanding): a value outside 1e-13 to 1e-7 1/psi is a
// unit mistake.
constexpr double kPsi = 4.4482216152605 / (0.0254 * 0.0254);  // Pa
constexpr double kLeastWearFactor = 1e-13 / kPsi;
constexpr double kLargestWearFactor = 1e-7 / kPsi;

WearConfig ReadWear(const YamlView& node, const Case& c) {
  node.ExpectMap("a casing wear run ({factor: 5e-10 1/psi, rotating_time: 100 h} or {factor, rop: 60 ft/h, from: MD})",
                 false);
  node.AllowOnlyKeys({"factor", "rotating_time", "rop", "from", "rpm"});
  WearConfig wear;
  wear.wear_factor = node.Positive("factor", Quantity::WearFactor);
  if (wear.wear_factor < kLeastWearFactor || wear.wear_factor > kLargestWearFactor) {
    node.Child("factor").Fail(fmt::format("expected a wear factor between 1e-13 and 1e-7 1/psi (White & Dawson's lie "
                                          "near 1e-10 1/psi = 1e-10 in²/lbf), got {:.3g} 1/psi",
                                          wear.wear_factor * kPsi));
  }
  wear.rotating_time = node.OptionalPositive("rotating_time", Quantity::Time);
  wear.rate_of_penetration = node.OptionalPositive("rop", Quantity::Velocity);
  wear.from_md = node.OptionalPositive("from", Quantity::Length);
  if (wear.rotating_time && (wear.rate_of_penetration || wear.from_md)) {
    node.Child("rotating_time").Fail("give either 'rotating_time' (at the bit MD) or 'rop' and 'from' (drilling ahead), not both");
  }
  if (!wear.rotating_time && !(wear.rate_of_penetration && wear.from_md)) {
    node.Fail("expected 'rotating_time' (hours rotating at the bit MD: \"100 h\") or 'rop' and 'from' (drilling ahead "
              "from MD 'from' to the bit MD at 'rop': \"60 ft/h\")");
  }
  if (wear.from_md && c.well && !(*wear.from_md < c.well->bit_md)) {
    node.Child("from").Fail("expected an MD above the bit's (drilling ahead from 'from' to the bit MD)");
  }
  wear.rotary_speed = node.OptionalPositive("rpm", Quantity::RotarySpeed).value_or(c.input.operation.rotary_speed);
  if (!(wear.rotary_speed > 0.0)) {
    node.Fail("casing wear needs a rotating string: give 'rpm' here or 'operation.rpm'");
  }
  const bool cased = c.well && std::any_of(c.well->hole.begin(), c.well->hole.end(),
                                           [](const well::HoleSection& section) { return section.cased; });
  if (!cased) node.Fail("casing wear needs a cased hole section (well.hole: {to: MD, diameter: D, cased: true})");
  return wear;
}

}  // namespace

LimitsConfig ReadLimitsSection(const YamlView& node, const Case& c) {
  node.ExpectMap("the string's limits ({design_factor: 1.25, wear: {...}})");
  node.AllowOnlyKeys({"design_factor", "wear"});
  LimitsConfig limits;
  if (const auto factor = node.OptionalChild("design_factor")) {
    limits.design_factor = factor->AsQuantity(Quantity::Dimensionless);
    if (!(limits.design_factor >= 1.0 && limits.design_factor <= 3.0)) {
      factor->Fail("expected a design factor between 1 and 3 (the allowable stress is yield / design factor)");
    }
  }
  if (const auto wear = node.OptionalChild("wear")) limits.wear = ReadWear(*wear, c);
  return limits;
}

}  // namespace drillflex::io
