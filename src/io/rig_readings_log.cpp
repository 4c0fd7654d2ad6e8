// ReadingsOfLog: a WITSML log's curves found by mnemonic, its values in SI, its rows classified.
#include "io/rig_readings_log.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "io/rig_readings_rows.hpp"

namespace drillflex::io {
namespace {

enum Role { kBitMd, kHoleMd, kBlockPosition, kHookLoad, kSurfaceTorque, kWeightOnBit, kRotarySpeed, kRoles };

struct RoleInfo {
  const char* key;  // RigReadingsOptions::mnemonics
  const char* what;
  units::Quantity quantity;
  std::array<const char*, 2> mnemonics;  // the usual ones, in order of preference; nullptr for none
  bool required;
};

// The usual mnemonics: the WITS (Wellsite Information Transfer Specification) record 1 names that rig
// systems and WITSML servers carry over (DBTM bit depth, DMEA hole depth, BPOS block position, HKLA/HKLD
// hook load average/maximum, TQA torque average, SWOB/WOBA surface WOB, RPMA rotary speed average).
constexpr RoleInfo kRoleInfo[kRoles] = {
    {"bit_md", "the bit depth", units::Quantity::Length, {"DBTM", nullptr}, true},
    {"hole_md", "the hole depth", units::Quantity::Length, {"DMEA", nullptr}, false},
    {"block_position", "the block position", units::Quantity::Length, {"BPOS", nullptr}, false},
    {"hook_load", "the hook load", units::Quantity::Force, {"HKLD", "HKLA"}, true},
    {"surface_torque", "the surface torque", units::Quantity::Moment, {"TQA", nullptr}, false},
    {"weight_on_bit", "the WOB", units::Quantity::WeightOnBit, {"SWOB", "WOBA"}, true},
    {"rotary_speed", "the rotary speed", units::Quantity::RotarySpeed, {"RPMA", nullptr}, true},
};

bool SameMnemonic(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
         });
}

[[noreturn]] void Fail(const LogPlace& place, const std::string& message) {
  throw InputError(place.location, place.path, message);
}

// An error on a row: its line, the element holding the rows.
[[noreturn]] void FailAtRow(const LogTable& table, int line, const std::string& message) {
  throw InputError(SourceLocation{table.data.location.file, line, 0}, table.data.path, message);
}

std::string KnownKeys() {
  std::string keys;
  for (const RoleInfo& info : kRoleInfo) keys += fmt::format("{}{}", keys.empty() ? "" : ", ", info.key);
  return keys;
}

struct Column {
  std::size_t curve = 0;
  double factor = 1.0;  // to SI
};

class LogReader {
 public:
  LogReader(const LogTable& table, const RigReadingsOptions& options) : table_(table), options_(options) {
    for (const auto& entry : options.mnemonics) {  // (clang 14 lambdas take no structured binding)
      const std::string& key = entry.first;
      const auto known = std::find_if(std::begin(kRoleInfo), std::end(kRoleInfo),
                                      [&](const RoleInfo& info) { return key == info.key; });
      if (known == std::end(kRoleInfo)) {
        Fail(table.place,
             fmt::format("the readings options name a curve for '{}': expected one of {}", key, KnownKeys()));
      }
    }
    FindColumns();
  }

  std::vector<RigReading> Readings(std::vector<std::string>& warnings) const;

 private:
  std::vector<std::string> Tried(Role role) const {
    if (const auto override = options_.mnemonics.find(kRoleInfo[role].key); override != options_.mnemonics.end()) {
      return {override->second};
    }
    std::vector<std::string> tried;
    for (const char* mnemonic : kRoleInfo[role].mnemonics) {
      if (mnemonic) tried.emplace_back(mnemonic);
    }
    return tried;
  }

  std::optional<std::size_t> Find(const std::string& mnemonic) const {
    for (std::size_t i = 0; i < table_.curves.size(); ++i) {
      if (SameMnemonic(table_.curves[i].mnemonic, mnemonic)) return i;
    }
    return std::nullopt;
  }

