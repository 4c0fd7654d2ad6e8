#include "units/unit_table.hpp"

#include <algorithm>
#include <array>

#include "core/types.hpp"

namespace drillflex::units {

namespace {

// Exact definitions (NIST SP 811, appendix B): the international foot, inch and avoirdupois pound,
// the standard acceleration of gravity (through lbf) and the US liquid gallon.
constexpr double kFoot = 0.3048;                // m
constexpr double kInch = 0.0254;                // m
constexpr double kPound = 0.45359237;           // kg
constexpr double kPoundForce = 4.4482216152605; // N = lb x 9.80665 m/s²
constexpr double kGallon = 3.785411784e-3;      // m³ = 231 in³
constexpr double kBarrel = 42.0 * kGallon;      // m³, oil barrel
constexpr double kRevolution = 2.0 * kPi;       // rad
constexpr double kSurveyFoot = 1200.0 / 3937.0; // m, the US survey foot (Energistics "ftUS")

constexpr Dimension kNone{};
constexpr Dimension kLength{1, 0, 0, 0};
constexpr Dimension kMass{0, 1, 0, 0};
constexpr Dimension kTime{0, 0, 1, 0};
constexpr Dimension kAngle{0, 0, 0, 1};
constexpr Dimension kForce{1, 1, -2, 0};
constexpr Dimension kPressure{-1, 1, -2, 0};
constexpr Dimension kViscosity{-1, 1, -1, 0};
constexpr Dimension kDensity{-3, 1, 0, 0};
constexpr Dimension kMassPerLength{-1, 1, 0, 0};
constexpr Dimension kVolume{3, 0, 0, 0};
constexpr Dimension kFlowRate{3, 0, -1, 0};
constexpr Dimension kRotarySpeed{0, 0, -1, 1};
constexpr Dimension kFrequency{0, 0, -1, 0};

constexpr bool kFold = true;

// Compound field units that are single words in practice get their own entry (ppg, gpm, psi);
// everything else is built by the expression parser from these.
constexpr std::array kSymbols{
    // length
    UnitSymbol{"m", 1.0, kLength},
    UnitSymbol{"mm", 1e-3, kLength},
    UnitSymbol{"cm", 1e-2, kLength},
    UnitSymbol{"km", 1e3, kLength},
    UnitSymbol{"in", kInch, kLength, kFold},
    UnitSymbol{"ft", kFoot, kLength, kFold},
    UnitSymbol{"kft", 1e3 * kFoot, kLength, kFold},  // for kft*lbf
    UnitSymbol{"yd", 3.0 * kFoot, kLength, kFold},
    UnitSymbol{"ftUS", kSurveyFoot, kLength},  // Energistics (WITSML) symbol
    // mass
    UnitSymbol{"kg", 1.0, kMass, kFold},
    UnitSymbol{"g", 1e-3, kMass},
    UnitSymbol{"t", 1e3, kMass},  // metric tonne
    UnitSymbol{"lb", kPound, kMass, kFold},
    UnitSymbol{"lbm", kPound, kMass, kFold},
    UnitSymbol{"oz", kPound / 16.0, kMass, kFold},  // avoirdupois ounce
    // time
    UnitSymbol{"s", 1.0, kTime},
    UnitSymbol{"ms", 1e-3, kTime},
    UnitSymbol{"min", 60.0, kTime, kFold},
    UnitSymbol{"h", 3600.0, kTime},
    UnitSymbol{"hr", 3600.0, kTime, kFold},
    // force
    UnitSymbol{"N", 1.0, kForce},
    UnitSymbol{"daN", 10.0, kForce},
    UnitSymbol{"kN", 1e3, kForce},
    UnitSymbol{"MN", 1e6, kForce},
    UnitSymbol{"lbf", kPoundForce, kForce, kFold},
    UnitSymbol{"klbf", 1e3 * kPoundForce, kForce, kFold},
    // The kilogram-force, 1 kg x standard gravity 9.80665 m/s² (3rd CGPM, 1901; NIST SP 811), and the
    // Energistics (WITSML) symbol of 1000 of them (a tonne-force), in which rigs log hook load and WOB.
    UnitSymbol{"kgf", 9.80665, kForce},
    UnitSymbol{"kkgf", 9.80665e3, kForce},
    // pressure and stress
    UnitSymbol{"Pa", 1.0, kPressure, kFold},
    UnitSymbol{"mPa", 1e-3, kPressure},  // for mPa*s
    UnitSymbol{"kPa", 1e3, kPressure, kFold},
    UnitSymbol{"MPa", 1e6, kPressure},
    UnitSymbol{"GPa", 1e9, kPressure, kFold},
    UnitSymbol{"bar", 1e5, kPressure, kFold},
    UnitSymbol{"psi", kPoundForce / (kInch * kInch), kPressure, kFold},
    UnitSymbol{"ksi", 1e3 * kPoundForce / (kInch * kInch), kPressure, kFold},
    // dynamic viscosity
    UnitSymbol{"cP", 1e-3, kViscosity, kFold},
    UnitSymbol{"P", 0.1, kViscosity},  // poise
    // plane angle
    UnitSymbol{"deg", kDegree, kAngle, kFold},
    UnitSymbol{"\u00B0", kDegree, kAngle},  // degree sign
    UnitSymbol{"\u00BA", kDegree, kAngle},  // masculine ordinal, a common stand-in for °
    UnitSymbol{"dega", kDegree, kAngle},  // Energistics (WITSML) symbol of the degree of angle
    UnitSymbol{"rad", 1.0, kAngle, kFold},
    UnitSymbol{"rev", kRevolution, kAngle, kFold},
    // rotary speed and frequency
    UnitSymbol{"rpm", kRevolution / 60.0, kRotarySpeed, kFold},
    UnitSymbol{"rps", kRevolution, kRotarySpeed, kFold},
    UnitSymbol{"Hz", 1.0, kFrequency, kFold},
    // volume and flow rate
    UnitSymbol{"L", 1e-3, kVolume},
    UnitSymbol{"l", 1e-3, kVolume},
    UnitSymbol{"gal", kGallon, kVolume, kFold},
    UnitSymbol{"bbl", kBarrel, kVolume, kFold},
    UnitSymbol{"gpm", kGallon / 60.0, kFlowRate, kFold},
    UnitSymbol{"lpm", 1e-3 / 60.0, kFlowRate, kFold},
    // density and mass per length
    UnitSymbol{"ppg", kPound / kGallon, kDensity, kFold},
    UnitSymbol{"sg", 1000.0, kDensity, kFold},  // specific gravity against 1000 kg/m³ water
    UnitSymbol{"pcf", kPound / (kFoot * kFoot * kFoot), kDensity, kFold},
    UnitSymbol{"ppf", kPound / kFoot, kMassPerLength, kFold},
    // dimensionless
    UnitSymbol{"%", 0.01, kNone},
};

char LowerAscii(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

bool EqualIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(),
                    [](char x, char y) { return LowerAscii(x) == LowerAscii(y); });
}

}  // namespace

