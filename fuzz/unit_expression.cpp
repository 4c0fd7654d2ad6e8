// Fuzz target: a unit expression or a value with a unit -> units::ParseUnit, units::ParseQuantity
// (the quantity and unit system chosen by the first byte) and units::ParseSystem. Bad input must end
// in a UnitError; any other exception, a sanitizer report (an integer overflow of an exponent among
// them), a timeout, or a unit or value read as zero, negative factor, infinite or NaN is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "core/error.hpp"
#include "units/units.hpp"

namespace {

using namespace drillflex;

constexpr int kQuantityCount = static_cast<int>(units::Quantity::RevolutionsPerVolume) + 1;

void Finding(const char* what, std::string_view text, double value) {
  std::fprintf(stderr, "%s: '%.*s' read as %g\n", what, static_cast<int>(text.size()), text.data(), value);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto quantity = static_cast<units::Quantity>(data[0] % kQuantityCount);
  const auto system = (data[0] / kQuantityCount) % 2 == 0 ? units::System::SI : units::System::Field;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const units::Unit unit = units::ParseUnit(text);
    if (!std::isfinite(unit.to_si) || !(unit.to_si > 0.0)) Finding("a unit's factor to SI", text, unit.to_si);
  } catch (const UnitError&) {
  }
  try {
    const double value = units::ParseQuantity(text, quantity, system);
    if (!std::isfinite(value)) Finding("a value", text, value);
  } catch (const UnitError&) {
  }
  try {
    units::ParseSystem(text);
  } catch (const UnitError&) {
  }
  return 0;
}
