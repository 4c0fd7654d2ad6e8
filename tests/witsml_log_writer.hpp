// A test-only writer of WITSML `log` documents (never in src/: drillflex reads logs, it does not write
// them): curves with their units and rows of values as text, as a 1.4.1.1 `logs/log` (logCurveInfo,
// logData with mnemonicList, unitList and a `data` element a row) or a 2.0 `Log/ChannelSet` (Index,
// Channels, the rows as one JSON array in Data/Data). Each row stands on its own line: row i (0-based)
// is on line FirstRowLine1411() + i (2.0: FirstRowLine20() + i).
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

namespace drillflex::test_witsml {

struct LogCurve {
  std::string mnemonic;
  std::string unit;
};

// The first curve is the index; a row's cells one a curve, as text. A 1.4.1.1 cell is written as it
// is ("" for an empty value); a 2.0 cell is a JSON value ("1.5", "null", "\"2024-01-01T00:00:00Z\"",
// "[1.5, true]").
struct LogDocument {
  std::vector<LogCurve> curves;
  std::vector<std::vector<std::string>> rows;
  std::string null_value = "-999.25";  // 1.4.1.1's nullValue
  std::string index_type = "date time";

  std::string Version1411() const {
    std::string mnemonics, units, infos, data;
    for (const LogCurve& curve : curves) {
      mnemonics += (mnemonics.empty() ? "" : ",") + curve.mnemonic;
      units += (units.empty() ? "" : ",") + curve.unit;
      infos += fmt::format(
          "<logCurveInfo uid=\"{0}\"><mnemonic>{0}</mnemonic><unit>{1}</unit>"
          "<typeLogData>double</typeLogData></logCurveInfo>\n",
          curve.mnemonic, curve.unit);
    }
    for (const auto& row : rows) {
      std::string cells;
      for (std::size_t i = 0; i < row.size(); ++i) cells += (i == 0 ? "" : ",") + row[i];
      data += "<data>" + cells + "</data>\n";
    }
    return fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<logs xmlns=\"http://www.witsml.org/schemas/1series\" version=\"1.4.1.1\">\n"
        "<log uidWell=\"w\" uidWellbore=\"wb\" uid=\"l1\">\n"
        "<name>rig time log</name><indexType>{}</indexType><indexCurve>{}</indexCurve>"
        "<nullValue>{}</nullValue>\n"
        "{}<logData>\n<mnemonicList>{}</mnemonicList>\n<unitList>{}</unitList>\n{}</logData>\n</log>\n</logs>\n",
        index_type, curves.at(0).mnemonic, null_value, infos, mnemonics, units, data);
  }

  std::string Version20() const {
    std::string channels, data;
    for (std::size_t i = 1; i < curves.size(); ++i) {
      channels += fmt::format(
          "<Channel uuid=\"c{0}\"><eml:Citation><eml:Title>{1}</eml:Title></eml:Citation>"
          "<Mnemonic>{1}</Mnemonic><DataType>double</DataType><Uom>{2}</Uom></Channel>\n",
          i, curves[i].mnemonic, curves[i].unit);
    }
    for (std::size_t r = 0; r < rows.size(); ++r) {
      std::string values;
      for (std::size_t i = 1; i < rows[r].size(); ++i) values += (i == 1 ? "" : ", ") + rows[r][i];
      data += fmt::format("[[{}], [{}]]{}\n", rows[r].at(0), values, r + 1 < rows.size() ? "," : "");
    }
    return fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<Log xmlns=\"http://www.energistics.org/energyml/data/witsmlv2\" "
        "xmlns:eml=\"http://www.energistics.org/energyml/data/commonv2\" schemaVersion=\"2.0\" uuid=\"l1\">\n"
        "<eml:Citation><eml:Title>rig time log</eml:Title></eml:Citation>\n"
        "<ChannelSet uuid=\"s1\">\n<eml:Citation><eml:Title>surface</eml:Title></eml:Citation>\n"
        "<Index><IndexType>{}</IndexType><Uom>{}</Uom><Direction>increasing</Direction><Mnemonic>{}</Mnemonic>"
        "</Index>\n{}<Data><Data>[\n{}]</Data></Data>\n</ChannelSet>\n</Log>\n",
        index_type, curves.at(0).unit, curves.at(0).mnemonic, channels, data);
  }

  // The line of the first row: 1.4.1.1's after four lines of head, a logCurveInfo a curve and three of
  // logData; 2.0's after six lines of head, a Channel a curve but the index, and the Data line.
  int FirstRowLine1411() const { return 8 + static_cast<int>(curves.size()); }
  int FirstRowLine20() const { return 7 + static_cast<int>(curves.size()); }
};

}  // namespace drillflex::test_witsml
