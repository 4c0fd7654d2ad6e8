// The base unit symbols that unit expressions are built from ("m", "lbf", "ppg", "°", ...), each
// with its factor to SI and its dimension. Internal to units/: the public API is units.hpp.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "units/units.hpp"

namespace drillflex::units {

// One symbol: a value in it times to_si is the value in SI (m, kg, s, rad and their products).
// fold_case: the symbol is also accepted in any letter case ("cp", "PSI"); only set where no other
// symbol differs from it by case alone (mPa / MPa, t / T and s / S must stay as written).
struct UnitSymbol {
  std::string_view symbol;
  double to_si = 1.0;
  Dimension dimension;
  bool fold_case = false;
};

// Every known symbol, in a fixed order (the order suggestions are listed in on ties).
std::span<const UnitSymbol> UnitSymbols();

// The symbol spelled exactly so, else a fold_case symbol equal to it ignoring case; nullptr if none.
const UnitSymbol* FindUnitSymbol(std::string_view symbol);

// Up to max_count known symbols closest to an unknown one by case-insensitive edit distance,
// nearest first; empty when none is near enough to be a plausible typo.
std::vector<std::string_view> SimilarUnitSymbols(std::string_view unknown, std::size_t max_count);

// Edit distance (insertions, deletions, substitutions, adjacent transpositions), ignoring ASCII case.
std::size_t EditDistanceIgnoringCase(std::string_view a, std::string_view b);

// Text helpers shared by the units sources: strips ASCII white space; wraps in double quotes.
std::string_view TrimSpace(std::string_view text);
std::string Quoted(std::string_view text);

// Dimension arithmetic: exponents add under multiplication and scale under powers.
constexpr Dimension operator+(const Dimension& a, const Dimension& b) {
  return {a.length + b.length, a.mass + b.mass, a.time + b.time, a.angle + b.angle};
}
constexpr Dimension operator*(int power, const Dimension& d) {
  return {power * d.length, power * d.mass, power * d.time, power * d.angle};
}

}  // namespace drillflex::units
