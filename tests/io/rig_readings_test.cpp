// The rig readings reader: the Volve 15/9-F-5 readings CSV in SI, CSVs in any column order and unit, every
// bad CSV refused with its file, line and column, and WITSML 1.4.1.1 and 2.0 logs (time- and
// depth-indexed) read with their curves' units and their rows classified.
#include "io/rig_readings.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"
#include "../witsml_log_writer.hpp"

namespace drillflex::io {
namespace rig_readings_test {

using ::testing::HasSubstr;

constexpr double kKlbf = 4448.2216152605;            // N (NIST SP 811)
constexpr double kFtLbf = 0.3048 * 4.4482216152605;  // N*m
constexpr double kRpm = 2.0 * kPi / 60.0;            // rad/s

const std::string kVolve = DRILLFLEX_SOURCE_DIR "/../shared/field/volve-15-9-F-5/readings.csv";

// The InputError that `read` throws.
InputError ErrorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& error) { return error; }
  ADD_FAILURE() << "no error";
  return InputError({}, "", "");
}

InputError CsvError(const std::string& text, const RigReadingsOptions& options = {}) {
  return ErrorOf([&] { ParseRigReadingsCsv(text, "bad.csv", options); });
}

TEST(RigReadingsCsv, TheVolveSectionReadsInSI) {
  std::ifstream probe(kVolve);
  if (!probe) GTEST_SKIP() << kVolve << " is not there (the shared field data sit beside the repository)";
  const RigReadings readings = ReadRigReadings(kVolve);
  EXPECT_EQ(readings.file, kVolve);
  ASSERT_EQ(readings.rows.size(), 89u);
  EXPECT_TRUE(readings.warnings.empty());
  // The first row, line 3: 2829.1 m, 1343.0 kN, 15.60 kN*m, 145.6 kN, 99 rpm.
  const RigReading& first = readings.rows.front();
  EXPECT_EQ(first.line, 3);
  EXPECT_EQ(first.activity, RigActivity::kDrilling);
  EXPECT_DOUBLE_EQ(first.bit_md, 2829.1);
  EXPECT_DOUBLE_EQ(first.hook_load, 1.343e6);
  ASSERT_TRUE(first.surface_torque);
  EXPECT_DOUBLE_EQ(*first.surface_torque, 15.60e3);
  EXPECT_DOUBLE_EQ(first.weight_on_bit, 145.6e3);
  EXPECT_NEAR(first.rotary_speed, 10.367, 5e-4);  // 99 x 2 pi / 60
  // The last, line 91: 3791.0 m, 1429.1 kN, 24.27 kN*m, 54.0 kN, 130 rpm.
  const RigReading& last = readings.rows.back();
  EXPECT_EQ(last.line, 91);
  EXPECT_DOUBLE_EQ(last.bit_md, 3791.0);
  EXPECT_DOUBLE_EQ(last.hook_load, 1.4291e6);
  EXPECT_DOUBLE_EQ(*last.surface_torque, 24.27e3);
  EXPECT_DOUBLE_EQ(last.weight_on_bit, 54.0e3);
  EXPECT_DOUBLE_EQ(last.rotary_speed, 130 * kRpm);
  // The survey ends at 3790 m: the last bin's 3791.0 m lies beyond it, and is refused with that bottom.
  RigReadingsOptions options;
  options.deepest_md = 3790.0;
  const InputError error = ErrorOf([&] { ReadRigReadings(kVolve, options); });
  EXPECT_EQ(error.location().line, 91);
  EXPECT_EQ(error.location().column, 1);
  EXPECT_EQ(error.key_path(), "bit_md");
  EXPECT_THAT(error.what(), HasSubstr("beyond the well's bottom at 3790 m"));
}

