// An XML document read by pugixml (Debian's libpugixml-dev) that knows where each element is: its
// file, line and column (from the element's offset in the text), and its path from the root. Every
// error about a node names all three, as the case reader's errors do.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "core/error.hpp"

namespace drillflex::io {

class XmlSource {
 public:
  // Parses `text` (kept in memory: nothing refers to it afterwards). Malformed XML throws an
  // InputError at the line where pugixml stopped.
  XmlSource(std::string_view text, std::string file);
  XmlSource(const XmlSource&) = delete;
  XmlSource& operator=(const XmlSource&) = delete;

  const std::string& file() const { return file_; }
  pugi::xml_node root() const { return document_.document_element(); }

  // The file, line and column of an element (its name, just after '<').
  SourceLocation Location(const pugi::xml_node& node) const;
  // "tubulars/tubular[uid=bha]/tubularComponent[uid=c3]/od": the element's path from the root, each
  // step with its uid when it has one.
  static std::string Path(const pugi::xml_node& node);
  // Throws an InputError at the element: "file:line:column: path: message".
  [[noreturn]] void Fail(const pugi::xml_node& node, const std::string& message) const;

 private:
  SourceLocation LocationOfOffset(std::ptrdiff_t offset) const;

  std::string file_;
  std::vector<std::size_t> line_starts_;  // offset of the first character of each line
  pugi::xml_document document_;
};

// The local part of an element's name ("witsml:md" -> "md").
std::string_view LocalName(const pugi::xml_node& node);
// The namespace URI of an element: its prefix's (or the default) xmlns declaration on it or an
// ancestor; "" when none is declared.
std::string NamespaceOf(const pugi::xml_node& node);
// The first child element with this local name (any prefix), or an empty node.
pugi::xml_node ChildElement(const pugi::xml_node& node, std::string_view local_name);
// The element's text, white space trimmed.
std::string TrimmedText(const pugi::xml_node& node);

}  // namespace drillflex::io