std::string_view TrimSpace(std::string_view text) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

std::string Quoted(std::string_view text) {
  std::string quoted = "\"";
  quoted.append(text).append("\"");
  return quoted;
}

std::span<const UnitSymbol> UnitSymbols() { return kSymbols; }

const UnitSymbol* FindUnitSymbol(std::string_view symbol) {
  for (const UnitSymbol& entry : kSymbols) {
    if (entry.symbol == symbol) return &entry;
  }
  for (const UnitSymbol& entry : kSymbols) {
    if (entry.fold_case && EqualIgnoringCase(entry.symbol, symbol)) return &entry;
  }
  return nullptr;
}

// Optimal string alignment distance: Levenshtein plus the transposition of two adjacent letters
// ("pis" -> "psi" is one edit), the common typos. Wagner-Fischer table with one extra rule.
std::size_t EditDistanceIgnoringCase(std::string_view a, std::string_view b) {
  const std::size_t columns = b.size() + 1;
  std::vector<std::size_t> table((a.size() + 1) * columns);
  const auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return table[i * columns + j]; };
  for (std::size_t i = 0; i <= a.size(); ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= b.size(); ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = LowerAscii(a[i - 1]) == LowerAscii(b[j - 1]);
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + (same ? 0 : 1)});
      if (i > 1 && j > 1 && LowerAscii(a[i - 1]) == LowerAscii(b[j - 2]) &&
          LowerAscii(a[i - 2]) == LowerAscii(b[j - 1])) {
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
      }
    }
  }
  return at(a.size(), b.size());
}

std::vector<std::string_view> SimilarUnitSymbols(std::string_view unknown, std::size_t max_count) {
  // A plausible typo: one edit for short symbols, two for longer ones.
  const std::size_t max_distance = unknown.size() <= 3 ? 1 : 2;
  std::vector<std::pair<std::size_t, std::size_t>> candidates;  // (distance, table index)
  for (std::size_t index = 0; index < kSymbols.size(); ++index) {
    const std::size_t distance = EditDistanceIgnoringCase(unknown, kSymbols[index].symbol);
    if (distance <= max_distance) candidates.emplace_back(distance, index);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string_view> similar;
  for (const auto& [distance, index] : candidates) {
    if (similar.size() == max_count) break;
    similar.push_back(kSymbols[index].symbol);
  }
  return similar;
}

}  // namespace drillflex::units