TEST(RigReadingsCsv, ColumnsInAnyOrderWithTheirOwnUnits) {
  const RigReadings readings = ParseRigReadingsCsv(
      "# pick-up and slack-off weights at connections\r\n"
      "rpm, WOB ,note,surface_torque,hook_load,activity,bit_md\r\n"
      "rpm,klbf,-,kft*lbf,klbf,-,ft\r\n"
      "\r\n"
      "0,0,first stand,,212.5,pick_up,9000\r\n"
      "60,0,,7.5,180,rotating,9000\r\n"
      "# a comment between rows\n"
      "0,0,x,,150,SLACK_OFF,9010.5\n"
      "120,25.0,,9,155,drilling,9100\n",
      "order.csv", {});
  ASSERT_EQ(readings.rows.size(), 4u);
  const RigReading& pick_up = readings.rows[0];
  EXPECT_EQ(pick_up.line, 5);
  EXPECT_EQ(pick_up.activity, RigActivity::kPickUp);
  EXPECT_DOUBLE_EQ(pick_up.bit_md, 9000 * 0.3048);
  EXPECT_DOUBLE_EQ(pick_up.hook_load, 212.5 * kKlbf);
  EXPECT_FALSE(pick_up.surface_torque);  // empty: not read
  EXPECT_EQ(pick_up.rotary_speed, 0.0);
  const RigReading& rotating = readings.rows[1];
  EXPECT_EQ(rotating.activity, RigActivity::kRotatingOffBottom);
  EXPECT_DOUBLE_EQ(*rotating.surface_torque, 7500 * kFtLbf);
  EXPECT_DOUBLE_EQ(rotating.rotary_speed, 2 * kPi);  // 60 rpm: a turn a second
  EXPECT_EQ(readings.rows[2].activity, RigActivity::kSlackOff);
  EXPECT_EQ(readings.rows[2].line, 8);
  const RigReading& drilling = readings.rows[3];
  EXPECT_EQ(drilling.activity, RigActivity::kDrilling);
  EXPECT_DOUBLE_EQ(drilling.weight_on_bit, 25 * kKlbf);
  EXPECT_DOUBLE_EQ(drilling.bit_md, 2773.68);  // 9100 ft
}

TEST(RigReadingsCsv, RowsInSlipsOrOtherAreLeftOutWithAWarning) {
  const RigReadings readings = ParseRigReadingsCsv(
      "bit_md,activity,hook_load,surface_torque,wob,rpm\nm,-,kN,kN*m,kN,rpm\n"
      "1000,in_slips,300,,0,0\n1000,other,900,,0,0\n1000,in_slips,310,,0,0\n1000,pick_up,1100,,0,0\n",
      "slips.csv", {});
  ASSERT_EQ(readings.rows.size(), 1u);
  EXPECT_EQ(readings.rows[0].line, 6);
  ASSERT_EQ(readings.warnings.size(), 1u);
  EXPECT_THAT(readings.warnings[0], HasSubstr("3 rows left out (2 in_slips, 1 other)"));
  // Nothing but slips: no reading, refused.
  const InputError none = CsvError(
      "bit_md,activity,hook_load,surface_torque,wob,rpm\nm,-,kN,kN*m,kN,rpm\n"
      "1000,in_slips,300,,0,0\n");
  EXPECT_THAT(none.what(), HasSubstr("no drilling, rotating, pick_up or slack_off reading"));
}

// A bad CSV: what it is, its text, and the line, column (1-based character), key and words of the error.
struct BadCsv {
  std::string what;
  std::string text;
  int line;
  int column;
  std::string key;
  std::string message;
};

const std::string kHeader = "bit_md,activity,hook_load,surface_torque,wob,rpm\n";
const std::string kUnits = "m,-,kN,kN*m,kN,rpm\n";

