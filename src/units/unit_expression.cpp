// The unit expression parser: ParseUnit and Convert of units.hpp.
//
// Grammar (informal):  expression = product [ '/' ( product | '(' product ')' ) ]
//                      product    = factor { separator factor },  separator = '*' '·' '×' '.' '-' space
//                      factor     = [number] [symbol [exponent]]
//                      exponent   = digits | '^' ['-'|'+'] digits | '-' digits | superscripts (⁻¹²³...)
// Everything after the single '/' is in the denominator, so "deg/100 ft" is deg/(100 ft).
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "units/unit_table.hpp"
#include "units/units.hpp"

namespace drillflex::units {

namespace {

// An error about the expression as a whole: 'unit "m/s/s": <what>'.
UnitError ExpressionError(std::string_view expression, std::string_view what) {
  std::string message = "unit ";
  message.append(Quoted(expression)).append(": ").append(what);
  return UnitError(message);
}

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

// Length in bytes of a factor separator starting at text[at], 0 if there is none. A '.' followed
// by a digit belongs to a number ("30.48cm"); otherwise it separates ("ft.lbf"). A '-' before a
// letter separates ("ft-lbf"); before a digit it is an exponent's sign ("s-1").
std::size_t SeparatorLength(std::string_view text, std::size_t at) {
  const std::string_view rest = text.substr(at);
  const char c = rest.front();
  if (c == ' ' || c == '\t' || c == '*') return 1;
  if (c == '.') return (rest.size() > 1 && IsDigit(rest[1])) ? 0 : 1;
  if (c == '-') return (rest.size() > 1 && !IsDigit(rest[1])) ? 1 : 0;  // "ft-lbf", not "s-1"
  for (std::string_view multi_byte : {"\u00B7", "\u00D7", "\u22C5"}) {  // · × ⋅
    if (rest.starts_with(multi_byte)) return multi_byte.size();
  }
  return 0;
}

// The value of a trailing superscript digit (UTF-8) and its length in bytes, or {-1, 0}.
std::pair<int, std::size_t> TrailingSuperscriptDigit(std::string_view text) {
  if (text.ends_with("\u00B9")) return {1, 2};
  if (text.ends_with("\u00B2")) return {2, 2};
  if (text.ends_with("\u00B3")) return {3, 2};
  static constexpr std::string_view kOthers[] = {"\u2070", "", "", "", "\u2074", "\u2075",
                                                 "\u2076", "\u2077", "\u2078", "\u2079"};
  for (int digit = 0; digit <= 9; ++digit) {
    if (!kOthers[digit].empty() && text.ends_with(kOthers[digit])) {
      return {digit, kOthers[digit].size()};
    }
  }
  return {-1, 0};
}

// The largest power of a unit symbol: no unit in use goes past m^4, and with the bound neither the
// factor to SI of one symbol (km^9 is 1e27) nor the dimension's integer exponents can overflow.
constexpr int kMaxExponent = 9;
// The largest power of a base dimension that a whole expression may reach ("m m m ...").
constexpr int kMaxDimensionPower = 99;

[[noreturn]] void ThrowExponentOutOfRange(std::string_view expression) {
  throw ExpressionError(expression, "an exponent must lie between -" + std::to_string(kMaxExponent) + " and " +
                                        std::to_string(kMaxExponent) + " (and not be 0)");
}

// Removes a trailing exponent from a factor and returns it (1 when there is none).
int StripExponent(std::string_view& factor, std::string_view expression) {
  int exponent = 0;
  int place = 1;
  bool found = false;
  while (true) {
    const auto [digit, bytes] = TrailingSuperscriptDigit(factor);
    if (bytes == 0) break;
    if (place > kMaxExponent) ThrowExponentOutOfRange(expression);  // a second digit
    exponent += digit * place;
    place *= 10;
    found = true;
    factor.remove_suffix(bytes);
  }
  if (found) {
    if (factor.ends_with("\u207B")) {  // superscript minus
      exponent = -exponent;
      factor.remove_suffix(std::string_view("\u207B").size());
    }
  } else {
    std::size_t digits = 0;
    while (digits < factor.size() && IsDigit(factor[factor.size() - 1 - digits])) ++digits;
    if (digits > 0) {
      const std::string_view text = factor.substr(factor.size() - digits);
      const std::from_chars_result read = std::from_chars(text.data(), text.data() + text.size(), exponent);
      if (read.ec != std::errc() || exponent > kMaxExponent) ThrowExponentOutOfRange(expression);
      factor.remove_suffix(digits);
      found = true;
      if (factor.ends_with('-') || factor.ends_with('+')) {
        if (factor.back() == '-') exponent = -exponent;
        factor.remove_suffix(1);
      }
    }
    if (factor.ends_with('^')) {
      if (!found) {
        throw ExpressionError(expression, "'^' must be followed by an integer exponent");
      }
      factor.remove_suffix(1);
    }
  }
  if (!found) return 1;
  if (exponent == 0) throw ExpressionError(expression, "an exponent of 0 is not allowed");
  return exponent;
}

[[noreturn]] void ThrowUnknownSymbol(std::string_view symbol, std::string_view expression) {
  std::string message = "unknown unit ";
  message.append(Quoted(symbol));
  if (symbol != expression) message.append(" in ").append(Quoted(expression));
  const std::vector<std::string_view> similar = SimilarUnitSymbols(symbol, 4);
  if (similar.empty()) {
    message.append(
        "; known units include m, mm, in, ft, kg, lb, N, kN, lbf, klbf, N*m, ft*lbf, Pa, MPa, psi, "
        "kg/m3, ppg, sg, Pa*s, cP, deg, rad, rpm, Hz, s, deg/30m, deg/100ft, gpm");
    throw UnitError(message);
  }
  message.append("; did you mean ");
  for (std::size_t i = 0; i < similar.size(); ++i) {
    if (i > 0) message.append(i + 1 == similar.size() ? " or " : ", ");
    message.append(Quoted(similar[i]));
  }
  message.append("?");
  throw UnitError(message);
}

// Multiplies `unit` by one factor raised to `sign` (+1 numerator, -1 denominator).
void ApplyFactor(std::string_view factor, int sign, Unit& unit, std::string_view expression) {
  std::size_t number_length = 0;
  while (number_length < factor.size() &&
         (IsDigit(factor[number_length]) ||
          (factor[number_length] == '.' && number_length + 1 < factor.size() &&
           IsDigit(factor[number_length + 1])))) {
    ++number_length;
  }
  if (number_length > 0) {
    double number = 0.0;
    const auto [end, error] = std::from_chars(factor.data(), factor.data() + number_length, number);
    if (error != std::errc() || end != factor.data() + number_length || !(number > 0.0) ||
        !std::isfinite(number)) {
      std::string what = "the number ";
      what.append(Quoted(factor.substr(0, number_length))).append(" must be positive and finite");
      throw ExpressionError(expression, what);
    }
    unit.to_si = sign > 0 ? unit.to_si * number : unit.to_si / number;
    factor.remove_prefix(number_length);
    if (factor.empty()) return;
  }
  const int exponent = sign * StripExponent(factor, expression);
  if (factor.empty()) {
    throw ExpressionError(expression, "an exponent needs a unit symbol before it");
  }
  const UnitSymbol* symbol = FindUnitSymbol(factor);
  if (symbol == nullptr) ThrowUnknownSymbol(factor, expression);
  unit.to_si *= std::pow(symbol->to_si, exponent);
  unit.dimension = unit.dimension + exponent * symbol->dimension;
  const Dimension& d = unit.dimension;
  if (std::max({std::abs(d.length), std::abs(d.mass), std::abs(d.time), std::abs(d.angle)}) > kMaxDimensionPower) {
    throw ExpressionError(expression, "a base unit's power goes past " + std::to_string(kMaxDimensionPower));
  }
}

// The unit, once its factor to SI is known to be a finite positive number ("t250" is 1e750 kg^250,
// which no double holds; "mm^9 mm^9 ... / ..." can underflow to 0).
Unit CheckedFactor(const Unit& unit, std::string_view expression) {
  if (!(unit.to_si > 0.0) || !std::isfinite(unit.to_si)) {
    throw ExpressionError(expression, "its size in SI units is out of range");
  }
  return unit;
}

// Applies every factor of a product (numerator or denominator).
void ApplyProduct(std::string_view product, int sign, Unit& unit, std::string_view expression) {
  std::size_t start = 0;
  std::size_t at = 0;
  while (at < product.size()) {
    const std::size_t separator = SeparatorLength(product, at);
    if (separator == 0) {
      ++at;
      continue;
    }
    if (at > start) ApplyFactor(product.substr(start, at - start), sign, unit, expression);
    at += separator;
    start = at;
  }
  if (at > start) ApplyFactor(product.substr(start, at - start), sign, unit, expression);
}

}  // namespace

Unit ParseUnit(std::string_view expression) {
  expression = TrimSpace(expression);
  Unit unit;
  const std::size_t slash = expression.find('/');
  if (slash == std::string_view::npos) {
    ApplyProduct(expression, +1, unit, expression);
    return CheckedFactor(unit, expression);
  }
  if (expression.find('/', slash + 1) != std::string_view::npos) {
    throw ExpressionError(expression,
                          "only one '/' is allowed (everything after it is in the denominator)");
  }
  const std::string_view numerator = TrimSpace(expression.substr(0, slash));
  std::string_view denominator = TrimSpace(expression.substr(slash + 1));
  if (numerator.empty()) {
    throw ExpressionError(expression, "nothing before '/' (write 1/s for a reciprocal)");
  }
  if (denominator.size() >= 2 && denominator.front() == '(' && denominator.back() == ')') {
    denominator = TrimSpace(denominator.substr(1, denominator.size() - 2));
  }
  if (denominator.empty()) throw ExpressionError(expression, "nothing after '/'");
  ApplyProduct(numerator, +1, unit, expression);
  ApplyProduct(denominator, -1, unit, expression);
  return CheckedFactor(unit, expression);
}

double Convert(double value, std::string_view from_unit, std::string_view to_unit) {
  const Unit from = ParseUnit(from_unit);
  const Unit to = ParseUnit(to_unit);
  if (!(from.dimension == to.dimension)) {
    std::string message = "cannot convert from ";
  message.append(Quoted(TrimSpace(from_unit)));
    message.append(" (").append(DimensionName(from.dimension)).append(") to ");
    message.append(Quoted(TrimSpace(to_unit))).append(" (").append(DimensionName(to.dimension)).append(")");
    throw UnitError(message);
  }
  return value * from.to_si / to.to_si;
}

}  // namespace drillflex::units
