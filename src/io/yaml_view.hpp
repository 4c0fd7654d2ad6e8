// A read-only view on one node of a case file that knows where it is: the file, the line and
// column, and the key path from the root ("string[2].id"). Every read either returns a value in
// SI or throws an InputError that names all three and says what was expected.
#pragma once

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "core/types.hpp"
#include "units/units.hpp"

namespace drillflex::io {

// What every node of one file shares: the file's name and the unit system of its bare numbers.
struct ReadContext {
  std::string file;
  units::System system = units::System::SI;
};

// The widest diameter a case may give (m): far wider than any hole or tubular (tests use bare numbers
// such as `od: 8` in SI), far narrower than what the reduction could not factor.
inline constexpr double kMaxDiameter = 100.0;

class YamlView {
 public:
  YamlView(YAML::Node node, std::string path, std::shared_ptr<const ReadContext> context,
           SourceLocation fallback = {});

  const std::string& path() const { return path_; }
  SourceLocation location() const;
  const ReadContext& context() const { return *context_; }
  const YAML::Node& node() const { return node_; }

  bool IsMap() const { return node_.IsMap(); }
  bool IsSequence() const { return node_.IsSequence(); }
  bool IsScalar() const { return node_.IsScalar(); }
  bool IsNull() const { return !node_ || node_.IsNull(); }

  // Fails unless the node is a map (or null, read as an empty map, when allow_null).
  void ExpectMap(std::string_view what, bool allow_null = true) const;
  void ExpectSequence(std::string_view what) const;
  // Fails on the first key not in `allowed`, suggesting the closest allowed key.
  void AllowOnlyKeys(std::initializer_list<std::string_view> allowed) const;
  void AllowOnlyKeys(const std::vector<std::string>& allowed) const;

  // Fails on a key given twice in one map, anywhere below this node (YAML keeps both and every
  // reader takes the first: a second `operation:` block was silently ignored), naming both lines.
  void RefuseRepeatedKeys() const;

  bool Has(std::string_view key) const;
  YamlView Child(std::string_view key) const;  // required key
  std::optional<YamlView> OptionalChild(std::string_view key) const;
  // The child when the key is present at all, even with an empty value (`static:`).
  std::optional<YamlView> PresentChild(std::string_view key) const;
  std::size_t size() const { return node_.size(); }
  YamlView Item(std::size_t index) const;
  std::vector<std::string> Keys() const;

  // This node's value.
  double AsQuantity(units::Quantity quantity) const;  // SI
  double AsPositive(units::Quantity quantity) const;  // SI, > 0
  int AsInteger() const;
  bool AsBool() const;
  std::string AsString() const;
  Vec3 AsVector3(units::Quantity quantity) const;  // a list of three quantities

  // Children by key (required unless a default is given).
  double Quantity(std::string_view key, units::Quantity quantity) const;
  double QuantityOr(std::string_view key, units::Quantity quantity, double default_si) const;
  std::optional<double> OptionalQuantity(std::string_view key, units::Quantity quantity) const;
  double Positive(std::string_view key, units::Quantity quantity) const;
  std::optional<double> OptionalPositive(std::string_view key, units::Quantity quantity) const;
  int IntegerOr(std::string_view key, int default_value) const;
  std::string StringOr(std::string_view key, std::string default_value) const;

  // Throws an InputError at this node: "file:line:col: path: message".
  [[noreturn]] void Fail(const std::string& message) const;

 private:
  std::string ChildPath(std::string_view key) const;
  std::string Describe() const;  // "a map", "a list", "the text 'abc'"

  YAML::Node node_;
  std::string path_;
  std::shared_ptr<const ReadContext> context_;
  SourceLocation fallback_;
};

// "a, b, c": the words joined for a message.
std::string JoinWords(const std::vector<std::string>& words);

// Levenshtein distance, for "did you mean" suggestions.
int EditDistance(std::string_view a, std::string_view b);
// The closest candidate within a small distance, or "".
std::string ClosestMatch(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace drillflex::io