TEST(RigReadingsCsv, BadFilesAreRefusedWithFileLineAndColumn) {
  const std::vector<BadCsv> cases = {
      {"an empty file", "", 1, 0, "", "holds no reading"},
      {"a missing column", "bit_md,activity,hook_load,surface_torque,rpm\n" + kUnits, 1, 1, "wob",
       "the header has no column 'wob': expected the columns bit_md, activity"},
      {"a column twice", "bit_md,activity,hook_load,surface_torque,wob,rpm,wob\n", 1, 50, "wob", "named twice"},
      {"no units", kHeader, 1, 0, "", "expected a line of units"},
      {"no rows", kHeader + kUnits + "# nothing\n", 3, 0, "", "holds no reading"},  // at the end
      {"an unknown unit", kHeader + "m,-,kNx,kN*m,kN,rpm\n1,drilling,1,1,1,1\n", 2, 5, "hook_load",
       "unknown unit \"kNx\""},
      {"a unit of the wrong kind", kHeader + "m,-,kN,kN,kN,rpm\n", 2, 8, "surface_torque",
       "is a force, but a moment or torque"},
      {"WOB in a length", kHeader + "m,-,kN,kN*m,ft,rpm\n", 2, 13, "wob", "is a length, but a weight on bit"},
      {"RPM in hertz", kHeader + "m,-,kN,kN*m,kN,Hz\n", 2, 16, "rpm", "is a frequency, but a rotary speed"},
      {"a missing unit", kHeader + "m,-,kN,kN*m,kN\n", 2, 15, "rpm", "no unit: expected the unit of a rotary speed"},
      {"a unit for the activity", kHeader + "m,s,kN,kN*m,kN,rpm\n", 2, 3, "activity", "expected '-'"},
      {"a missing value", kHeader + kUnits + "1000,drilling,1300,20,,120\n", 3, 23, "wob",
       "no value: expected a weight on bit (force) in kN"},
      {"a short row", kHeader + kUnits + "1000,drilling,1300,20\n", 3, 22, "wob", "no value"},
      {"an unreadable value", kHeader + kUnits + "1000,drilling,13OO,20,100,120\n", 3, 15, "hook_load",
       "expected a number (a force in kN), got '13OO'"},
      {"a value with a unit", kHeader + kUnits + "1000 m,drilling,1300,20,100,120\n", 3, 1, "bit_md", "got '1000 m'"},
      {"an unknown activity", kHeader + kUnits + "1000,tripping,1300,20,100,120\n", 3, 6, "activity",
       "unknown activity 'tripping': expected drilling (on bottom, rotating), rotating (off bottom), pick_up, "
       "slack_off"},
      {"a negative hook load", kHeader + kUnits + "1000,drilling,-5,20,100,120\n", 3, 15, "hook_load",
       "not negative, got -5"},
      {"a negative WOB", kHeader + kUnits + "1000,drilling,1300,20,-1,120\n", 3, 23, "wob", "not negative"},
      {"a negative RPM", kHeader + kUnits + "1000,drilling,1300,20,100,-120\n", 3, 27, "rpm", "not negative"},
      {"a negative torque", kHeader + kUnits + "1000,drilling,1300,-20,100,120\n", 3, 20, "surface_torque",
       "not negative"},
      {"not a finite number", kHeader + kUnits + "1000,drilling,inf,20,100,120\n", 3, 15, "hook_load",
       "expected a number"},
      {"NaN", kHeader + kUnits + "1000,drilling,1300,nan,100,120\n", 3, 20, "surface_torque", "expected a number"},
      {"a negative depth", kHeader + kUnits + "-1,drilling,1300,20,100,120\n", 3, 1, "bit_md", "not negative"},
      {"too many values", kHeader + kUnits + "1000,drilling,1300,20,100,120,7\n", 3, 31, "",
       "expected at most 6 values"},
  };
  for (const BadCsv& bad : cases) {
    SCOPED_TRACE(bad.what);
    const InputError error = CsvError(bad.text);
    EXPECT_EQ(error.location().file, "bad.csv");
    EXPECT_EQ(error.location().line, bad.line);
    EXPECT_EQ(error.location().column, bad.column);
    EXPECT_EQ(error.key_path(), bad.key);
    EXPECT_THAT(error.what(), HasSubstr(bad.message));
    // The message names the file, the line and the column.
    EXPECT_THAT(error.what(), HasSubstr("bad.csv:" + std::to_string(bad.line)));
    if (!bad.key.empty()) { EXPECT_THAT(error.what(), HasSubstr(bad.key)); }
  }
}

TEST(RigReadingsCsv, DepthsOutsideTheWellAreRefused) {
  RigReadingsOptions options;
  options.deepest_md = 2000.0;
  const std::string rows =
      kHeader + "ft,-,kN,kN*m,kN,rpm\n6561,drilling,1300,20,100,120\n6563,drilling,1300,20,100,120\n";
  // 6561 ft is 1999.79 m, inside; 6563 ft is 2000.40 m, beyond.
  const InputError error = CsvError(rows, options);
  EXPECT_EQ(error.location().line, 4);
  EXPECT_EQ(error.key_path(), "bit_md");
  EXPECT_THAT(error.what(), HasSubstr("the bit depth 2000.4 m lies beyond the well's bottom at 2000 m"));
}

