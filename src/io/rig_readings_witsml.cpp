// ParseRigReadingsWitsml: WITSML 1.4.1.1 `logs/log` and 2.0 `Log/ChannelSet` documents brought to a
// LogTable each (io/rig_readings_log.hpp), every row with the line it stands on.
//
// 1.4.1.1 (Energistics WITSML 1.4.1.1 log schema): `log` with `indexCurve`, `nullValue`,
// `dataDelimiter` (default ','), `logCurveInfo` (`mnemonic`, `unit`, `nullValue`) and `logData` with
// `mnemonicList`, `unitList` (comma-separated) and a `data` element a row.
// 2.0 (Energistics WITSML 2.0 Log schema): `Log` holds `ChannelSet`s, each with `Index` (`Mnemonic`,
// `Uom`), `Channel`s (`Mnemonic`, `Uom`) and `Data/Data`, the rows as one JSON array, a row
// [[index, ...], [value, ...]], a value a number, null, a string, or [value, quality ...] (point metadata).
#include <algorithm>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/rig_readings_log.hpp"
#include "io/rig_readings_rows.hpp"
#include "io/witsml_reader.hpp"
#include "io/xml_source.hpp"

namespace drillflex::io {
namespace {

// A row of 2.0 nests no deeper than [[index], [[value, quality]]]: deeper is not a row.
constexpr int kMaxRowDepth = 3;

LogPlace PlaceOf(const XmlSource& source, const pugi::xml_node& node) {
  return {source.Location(node), XmlSource::Path(node)};
}

std::vector<pugi::xml_node> ChildElements(const pugi::xml_node& node, std::string_view local_name) {
  std::vector<pugi::xml_node> children;
  for (const pugi::xml_node child : node.children()) {
    if (child.type() == pugi::node_element && LocalName(child) == local_name) children.push_back(child);
  }
  return children;
}

pugi::xml_node RequiredChild(const XmlSource& source, const pugi::xml_node& node, std::string_view local_name,
                             std::string_view what) {
  const pugi::xml_node child = ChildElement(node, local_name);
  if (!child) source.Fail(node, fmt::format("expected a <{}> element: {}", local_name, what));
  return child;
}

std::vector<std::string> SplitTrimmed(std::string_view text, char delimiter) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = std::min(text.find(delimiter, start), text.size());
    std::string_view cell = text.substr(start, end - start);
    const auto first = cell.find_first_not_of(" \t\r\n");
    cells.emplace_back(first == std::string_view::npos
                           ? std::string_view()
                           : cell.substr(first, cell.find_last_not_of(" \t\r\n") - first + 1));
    if (end == text.size()) return cells;
    start = end + 1;
  }
}

// The first line of an element's text (its text node's), else the element's.
int TextLine(const XmlSource& source, const pugi::xml_node& element) {
  for (const pugi::xml_node child : element.children()) {
    if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) return source.Location(child).line;
  }
  return source.Location(element).line;
}

LogTable Table1411(const XmlSource& source, const pugi::xml_node& log) {
  LogTable table;
  table.name = fmt::format("log '{}'", TrimmedText(ChildElement(log, "name")));
  table.place = PlaceOf(source, log);
  std::optional<std::string> null_value;
  if (const pugi::xml_node null = ChildElement(log, "nullValue")) null_value = TrimmedText(null);
  char delimiter = ',';
  if (const pugi::xml_node given = ChildElement(log, "dataDelimiter")) {
    const std::string text = given.child_value();  // untrimmed: a space or a tab may be the delimiter
    if (text.size() != 1) source.Fail(given, fmt::format("expected one character, got '{}'", text));
    delimiter = text[0];
  }
  const pugi::xml_node data = RequiredChild(source, log, "logData", "the log's rows");
  table.data = PlaceOf(source, data);
  // The curves: mnemonicList's order, else logCurveInfo's; units from unitList, else logCurveInfo's.
  const std::vector<pugi::xml_node> infos = ChildElements(log, "logCurveInfo");
  std::map<std::string, pugi::xml_node> info_by_mnemonic;  // the first of each mnemonic
  for (const pugi::xml_node info : infos) info_by_mnemonic.emplace(TrimmedText(ChildElement(info, "mnemonic")), info);
  const auto info_of = [&](const std::string& mnemonic) {
    const auto found = info_by_mnemonic.find(mnemonic);
    return found == info_by_mnemonic.end() ? pugi::xml_node() : found->second;
  };
  std::vector<std::string> mnemonics;
  if (const pugi::xml_node list = ChildElement(data, "mnemonicList")) {
    mnemonics = SplitTrimmed(TrimmedText(list), ',');
  } else {
    for (const pugi::xml_node info : infos) mnemonics.push_back(TrimmedText(ChildElement(info, "mnemonic")));
  }
  if (mnemonics.empty()) source.Fail(data, "expected a <mnemonicList> or <logCurveInfo>s naming the curves");
  std::vector<std::string> unit_list;
  if (const pugi::xml_node list = ChildElement(data, "unitList")) {
    unit_list = SplitTrimmed(TrimmedText(list), ',');
    if (unit_list.size() != mnemonics.size()) {
      source.Fail(list, fmt::format("expected {} units (one a curve of the mnemonic list), got {}", mnemonics.size(),
                                    unit_list.size()));
    }
  }
  const std::string index = TrimmedText(ChildElement(log, "indexCurve"));
  for (std::size_t i = 0; i < mnemonics.size(); ++i) {
    const pugi::xml_node info = info_of(mnemonics[i]);
    LogCurve curve;
    curve.mnemonic = mnemonics[i];
    curve.uom = !unit_list.empty() ? unit_list[i] : TrimmedText(ChildElement(info, "unit"));
    curve.null_value = null_value;
    if (const pugi::xml_node own = ChildElement(info, "nullValue")) curve.null_value = TrimmedText(own);
    curve.place = PlaceOf(source, info ? info : data);
    if (!index.empty() && curve.mnemonic == index) table.index = i;
    table.curves.push_back(curve);
  }
  for (const pugi::xml_node row : ChildElements(data, "data")) {
    LogRow parsed{TextLine(source, row), SplitTrimmed(row.child_value(), delimiter)};
    if (parsed.cells.size() != table.curves.size()) {
      source.Fail(row, fmt::format("expected {} values (one a curve of the mnemonic list), got {}", table.curves.size(),
                                   parsed.cells.size()));
    }
    table.rows.push_back(std::move(parsed));
  }
  return table;
}

