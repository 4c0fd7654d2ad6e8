// Quantities, their default units per system, and reading "<number> [unit]" values (units.hpp).
// The unit symbols are in unit_table.cpp, the expression parser in unit_expression.cpp.
#include "units/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "units/unit_table.hpp"

namespace drillflex::units {

namespace {

struct QuantityInfo {
  Quantity quantity;
  std::string_view name;
  Dimension dimension;
  std::string_view si_unit;
  std::string_view field_unit;
};

constexpr Dimension kLength{1, 0, 0, 0};
constexpr Dimension kForce{1, 1, -2, 0};
constexpr Dimension kForcePerLength{0, 1, -2, 0};

// One row per Quantity, in the enum's order (checked below).
constexpr std::array kQuantities{
    QuantityInfo{Quantity::Dimensionless, "a dimensionless number", {}, "", ""},
    QuantityInfo{Quantity::Length, "a length", kLength, "m", "ft"},
    QuantityInfo{Quantity::Diameter, "a diameter (length)", kLength, "m", "in"},
    QuantityInfo{Quantity::Force, "a force", kForce, "N", "lbf"},
    QuantityInfo{Quantity::WeightOnBit, "a weight on bit (force)", kForce, "N", "klbf"},
    QuantityInfo{Quantity::Moment, "a moment or torque (force x length)", {2, 1, -2, 0}, "N*m",
                 "ft*lbf"},
    QuantityInfo{Quantity::Density, "a density", {-3, 1, 0, 0}, "kg/m3", "ppg"},
    QuantityInfo{Quantity::Viscosity, "a dynamic viscosity", {-1, 1, -1, 0}, "Pa*s", "cP"},
    QuantityInfo{Quantity::Stress, "a stress, pressure or modulus", {-1, 1, -2, 0}, "Pa", "psi"},
    QuantityInfo{Quantity::Angle, "an angle", {0, 0, 0, 1}, "deg", "deg"},
    QuantityInfo{Quantity::RotarySpeed, "a rotary speed", {0, 0, -1, 1}, "rpm", "rpm"},
    QuantityInfo{Quantity::Time, "a time", {0, 0, 1, 0}, "s", "s"},
    QuantityInfo{Quantity::Mass, "a mass", {0, 1, 0, 0}, "kg", "lb"},
    QuantityInfo{Quantity::MassPerLength, "a mass per length", {-1, 1, 0, 0}, "kg/m", "lb/ft"},
    QuantityInfo{Quantity::ForcePerLength, "a force per length", kForcePerLength, "N/m", "lbf/ft"},
    QuantityInfo{Quantity::DoglegSeverity, "a dogleg severity (angle per length)", {-1, 0, 0, 1},
                 "deg/30m", "deg/100ft"},
    QuantityInfo{Quantity::Imbalance, "an imbalance (mass x length)", {1, 1, 0, 0}, "kg*m",
                 "lb*in"},
    QuantityInfo{Quantity::Stiffness, "a stiffness (force per length)", kForcePerLength, "N/m",
                 "lbf/in"},
    QuantityInfo{Quantity::RotationalStiffness, "a rotational stiffness (moment per angle)",
                 {2, 1, -2, -1}, "N*m/rad", "ft*lbf/rad"},
    QuantityInfo{Quantity::Velocity, "a velocity", {1, 0, -1, 0}, "m/s", "ft/s"},
    QuantityInfo{Quantity::Acceleration, "an acceleration", {1, 0, -2, 0}, "m/s2", "m/s2"},
    QuantityInfo{Quantity::Frequency, "a frequency", {0, 0, -1, 0}, "Hz", "Hz"},
    QuantityInfo{Quantity::FlowRate, "a flow rate", {3, 0, -1, 0}, "m3/s", "gpm"},
    QuantityInfo{Quantity::RevolutionsPerVolume, "revolutions per volume (angle per volume)",
                 {-3, 0, 0, 1}, "rev/m3", "rev/gal"},
    QuantityInfo{Quantity::WearFactor, "a wear factor (per stress)", {1, -1, 2, 0}, "1/Pa", "1/psi"},
};

constexpr bool QuantityTableInEnumOrder() {
  for (std::size_t i = 0; i < kQuantities.size(); ++i) {
    if (static_cast<std::size_t>(kQuantities[i].quantity) != i) return false;
  }
  return kQuantities.back().quantity == Quantity::WearFactor;
}
static_assert(QuantityTableInEnumOrder(), "kQuantities must list every Quantity in enum order");

const QuantityInfo& InfoOf(Quantity quantity) {
  const auto index = static_cast<std::size_t>(quantity);
  if (index >= kQuantities.size()) throw LogicError("units: Quantity value out of range");
  return kQuantities[index];
}

// Factors to SI of every default unit, parsed once; a default unit of the wrong dimension is a bug.
double DefaultFactor(Quantity quantity, System system) {
  static const auto factors = [] {
    std::array<std::array<double, 2>, kQuantities.size()> result{};
    for (std::size_t i = 0; i < kQuantities.size(); ++i) {
      const Unit si = ParseUnit(kQuantities[i].si_unit);
      const Unit field = ParseUnit(kQuantities[i].field_unit);
      if (!(si.dimension == kQuantities[i].dimension) ||
          !(field.dimension == kQuantities[i].dimension)) {
        throw LogicError("units: a default unit has the wrong dimension");
      }
      result[i] = {si.to_si, field.to_si};
    }
    return result;
  }();
  return factors[static_cast<std::size_t>(quantity)][system == System::SI ? 0 : 1];
}

struct DimensionLabel {
  Dimension dimension;
  std::string_view name;
};

constexpr std::array kDimensionNames{
    DimensionLabel{{0, 0, 0, 0}, "a dimensionless number"},
    DimensionLabel{{1, 0, 0, 0}, "a length"},
    DimensionLabel{{0, 1, 0, 0}, "a mass"},
    DimensionLabel{{0, 0, 1, 0}, "a time"},
    DimensionLabel{{0, 0, 0, 1}, "an angle"},
    DimensionLabel{{2, 0, 0, 0}, "an area"},
    DimensionLabel{{3, 0, 0, 0}, "a volume"},
    DimensionLabel{{1, 1, -2, 0}, "a force"},
    DimensionLabel{{2, 1, -2, 0}, "a moment (force x length)"},
    DimensionLabel{{-3, 1, 0, 0}, "a density"},
    DimensionLabel{{-1, 1, -2, 0}, "a pressure or stress"},
    DimensionLabel{{-1, 1, -1, 0}, "a dynamic viscosity"},
    DimensionLabel{{0, 0, -1, 1}, "a rotary speed"},
    DimensionLabel{{0, 0, -2, 1}, "an angular acceleration"},
    DimensionLabel{{0, 0, -1, 0}, "a frequency"},
    DimensionLabel{{-1, 1, 0, 0}, "a mass per length"},
    DimensionLabel{{0, 1, -2, 0}, "a force per length"},
    DimensionLabel{{-1, 0, 0, 1}, "an angle per length (dogleg severity)"},
    DimensionLabel{{1, 1, 0, 0}, "a mass x length (imbalance)"},
    DimensionLabel{{2, 1, 0, 0}, "a mass moment of inertia"},
    DimensionLabel{{2, 1, -2, -1}, "a rotational stiffness (moment per angle)"},
    DimensionLabel{{1, 0, -1, 0}, "a velocity"},
    DimensionLabel{{1, 0, -2, 0}, "an acceleration"},
    DimensionLabel{{3, 0, -1, 0}, "a flow rate"},
    DimensionLabel{{-3, 0, 0, 1}, "an angle per volume (revolutions per volume)"},
};

void AppendPower(std::string& text, std::string_view symbol, int exponent) {
  if (exponent == 0) return;
  if (!text.empty()) text.append(" ");
  text.append(symbol);
  if (exponent != 1) text.append("^").append(std::to_string(exponent));
}

constexpr std::string_view kNumberExpected =
    R"(expected a number with an optional unit (e.g. "8.5 in", "8-1/2 in" or "30e6 psi"))";

[[noreturn]] void ThrowNotANumber(std::string_view text) {
  std::string message(kNumberExpected);
  message.append(", but got ").append(Quoted(text));
  throw UnitError(message);
}

bool AllDigits(std::string_view text) {
  if (text.empty()) return false;
  for (char c : text) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

std::size_t CountDigits(std::string_view text) {
  std::size_t count = 0;
  while (count < text.size() && text[count] >= '0' && text[count] <= '9') ++count;
  return count;
}

// Reads "<digits>/<digits>" at the start of text; returns its value and length. The fraction must
// not run on into a longer number ("1/2.5").
std::optional<std::pair<double, std::size_t>> ReadFraction(std::string_view text) {
  const std::size_t numerator_digits = CountDigits(text);
  if (numerator_digits == 0 || numerator_digits >= text.size() || text[numerator_digits] != '/') {
    return std::nullopt;
  }
  const std::string_view after_slash = text.substr(numerator_digits + 1);
  const std::size_t denominator_digits = CountDigits(after_slash);
  if (denominator_digits == 0) return std::nullopt;
  if (denominator_digits < after_slash.size() && after_slash[denominator_digits] == '.') {
    return std::nullopt;
  }
  double numerator = 0.0;
  double denominator = 0.0;
  std::from_chars(text.data(), text.data() + numerator_digits, numerator);
  std::from_chars(after_slash.data(), after_slash.data() + denominator_digits, denominator);
  if (denominator == 0.0) return std::nullopt;
  return std::make_pair(numerator / denominator, numerator_digits + 1 + denominator_digits);
}

// Reads the number at the start of text, with an optional fraction ("1/2") or mixed fraction
// ("8-1/2", "8 1/2"); returns the value and what follows it.
std::pair<double, std::string_view> ReadNumber(std::string_view text) {
  const std::size_t sign_length = text.starts_with('+') ? 1 : 0;
  const char* begin = text.data() + sign_length;
  double value = 0.0;
  const auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range) {
    std::string message = "the number in ";
    message.append(Quoted(text)).append(" is out of range");
    throw UnitError(message);
  }
  if (error != std::errc() || (sign_length == 1 && (*begin == '-' || *begin == '+'))) {
    ThrowNotANumber(text);
  }
  if (!std::isfinite(value)) {
    std::string message = Quoted(text);
    message.append(" is not a finite number");
    throw UnitError(message);
  }
  const std::string_view number(begin, static_cast<std::size_t>(end - begin));
  std::string_view rest = text.substr(static_cast<std::size_t>(end - text.data()));
  const bool negative = number.starts_with('-');
  if (!AllDigits(negative ? number.substr(1) : number)) return {value, rest};

  // "1/2": the integer just read is the numerator.
  if (rest.starts_with('/')) {
    const char* digits = negative ? begin + 1 : begin;
    const std::string_view from_digits(digits, static_cast<std::size_t>(text.data() + text.size() - digits));
    if (const auto fraction = ReadFraction(from_digits)) {
      return {negative ? -fraction->first : fraction->first, from_digits.substr(fraction->second)};
    }
    return {value, rest};
  }
  // "8-1/2" or "8 1/2": a whole number, one '-' or some spaces, then a fraction.
  std::size_t gap = 0;
  if (rest.starts_with('-')) {
    gap = 1;
  } else {
    while (gap < rest.size() && (rest[gap] == ' ' || rest[gap] == '\t')) ++gap;
  }
  if (gap == 0) return {value, rest};
  if (const auto fraction = ReadFraction(rest.substr(gap))) {
    rest.remove_prefix(gap + fraction->second);
    return {negative ? value - fraction->first : value + fraction->first, rest};
  }
  return {value, rest};
}

// ParseUnit, with the whole value named in its error messages.
Unit ParseUnitOfValue(std::string_view unit_text, std::string_view value_text) {
  try {
    return ParseUnit(unit_text);
  } catch (const UnitError& error) {
    std::string message = Quoted(value_text);
    message.append(": ").append(error.what());
    throw UnitError(message);
  }
}

// '"12.5 ppg" is a density, but a diameter (length) is expected (field unit: in)'.
[[noreturn]] void ThrowWrongDimension(std::string_view value_text, const Dimension& given,
                                      Quantity quantity, System system) {
  std::string message = Quoted(value_text);
  message.append(" is ").append(DimensionName(given)).append(", but ");
  message.append(QuantityName(quantity)).append(" is expected");
  const std::string_view default_unit = DefaultUnit(quantity, system);
  if (default_unit.empty()) {
    message.append(" (a bare number)");
  } else {
    message.append(" (").append(SystemName(system)).append(" unit: ");
    message.append(default_unit).append(")");
  }
  throw UnitError(message);
}

}  // namespace

Dimension DimensionOf(Quantity quantity) { return InfoOf(quantity).dimension; }

std::string QuantityName(Quantity quantity) { return std::string(InfoOf(quantity).name); }

std::string DimensionName(const Dimension& dimension) {
  for (const DimensionLabel& label : kDimensionNames) {
    if (label.dimension == dimension) return std::string(label.name);
  }
  std::string powers;
  AppendPower(powers, "m", dimension.length);
  AppendPower(powers, "kg", dimension.mass);
  AppendPower(powers, "s", dimension.time);
  AppendPower(powers, "rad", dimension.angle);
  std::string name = "a quantity in ";
  name.append(powers);
  return name;
}

std::string_view DefaultUnit(Quantity quantity, System system) {
  const QuantityInfo& info = InfoOf(quantity);
  return system == System::SI ? info.si_unit : info.field_unit;
}

double ToSI(double value, Quantity quantity, System system) {
  return value * DefaultFactor(quantity, system);
}

double FromSI(double value_in_si, Quantity quantity, System system) {
  return value_in_si / DefaultFactor(quantity, system);
}

double ParseQuantity(std::string_view text, Quantity quantity, System system) {
  const std::string_view trimmed = TrimSpace(text);
  if (trimmed.empty()) {
    std::string message(kNumberExpected);
    message.append(", but the value is empty");
    throw UnitError(message);
  }
  const auto [value, rest] = ReadNumber(trimmed);
  const std::string_view unit_text = TrimSpace(rest);
  const Unit unit = unit_text.empty() ? Unit{DefaultFactor(quantity, system), DimensionOf(quantity)}
                                      : ParseUnitOfValue(unit_text, trimmed);
  if (!(unit.dimension == DimensionOf(quantity))) {
    ThrowWrongDimension(trimmed, unit.dimension, quantity, system);
  }
  const double value_in_si = value * unit.to_si;
  if (!std::isfinite(value_in_si)) {
    std::string message = Quoted(trimmed);
    message.append(" is out of range");
    throw UnitError(message);
  }
  return value_in_si;
}

System ParseSystem(std::string_view text) {
  const std::string_view trimmed = TrimSpace(text);
  const auto equals_ignoring_case = [&](std::string_view name) {
    return EditDistanceIgnoringCase(trimmed, name) == 0;
  };
  if (equals_ignoring_case("SI")) return System::SI;
  if (equals_ignoring_case("field")) return System::Field;
  std::string message = "unknown unit system ";
  message.append(Quoted(trimmed)).append(": expected \"SI\" or \"field\"");
  throw UnitError(message);
}

std::string_view SystemName(System system) { return system == System::SI ? "SI" : "field"; }

}  // namespace drillflex::units