// A value whose number reads but whose SI value does not fit a double.
TEST(RigReadingsCsv, AnSIValueOutOfRangeIsRefused) {
  const InputError error = CsvError(kHeader + "m,-,MN,kN*m,kN,rpm\n1000,drilling,1e305,20,100,120\n");
  EXPECT_EQ(error.key_path(), "hook_load");
  EXPECT_THAT(error.what(), HasSubstr("1e305 is out of range"));
}

// The rows of a rig's time log, one a second or so while it drills a few centimetres, lifts off bottom,
// turns, picks up, slacks off and sets the slips: DBTM, DMEA, BPOS in m, HKLD and SWOB in klbf, TQA in
// kft.lbf, RPMA in rpm; -999.25 is the null value (1.4.1.1) or null (2.0).
struct TimeRow {
  const char* time;
  double bit, hole, block, hook, torque, wob, rpm;
  RigActivity activity;  // what the rule makes of it
};

constexpr double kNull = -999.25;
const std::vector<TimeRow> kTimeRows = {
    {"2024-03-01T10:00:00Z", 999.90, 1000.0, 10.00, 190, 12.0, 20, 120, RigActivity::kDrilling},
    {"2024-03-01T10:00:05Z", 999.95, 1000.0, 9.95, 191, 12.2, 19, 120, RigActivity::kDrilling},
    {"2024-03-01T10:00:10Z", 998.00, 1000.0, 11.90, 210, 8.0, 0, 100, RigActivity::kOther},  // lifting, turning
    {"2024-03-01T10:00:15Z", 998.00, 1000.0, 11.90, 210, 7.5, 0, 100, RigActivity::kRotatingOffBottom},
    {"2024-03-01T10:00:20Z", 998.00, 1000.0, 11.90, kNull, 7.5, 0, 100, RigActivity::kOther},  // no hook load: left out
    {"2024-03-01T10:00:25Z", 997.00, 1000.0, 12.90, 225, kNull, 0, 0, RigActivity::kPickUp},
    {"2024-03-01T10:00:30Z", 996.00, 1000.0, 13.90, 226, kNull, 0, 0, RigActivity::kPickUp},
    {"2024-03-01T10:00:35Z", 997.00, 1000.0, 12.90, 170, kNull, 0, 0, RigActivity::kSlackOff},
    {"2024-03-01T10:00:40Z", 997.00, 1000.0, 12.90, 40, kNull, 0, 0, RigActivity::kInSlips},
    {"2024-03-01T10:00:45Z", 997.00, 1000.0, 20.00, 41, kNull, 0, 0, RigActivity::kInSlips},
};

test_witsml::LogDocument TimeLog(bool v20) {
  test_witsml::LogDocument log;
  log.curves = {{"TIME", "s"},    {"DBTM", "m"},      {"DMEA", "m"},    {"BPOS", "m"},
                {"HKLD", "klbf"}, {"TQA", "kft.lbf"}, {"SWOB", "klbf"}, {"RPMA", "rpm"}};
  const auto cell = [&](double value) {
    if (value == kNull) return std::string(v20 ? "null" : "-999.25");
    return fmt::format("{}", value);
  };
  for (const TimeRow& row : kTimeRows) {
    log.rows.push_back({v20 ? fmt::format("\"{}\"", row.time) : std::string(row.time), cell(row.bit), cell(row.hole),
                        cell(row.block), cell(row.hook), cell(row.torque), cell(row.wob), cell(row.rpm)});
  }
  return log;
}

void ExpectTheTimeLog(const RigReadings& readings, int first_line) {
  // Row 4 (no hook load) left out; 2 (lifting while turning) other; 8 and 9 in slips: the lowest hook
  // load 40 klbf is under half the median (190 klbf), so the in-slips hook load is 48 klbf.
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < kTimeRows.size(); ++i) {
    if (i != 4 && IsModelledActivity(kTimeRows[i].activity)) kept.push_back(i);
  }
  ASSERT_EQ(readings.rows.size(), kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const TimeRow& row = kTimeRows[kept[k]];
    const RigReading& reading = readings.rows[k];
    SCOPED_TRACE(row.time);
    EXPECT_EQ(reading.line, first_line + static_cast<int>(kept[k]));
    EXPECT_EQ(reading.activity, row.activity) << RigActivityName(reading.activity);
    EXPECT_DOUBLE_EQ(reading.bit_md, row.bit);
    EXPECT_DOUBLE_EQ(reading.hook_load, row.hook * kKlbf);
    EXPECT_DOUBLE_EQ(reading.weight_on_bit, row.wob * kKlbf);
    EXPECT_DOUBLE_EQ(reading.rotary_speed, row.rpm * kRpm);
    if (row.torque == kNull) {
      EXPECT_FALSE(reading.surface_torque);
    } else {
      ASSERT_TRUE(reading.surface_torque);
      EXPECT_DOUBLE_EQ(*reading.surface_torque, row.torque * 1000 * kFtLbf);
    }
  }
  ASSERT_EQ(readings.warnings.size(), 2u);
  EXPECT_THAT(readings.warnings[0], HasSubstr("1 rows left out: no value of DBTM, HKLD, SWOB or RPMA"));
  EXPECT_THAT(readings.warnings[1], HasSubstr("3 rows left out (2 in_slips, 1 other)"));
}

