// XmlSource: pugixml's document with line numbers computed from the node offsets it keeps.
#include "io/xml_source.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace drillflex::io {

XmlSource::XmlSource(std::string_view text, std::string file) : file_(std::move(file)) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') line_starts_.push_back(i + 1);
  }
  // parse_default: comments and any DOCTYPE skipped, the predefined entities and character references
  // expanded; pugixml defines no other entities and fetches nothing.
  const pugi::xml_parse_result result =
      document_.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!result) {
    throw InputError(LocationOfOffset(result.offset), "",
                     fmt::format("not well-formed XML: {}", result.description()));
  }
  if (!root()) throw InputError({file_, 1, 1}, "", "the document has no root element");
}

SourceLocation XmlSource::LocationOfOffset(std::ptrdiff_t offset) const {
  if (offset < 0) return {file_, 0, 0};
  const auto after = std::upper_bound(line_starts_.begin(), line_starts_.end(), static_cast<std::size_t>(offset));
  const auto line = static_cast<int>(after - line_starts_.begin());  // 1-based: the line starting before
  const auto column = static_cast<int>(static_cast<std::size_t>(offset) - *(after - 1)) + 1;
  return {file_, line, column};
}

SourceLocation XmlSource::Location(const pugi::xml_node& node) const {
  return LocationOfOffset(node.offset_debug());
}

std::string XmlSource::Path(const pugi::xml_node& node) {
  std::vector<std::string> steps;
  for (pugi::xml_node at = node; at && at.type() == pugi::node_element; at = at.parent()) {
    std::string step(LocalName(at));
    if (const pugi::xml_attribute uid = at.attribute("uid")) step.append(fmt::format("[uid={}]", uid.value()));
    steps.push_back(step);
  }
  std::string path;
  for (auto step = steps.rbegin(); step != steps.rend(); ++step) {
    path.append(path.empty() ? "" : "/").append(*step);
  }
  return path;
}

void XmlSource::Fail(const pugi::xml_node& node, const std::string& message) const {
  throw InputError(Location(node), Path(node), message);
}

std::string_view LocalName(const pugi::xml_node& node) {
  const std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

std::string NamespaceOf(const pugi::xml_node& node) {
  const std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  const std::string attribute =
      colon == std::string_view::npos ? std::string("xmlns") : "xmlns:" + std::string(name.substr(0, colon));
  for (pugi::xml_node at = node; at; at = at.parent()) {
    if (const pugi::xml_attribute declared = at.attribute(attribute.c_str())) return declared.value();
  }
  return "";
}

pugi::xml_node ChildElement(const pugi::xml_node& node, std::string_view local_name) {
  for (const pugi::xml_node child : node.children()) {
    if (child.type() == pugi::node_element && LocalName(child) == local_name) return child;
  }
  return {};
}

std::string TrimmedText(const pugi::xml_node& node) {
  std::string_view text = node.child_value();
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return std::string(text);
}

}  // namespace drillflex::io