// A cell of a 2.0 row as text: a number's shortest digits, a string as it is, "" for null.
std::string CellText(const nlohmann::json& value, bool metadata_allowed,
                     const std::function<void(const std::string&)>& fail) {
  if (value.is_null()) return "";
  if (value.is_number()) return fmt::format("{}", value.get<double>());
  if (value.is_string()) return value.get_ref<const std::string&>();
  if (value.is_array() && metadata_allowed && !value.empty()) return CellText(value.front(), false, fail);
  fail("expected a number, a string or null as a value, got a " + std::string(value.type_name()));
  return "";
}

// The rows of a 2.0 `Data` text: a JSON array of [[index, ...], [value, ...]], each row parsed alone
// so that its line is known.
void Rows20(const XmlSource& source, const pugi::xml_node& element, LogTable& table, std::size_t index_count) {
  const std::string_view text = element.child_value();
  int line = TextLine(source, element);
  std::size_t at = 0;
  const auto fail = [&](const std::string& message) {
    throw InputError({source.file(), line, 0}, XmlSource::Path(element), message);
  };
  const auto skip_space = [&] {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\r' || text[at] == '\n' ||
                                (text[at] == ',' && !table.rows.empty()))) {
      if (text[at] == '\n') ++line;
      ++at;
    }
  };
  skip_space();
  if (at == text.size() || text[at] != '[') fail("expected the rows as a JSON array: [[[index], [value, ...]], ...]");
  ++at;
  while (true) {
    skip_space();
    if (at == text.size()) fail("the rows' JSON array has no closing ']'");
    if (text[at] == ']') break;
    if (text[at] != '[') fail(fmt::format("expected a row [[index], [value, ...]], got '{}'", text[at]));
    // The row's end: its matching bracket, strings skipped.
    const std::size_t start = at;
    const int row_line = line;
    int depth = 0;
    bool in_string = false;
    for (; at < text.size(); ++at) {
      const char c = text[at];
      if (c == '\n') ++line;
      if (in_string) {
        if (c == '\\') {
          ++at;  // an escaped character
        } else if (c == '"') {
          in_string = false;
        }
        continue;
      }
      if (c == '"') {
        in_string = true;
      } else if (c == '[' && ++depth > kMaxRowDepth) {
        fail("a row nests deeper than [[index], [[value, quality]]]");
      } else if (c == ']' && --depth == 0) {
        break;
      }
    }
    if (at >= text.size()) fail("a row has no closing ']'");
    ++at;
    const nlohmann::json row = nlohmann::json::parse(text.substr(start, at - start), nullptr, false);
    const auto row_fail = [&](const std::string& message) {
      throw InputError({source.file(), row_line, 0}, XmlSource::Path(element), message);
    };
    if (row.is_discarded()) row_fail("a row is not JSON: expected [[index, ...], [value, ...]]");
    if (row.size() != 2 || !row[0].is_array() || !row[1].is_array()) {
      row_fail("expected a row as [[index, ...], [value, ...]]");
    }
    if (row[0].size() != index_count || row[1].size() != table.curves.size() - index_count) {
      row_fail(fmt::format("expected {} index values and {} channel values (the channel set's), got {} and {}",
                           index_count, table.curves.size() - index_count, row[0].size(), row[1].size()));
    }
    LogRow parsed{row_line, {}};
    for (const nlohmann::json* part : {&row[0], &row[1]}) {
      for (const nlohmann::json& value : *part) parsed.cells.push_back(CellText(value, true, row_fail));
    }
    table.rows.push_back(std::move(parsed));
  }
  ++at;
  skip_space();
  if (at != text.size()) fail("text after the rows' JSON array");
}