TEST(RigReadingsWitsml, ATimeLog1411ReadsAndIsClassified) {
  const test_witsml::LogDocument log = TimeLog(false);
  ExpectTheTimeLog(ParseRigReadingsWitsml(log.Version1411(), "time.xml", {}), log.FirstRowLine1411());
}

TEST(RigReadingsWitsml, ATimeLog20ReadsAndIsClassified) {
  const test_witsml::LogDocument log = TimeLog(true);
  ExpectTheTimeLog(ParseRigReadingsWitsml(log.Version20(), "time.xml", {}), log.FirstRowLine20());
}

TEST(RigReadingsWitsml, TheReaderTellsALogFromACsvByItsContent) {
  const std::string path = testing::TempDir() + "/rig_readings_time_log.txt";
  const test_witsml::LogDocument log = TimeLog(false);
  std::ofstream(path) << log.Version1411();
  const RigReadings readings = ReadRigReadings(path);
  EXPECT_EQ(readings.file, path);
  ExpectTheTimeLog(readings, log.FirstRowLine1411());
  std::ofstream(path) << kHeader << kUnits << "1000,drilling,1300,20,100,120\n";
  EXPECT_EQ(ReadRigReadings(path).rows.size(), 1u);
  const InputError missing = ErrorOf([] { ReadRigReadings("/nonexistent/readings.csv"); });
  EXPECT_THAT(missing.what(), HasSubstr("/nonexistent/readings.csv: cannot open"));
}

// A depth log (1.4.1.1) indexed by the bit's depth in ft, without DBTM: the index is the bit depth,
// HKLA and WOBA the alternates, no DMEA (the hole's depth is the deepest bit depth so far).
TEST(RigReadingsWitsml, ADepthLogWithoutDbtmTakesItsIndex) {
  test_witsml::LogDocument log;
  log.index_type = "measured depth";
  log.curves = {{"DEPT", "ft"}, {"HKLA", "kN"}, {"WOBA", "kN"}, {"RPMA", "rpm"}, {"TQA", "kN.m"}};
  log.rows = {
      {"9000", "1200", "100", "120", "20"}, {"9000.5", "1201", "101", "121", ""}, {"9001", "1202", "102", "122", "21"}};
  const RigReadings readings = ParseRigReadingsWitsml(log.Version1411(), "depth.xml", {});
  ASSERT_EQ(readings.rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(readings.rows[i].activity, RigActivity::kDrilling);
    EXPECT_DOUBLE_EQ(readings.rows[i].bit_md, (9000 + 0.5 * static_cast<double>(i)) * 0.3048);
    EXPECT_DOUBLE_EQ(readings.rows[i].hook_load, (1200 + static_cast<double>(i)) * 1e3);
  }
  EXPECT_FALSE(readings.rows[1].surface_torque);  // empty
  EXPECT_DOUBLE_EQ(*readings.rows[2].surface_torque, 21e3);
  EXPECT_TRUE(readings.warnings.empty());
}

test_witsml::LogDocument OddlyNamedLog() {
  test_witsml::LogDocument log;
  log.index_type = "measured depth";
  log.curves = {{"DEPTH", "m"}, {"BITDEP", "m"}, {"HOOKLOAD", "kkgf"}, {"SWOB", "kkgf"}, {"RPMA", "rpm"}};
  log.rows = {{"2500", "2499.9", "130", "10", "140"}};
  return log;
}