  // A depth-indexed log without a bit depth curve: its index is the bit's depth.
  std::optional<std::size_t> DepthIndex() const {
    if (!table_.index) return std::nullopt;
    try {
      if (units::ParseUnit(table_.curves[*table_.index].uom).dimension == units::DimensionOf(units::Quantity::Length)) {
        return table_.index;
      }
    } catch (const UnitError&) {}
    return std::nullopt;
  }

  void FindColumns();
  std::optional<double> Value(const LogRow& row, Role role) const;

  const LogTable& table_;
  const RigReadingsOptions& options_;
  std::optional<Column> columns_[kRoles];
};

void LogReader::FindColumns() {
  std::string missing;
  for (int r = 0; r < kRoles; ++r) {
    const Role role = static_cast<Role>(r);
    const bool overridden = options_.mnemonics.contains(kRoleInfo[role].key);
    std::optional<std::size_t> curve;
    for (const std::string& mnemonic : Tried(role)) {
      if (!curve) curve = Find(mnemonic);
    }
    if (!curve && role == kBitMd && !overridden) curve = DepthIndex();
    if (!curve) {
      if (!kRoleInfo[role].required && !overridden) continue;
      std::string tried;
      for (const std::string& mnemonic : Tried(role)) tried += fmt::format("{}{}", tried.empty() ? "" : ", ", mnemonic);
      missing += fmt::format("{}{} ({}: tried {}{})", missing.empty() ? "" : "; ", kRoleInfo[role].what,
                             kRoleInfo[role].key, tried, role == kBitMd && !overridden ? ", then a depth index" : "");
      continue;
    }
    const LogCurve& found = table_.curves[*curve];
    const double factor = FactorToSi(found.uom, kRoleInfo[role].quantity, [&](const std::string& message) {
      Fail(found.place, fmt::format("{} ({}): {}", found.mnemonic, kRoleInfo[role].what, message));
    });
    columns_[role] = Column{*curve, factor};
  }
  if (!missing.empty()) {
    constexpr std::size_t kListed = 40;  // a long log's curves are listed in part
    std::string curves;
    for (std::size_t i = 0; i < std::min(table_.curves.size(), kListed); ++i) {
      curves += fmt::format("{}{}", curves.empty() ? "" : ", ", table_.curves[i].mnemonic);
    }
    if (table_.curves.size() > kListed) curves += fmt::format(" and {} more", table_.curves.size() - kListed);
    Fail(table_.place,
         fmt::format("{} has no curve for {}; its curves: {} (the readings options' mnemonics name others)",
                     table_.name, missing, curves.empty() ? "none" : curves));
  }
}

std::optional<double> LogReader::Value(const LogRow& row, Role role) const {
  if (!columns_[role]) return std::nullopt;
  const Column& column = *columns_[role];
  const LogCurve& curve = table_.curves[column.curve];
  const std::string& cell = row.cells[column.curve];
  if (cell.empty()) return std::nullopt;
  const std::optional<double> number = ParseNumber(cell);
  if (curve.null_value) {
    const std::optional<double> null_number = ParseNumber(*curve.null_value);
    if (cell == *curve.null_value || (number && null_number && *number == *null_number)) return std::nullopt;
  }
  if (!number) {
    FailAtRow(table_, row.line,
              fmt::format("{} ({}): expected a number in {} (or no value: empty{}), got '{}'", curve.mnemonic,
                          kRoleInfo[role].what, curve.uom,
                          curve.null_value ? fmt::format(" or the null value {}", *curve.null_value) : "", cell));
  }
  const double si = *number * column.factor;
  if (!std::isfinite(si)) {
    FailAtRow(table_, row.line,
              fmt::format("{} ({}): {} {} is out of range", curve.mnemonic, kRoleInfo[role].what, cell, curve.uom));
  }
  return si;
}