LogTable Table20(const XmlSource& source, const pugi::xml_node& log, const pugi::xml_node& set) {
  LogTable table;
  std::string title = TrimmedText(ChildElement(ChildElement(set, "Citation"), "Title"));
  if (title.empty()) title = TrimmedText(ChildElement(ChildElement(log, "Citation"), "Title"));
  table.name = fmt::format("ChannelSet '{}'", title);
  table.place = PlaceOf(source, set);
  const auto curve_of = [&](const pugi::xml_node& node, bool index) {
    LogCurve curve;
    curve.mnemonic = TrimmedText(ChildElement(node, "Mnemonic"));
    if (curve.mnemonic.empty() && !index) source.Fail(node, "expected a <Mnemonic> naming the channel");
    curve.uom = TrimmedText(ChildElement(node, "Uom"));
    curve.place = PlaceOf(source, node);
    return curve;
  };
  const std::vector<pugi::xml_node> indexes = ChildElements(set, "Index");
  for (const pugi::xml_node index : indexes) table.curves.push_back(curve_of(index, true));
  if (!indexes.empty()) table.index = 0;
  for (const pugi::xml_node channel : ChildElements(set, "Channel")) table.curves.push_back(curve_of(channel, false));
  if (table.curves.size() == indexes.size()) source.Fail(set, "expected <Channel>s: the channel set has none");
  const pugi::xml_node data = RequiredChild(source, set, "Data", "the channel set's rows (ChannelData)");
  const pugi::xml_node rows = ChildElement(data, "Data");
  if (!rows) {
    const std::string uri = TrimmedText(ChildElement(data, "FileUri"));
    source.Fail(data, uri.empty()
                          ? "expected the rows in <Data><Data>[...]</Data></Data>"
                          : fmt::format("the rows are in the file '{}', which drillflex does not read: expected "
                                        "them in the document (<Data><Data>[...]</Data></Data>)",
                                        uri));
  }
  table.data = PlaceOf(source, rows);
  Rows20(source, rows, table, indexes.size());
  return table;
}

void CheckVersion(const XmlSource& source, const char* attribute, std::string_view expected) {
  const std::string version = source.root().attribute(attribute).value();
  if (version != expected) {
    source.Fail(source.root(), fmt::format("WITSML {} '{}' is not read: drillflex reads 1.4.1.1 and 2.0 (this "
                                           "namespace: {})",
                                           attribute, version, expected));
  }
}

}  // namespace

RigReadings ParseRigReadingsWitsml(std::string_view text, const std::string& file, const RigReadingsOptions& options) {
  const XmlSource source(text, file);
  const pugi::xml_node root = source.root();
  const std::string space = NamespaceOf(root);
  std::vector<LogTable> tables;
  if (space == kWitsml1411Namespace) {
    CheckVersion(source, "version", "1.4.1.1");
    if (LocalName(root) != "logs") source.Fail(root, "expected <logs>: readings are read from WITSML log documents");
    for (const pugi::xml_node log : ChildElements(root, "log")) tables.push_back(Table1411(source, log));
    if (tables.empty()) source.Fail(root, "the document holds no <log>");
  } else if (space == kWitsml20Namespace) {
    CheckVersion(source, "schemaVersion", "2.0");
    if (LocalName(root) != "Log") source.Fail(root, "expected <Log>: readings are read from WITSML log documents");
    for (const pugi::xml_node set : ChildElements(root, "ChannelSet")) tables.push_back(Table20(source, root, set));
    if (tables.empty()) source.Fail(root, "the log holds no <ChannelSet>");
  } else {
    source.Fail(root, fmt::format("namespace '{}' is not read: expected a WITSML 1.4.1.1 ({}) or 2.0 ({}) log, or a "
                                  "readings CSV",
                                  space, kWitsml1411Namespace, kWitsml20Namespace));
  }
  std::vector<RigReading> rows;
  std::vector<std::string> warnings;
  for (const LogTable& table : tables) {
    for (const RigReading& reading : ReadingsOfLog(table, options, warnings)) rows.push_back(reading);
  }
  const LogPlace& first = tables.front().place;
  return KeptReadings(
      file, rows, std::move(warnings), first.location,
      XmlSource::Path(root) + ": the log holds no row with a bit depth, hook load, WOB and rotary speed");
}

}  // namespace drillflex::io