TEST(RigReadingsWitsml, MnemonicsCanBeOverridden) {
  const test_witsml::LogDocument log = OddlyNamedLog();
  // Without the override the hook load is not found: refused, naming what was tried.
  const InputError error = ErrorOf([&] { ParseRigReadingsWitsml(log.Version1411(), "odd.xml", {}); });
  EXPECT_EQ(error.location().line, 3);  // <log>
  EXPECT_THAT(error.what(),
              HasSubstr("log 'rig time log' has no curve for the hook load (hook_load: tried HKLD, HKLA)"));
  EXPECT_THAT(error.what(), HasSubstr("its curves: DEPTH, BITDEP, HOOKLOAD, SWOB, RPMA"));
  RigReadingsOptions options;
  options.mnemonics = {{"hook_load", "HOOKLOAD"}, {"bit_md", "bitdep"}};
  for (const std::string& text : {log.Version1411(), OddlyNamedLog().Version20()}) {
    const RigReadings readings = ParseRigReadingsWitsml(text, "odd.xml", options);
    ASSERT_EQ(readings.rows.size(), 1u);
    EXPECT_DOUBLE_EQ(readings.rows[0].bit_md, 2499.9);            // BITDEP, not the index DEPTH
    EXPECT_DOUBLE_EQ(readings.rows[0].hook_load, 130 * 9806.65);  // kkgf: 1000 kgf
    EXPECT_DOUBLE_EQ(readings.rows[0].weight_on_bit, 10 * 9806.65);
  }
  // An override naming a curve the log lacks is refused, naming it; so is an unknown key.
  options.mnemonics = {{"surface_torque", "TQX"}};
  EXPECT_THAT(ErrorOf([&] { ParseRigReadingsWitsml(log.Version1411(), "odd.xml", options); }).what(),
              HasSubstr("the surface torque (surface_torque: tried TQX)"));
  options.mnemonics = {{"hookload", "HOOKLOAD"}};
  EXPECT_THAT(ErrorOf([&] { ParseRigReadingsWitsml(log.Version1411(), "odd.xml", options); }).what(),
              HasSubstr("'hookload': expected one of bit_md, hole_md, block_position, hook_load"));
}

TEST(RigReadingsWitsml, BadLogsAreRefusedWithLineAndCurve) {
  test_witsml::LogDocument log;
  log.curves = {{"TIME", "s"}, {"DBTM", "m"}, {"HKLD", "klbf"}, {"SWOB", "klbf"}, {"RPMA", "rpm"}};
  log.rows = {{"1", "1000", "200", "20", "120"}, {"2", "1000", "2OO", "20", "120"}};
  // An unreadable value: its row's line, the curve.
  InputError error = ErrorOf([&] { ParseRigReadingsWitsml(log.Version1411(), "bad.xml", {}); });
  EXPECT_EQ(error.location().line, log.FirstRowLine1411() + 1);
  EXPECT_THAT(error.what(), HasSubstr("logs/log[uid=l1]/logData: HKLD (the hook load): expected a number in klbf"));
  EXPECT_THAT(error.what(), HasSubstr("got '2OO'"));
  // A depth beyond the well.
  log.rows[1][2] = "200";
  RigReadingsOptions options;
  options.deepest_md = 999.0;
  error = ErrorOf([&] { ParseRigReadingsWitsml(log.Version1411(), "bad.xml", options); });
  EXPECT_EQ(error.location().line, log.FirstRowLine1411());
  EXPECT_THAT(error.what(), HasSubstr("DBTM (the bit depth): the bit depth 1000 m lies beyond the well's bottom"));
  // A unit the unit layer does not know: at the curve's logCurveInfo (line 5 + its place).
  log.curves[2].unit = "kpf";
  error = ErrorOf([&] { ParseRigReadingsWitsml(log.Version1411(), "bad.xml", {}); });
  EXPECT_EQ(error.location().line, 7);
  EXPECT_THAT(error.what(), HasSubstr("logCurveInfo[uid=HKLD]: HKLD (the hook load): expected the unit of a force (such "
                                      "as N or lbf): unknown unit \"kpf\""));
  // A unit of the wrong kind, in 2.0: at its Channel.
  log.curves[2].unit = "m";
  for (auto& row : log.rows) row[0] = "\"t\"";
  error = ErrorOf([&] { ParseRigReadingsWitsml(log.Version20(), "bad.xml", {}); });
  EXPECT_THAT(error.what(),
              HasSubstr("Log/ChannelSet/Channel: HKLD (the hook load): unit \"m\" is a length, but a force"));
}