std::vector<RigReading> LogReader::Readings(std::vector<std::string>& warnings) const {
  struct Kept {
    RigReading reading;
    RigActivitySample sample;
  };
  std::vector<Kept> kept;
  int no_value = 0, negative = 0, wob_below_zero = 0, torque_below_zero = 0;
  double deepest = 0.0;  // the hole's depth where the log gives none: its deepest depth so far
  for (const LogRow& row : table_.rows) {
    const std::optional<double> bit_md = Value(row, kBitMd), hole_md = Value(row, kHoleMd),
                                block = Value(row, kBlockPosition), hook_load = Value(row, kHookLoad),
                                torque = Value(row, kSurfaceTorque), wob = Value(row, kWeightOnBit),
                                rpm = Value(row, kRotarySpeed);
    if (!bit_md || !hook_load || !wob || !rpm) {
      ++no_value;
      continue;
    }
    if (const std::string problem = DepthProblem(*bit_md, options_); !problem.empty()) {
      FailAtRow(
          table_, row.line,
          fmt::format("{} ({}): {}", table_.curves[columns_[kBitMd]->curve].mnemonic, kRoleInfo[kBitMd].what, problem));
    }
    if (*hook_load < 0.0 || *rpm < 0.0) {
      ++negative;
      continue;
    }
    Kept row_kept;
    RigReading& reading = row_kept.reading;
    reading.line = row.line;
    reading.bit_md = *bit_md;
    reading.hook_load = *hook_load;
    reading.rotary_speed = *rpm;
    // A WOB below zero is the sensor's offset with the bit off bottom (the WOB is the hook load's fall
    // from its off-bottom value): none on the bit. A torque below zero likewise says nothing of the string.
    reading.weight_on_bit = std::max(*wob, 0.0);
    if (*wob < 0.0) ++wob_below_zero;
    if (torque && *torque < 0.0) {
      ++torque_below_zero;
    } else {
      reading.surface_torque = torque;
    }
    deepest = std::max({deepest, *bit_md, hole_md.value_or(0.0)});
    row_kept.sample = {*bit_md, hole_md.value_or(deepest), block, *hook_load, reading.weight_on_bit, *rpm};
    kept.push_back(row_kept);
  }
  const std::string file = table_.place.location.file;
  const auto mnemonic = [&](Role role) { return table_.curves[columns_[role]->curve].mnemonic; };
  if (no_value > 0) {
    warnings.push_back(fmt::format("{}: {}: {} rows left out: no value of {}, {}, {} or {} (empty or the null value)",
                                   file, table_.name, no_value, mnemonic(kBitMd), mnemonic(kHookLoad),
                                   mnemonic(kWeightOnBit), mnemonic(kRotarySpeed)));
  }
  if (negative > 0) {
    warnings.push_back(fmt::format("{}: {}: {} rows left out: a negative hook load ({}) or rotary speed ({})", file,
                                   table_.name, negative, mnemonic(kHookLoad), mnemonic(kRotarySpeed)));
  }
  if (wob_below_zero > 0) {
    warnings.push_back(fmt::format("{}: {}: {} rows' WOB ({}) below zero (the sensor's offset) read as 0", file,
                                   table_.name, wob_below_zero, mnemonic(kWeightOnBit)));
  }
  if (torque_below_zero > 0) {
    warnings.push_back(fmt::format("{}: {}: {} rows' surface torque ({}) below zero (the sensor's offset) read as none",
                                   file, table_.name, torque_below_zero, mnemonic(kSurfaceTorque)));
  }

  RigActivityThresholds thresholds = options_.thresholds;
  if (options_.in_slips_hook_load) {
    thresholds.in_slips_hook_load = *options_.in_slips_hook_load;
  } else if (!kept.empty()) {
    std::vector<double> hook_loads;
    for (const Kept& row : kept) hook_loads.push_back(row.sample.hook_load);
    const auto middle = hook_loads.begin() + static_cast<std::ptrdiff_t>(hook_loads.size() / 2);
    std::nth_element(hook_loads.begin(), middle, hook_loads.end());
    thresholds.in_slips_hook_load = InSlipsHookLoad(*std::min_element(hook_loads.begin(), hook_loads.end()), *middle);
  }
  std::vector<RigReading> readings;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    RigReading reading = kept[i].reading;
    reading.activity = ClassifyRigActivity(kept[i].sample, i > 0 ? &kept[i - 1].sample : nullptr, thresholds);
    readings.push_back(reading);
  }
  return readings;
}

}  // namespace

std::vector<RigReading> ReadingsOfLog(const LogTable& table, const RigReadingsOptions& options,
                                      std::vector<std::string>& warnings) {
  return LogReader(table, options).Readings(warnings);
}

}  // namespace drillflex::io