TEST(RigReadingsWitsml, BadDocumentsAreRefused) {
  const auto error_of = [](const std::string& text) {
    return std::string(ErrorOf([&] { ParseRigReadingsWitsml(text, "bad.xml", {}); }).what());
  };
  EXPECT_THAT(error_of("<logs version=\"1.4.1.1\"/>"), HasSubstr("namespace '' is not read"));
  EXPECT_THAT(error_of("<trajectorys xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.1\"/>"),
              HasSubstr("expected <logs>"));
  EXPECT_THAT(error_of("<logs xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.3.1.1\"/>"),
              HasSubstr("version '1.3.1.1' is not read"));
  EXPECT_THAT(error_of("<logs xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.1\"/>"),
              HasSubstr("holds no <log>"));
  EXPECT_THAT(error_of("<logs xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.1\"><log/></logs>"),
              HasSubstr("expected a <logData> element"));
  EXPECT_THAT(error_of("<logs"), HasSubstr("not well-formed XML"));
  // 1.4.1.1: a row of the wrong width.
  test_witsml::LogDocument log;
  log.curves = {{"DEPT", "m"}, {"HKLD", "kN"}, {"SWOB", "kN"}, {"RPMA", "rpm"}};
  log.rows = {{"1000", "1200", "100"}};
  EXPECT_THAT(error_of(log.Version1411()), HasSubstr("expected 4 values (one a curve of the mnemonic list), got 3"));
  // 2.0: rows not as [[index], [values]], data in a file, no channel set.
  log.rows = {{"1000", "1200", "100", "120"}};
  std::string text = log.Version20();
  EXPECT_THAT(error_of(text.replace(text.find("[[1000]"), 7, "[1000")),
              HasSubstr("expected a row as [[index, ...], [value, ...]]"));
  text = log.Version20();
  EXPECT_THAT(error_of(text.replace(text.find("1200"), 4, "{}")), HasSubstr("got a object"));
  text = log.Version20();
  EXPECT_THAT(error_of(text.replace(text.find("1200"), 4, "[[[1]]]")), HasSubstr("nests deeper"));
  text = log.Version20();
  EXPECT_THAT(error_of(text.replace(text.find("<Data>["), 7, "<Data>x[")),
              HasSubstr("expected the rows as a JSON array"));
  EXPECT_THAT(error_of("<Log xmlns=\"http://www.energistics.org/energyml/data/witsmlv2\" schemaVersion=\"2.0\">"
                       "<ChannelSet><Channel><Mnemonic>HKLD</Mnemonic><Uom>kN</Uom></Channel>"
                       "<Data><FileUri>./log.avro</FileUri></Data></ChannelSet></Log>"),
              HasSubstr("the rows are in the file './log.avro'"));
  EXPECT_THAT(error_of("<Log xmlns=\"http://www.energistics.org/energyml/data/witsmlv2\" schemaVersion=\"2.0\"/>"),
              HasSubstr("holds no <ChannelSet>"));
}

// The values a 2.0 row may hold besides numbers: null, a number as a string, a value with its quality
// (point metadata).
TEST(RigReadingsWitsml, A20RowsValuesMayCarryQualityOrBeStrings) {
  test_witsml::LogDocument log;
  log.index_type = "measured depth";
  log.curves = {{"DEPT", "m"}, {"HKLD", "kN"}, {"SWOB", "kN"}, {"RPMA", "rpm"}, {"TQA", "kN.m"}};
  log.rows = {{"1000", "[1200, true]", "\"100\"", "120", "null"}};
  const RigReadings readings = ParseRigReadingsWitsml(log.Version20(), "quality.xml", {});
  ASSERT_EQ(readings.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(readings.rows[0].hook_load, 1.2e6);
  EXPECT_DOUBLE_EQ(readings.rows[0].weight_on_bit, 1e5);
  EXPECT_FALSE(readings.rows[0].surface_torque);
  EXPECT_EQ(readings.rows[0].line, log.FirstRowLine20());
}

}  // namespace rig_readings_test
}  // namespace drillflex::io
