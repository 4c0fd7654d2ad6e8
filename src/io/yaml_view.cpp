#include "io/yaml_view.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace drillflex::io {

YamlView::YamlView(YAML::Node node, std::string path, std::shared_ptr<const ReadContext> context,
                   SourceLocation fallback)
    : node_(std::move(node)), path_(std::move(path)), context_(std::move(context)),
      fallback_(std::move(fallback)) {}

SourceLocation YamlView::location() const {
  SourceLocation location = fallback_;
  location.file = context_->file;
  if (node_ && node_.Mark().line >= 0 && !node_.Mark().is_null()) {
    location.line = node_.Mark().line + 1;  // yaml-cpp counts from 0
    location.column = node_.Mark().column + 1;
  }
  return location;
}

void YamlView::Fail(const std::string& message) const {
  throw InputError(location(), path_, message);
}

std::string YamlView::Describe() const {
  if (!node_ || node_.IsNull()) return "nothing";
  if (node_.IsMap()) return "a map";
  if (node_.IsSequence()) return fmt::format("a list of {}", node_.size());
  return fmt::format("'{}'", node_.Scalar());
}

void YamlView::ExpectMap(std::string_view what, bool allow_null) const {
  if (node_.IsMap() || (allow_null && IsNull())) return;
  Fail(fmt::format("expected {} (a map of keys), got {}", what, Describe()));
}

void YamlView::ExpectSequence(std::string_view what) const {
  if (node_.IsSequence()) return;
  Fail(fmt::format("expected {} (a list), got {}", what, Describe()));
}

std::vector<std::string> YamlView::Keys() const {
  std::vector<std::string> keys;
  if (!node_.IsMap()) return keys;
  for (const auto& entry : node_) keys.push_back(entry.first.Scalar());
  return keys;
}

void YamlView::AllowOnlyKeys(std::initializer_list<std::string_view> allowed) const {
  AllowOnlyKeys(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void YamlView::AllowOnlyKeys(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) return;
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string message = fmt::format("unknown key '{}'", key);
    const std::string suggestion = ClosestMatch(key, allowed);
    if (!suggestion.empty()) {
      message.append(fmt::format(" (did you mean '{}'?)", suggestion));
    } else {
      message.append("; expected one of: ").append(JoinWords(allowed));
    }
    YamlView(entry.first, ChildPath(key), context_, location()).Fail(message);
  }
}

void YamlView::RefuseRepeatedKeys() const {
  // Depth first with a stack of its own, not by recursion: yaml-cpp reads maps and lists nested up to
  // its own limit, and a case (or the fuzzer's input) nested that deep must not run out of stack here.
  std::vector<YamlView> pending{*this};
  while (!pending.empty()) {
    const YamlView view = std::move(pending.back());
    pending.pop_back();
    if (view.node_.IsSequence()) {
      for (std::size_t i = 0; i < view.node_.size(); ++i) pending.push_back(view.Item(i));
      continue;
    }
    if (!view.node_.IsMap()) continue;
    std::vector<std::pair<std::string, YAML::Mark>> seen;
    for (const auto& entry : view.node_) {
      if (!entry.first.IsScalar()) continue;
      const std::string key = entry.first.Scalar();
      const YamlView key_view(entry.first, view.ChildPath(key), context_, view.location());
      for (const auto& [earlier, mark] : seen) {
        if (earlier != key) continue;
        const YAML::Mark again = entry.first.Mark();
        const std::string where = mark.line == again.line
                                      ? fmt::format("on line {}, at columns {} and {}", again.line + 1,
                                                    mark.column + 1, again.column + 1)
                                      : fmt::format("at line {} and at line {}", mark.line + 1, again.line + 1);
        key_view.Fail(fmt::format("'{}' is given twice in one map, {}: give it once (merge the two, or remove one)",
                                  key, where));
      }
      seen.emplace_back(key, entry.first.Mark());
      pending.emplace_back(entry.second, view.ChildPath(key), context_, key_view.location());
    }
  }
}

std::string YamlView::ChildPath(std::string_view key) const {
  if (path_.empty()) return std::string(key);
  std::string path = path_;
  path.append(".").append(key);
  return path;
}

bool YamlView::Has(std::string_view key) const {
  if (!node_.IsMap()) return false;
  const YAML::Node child = node_[std::string(key)];
  return child.IsDefined() && !child.IsNull();
}

YamlView YamlView::Child(std::string_view key) const {
  if (!Has(key)) {
    Fail(fmt::format("missing required key '{}'", key));
  }
  return YamlView(node_[std::string(key)], ChildPath(key), context_, location());
}

std::optional<YamlView> YamlView::OptionalChild(std::string_view key) const {
  if (!Has(key)) return std::nullopt;
  return YamlView(node_[std::string(key)], ChildPath(key), context_, location());
}

std::optional<YamlView> YamlView::PresentChild(std::string_view key) const {
  if (!node_.IsMap() || !node_[std::string(key)].IsDefined()) return std::nullopt;
  return YamlView(node_[std::string(key)], ChildPath(key), context_, location());
}

YamlView YamlView::Item(std::size_t index) const {
  return YamlView(node_[index], fmt::format("{}[{}]", path_, index), context_, location());
}

double YamlView::AsQuantity(units::Quantity quantity) const {
  if (!node_.IsScalar()) {
    Fail(fmt::format("expected {}, got {}", units::QuantityName(quantity), Describe()));
  }
  try {
    const double value = units::ParseQuantity(node_.Scalar(), quantity, context_->system);
    if (!std::isfinite(value)) Fail("expected a finite number");
    // No hole or tubular is wider: a diameter of 5.6e8 m (fuzz/case_file: "5 4444444444in", five
    // times 4444444444 in) read, and the body's stiffness then could not be factored.
    if (quantity == units::Quantity::Diameter && std::abs(value) > kMaxDiameter) {
      Fail(fmt::format("expected a diameter of at most {} m, got '{}'", kMaxDiameter, node_.Scalar()));
    }
    return value;
  } catch (const UnitError& error) {
    Fail(error.what());
  }
}

double YamlView::AsPositive(units::Quantity quantity) const {
  const double value = AsQuantity(quantity);
  if (!(value > 0.0)) {
    Fail(fmt::format("expected {} greater than zero, got '{}'", units::QuantityName(quantity),
                     node_.Scalar()));
  }
  return value;
}

int YamlView::AsInteger() const {
  if (node_.IsScalar()) {
    const std::string& text = node_.Scalar();
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc() && end == text.data() + text.size()) return value;
  }
  Fail(fmt::format("expected a whole number, got {}", Describe()));
}

bool YamlView::AsBool() const {
  if (node_.IsScalar()) {
    std::string text = node_.Scalar();
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    if (text == "true" || text == "yes" || text == "on") return true;
    if (text == "false" || text == "no" || text == "off") return false;
  }
  Fail(fmt::format("expected true or false, got {}", Describe()));
}

std::string YamlView::AsString() const {
  if (!node_.IsScalar()) Fail(fmt::format("expected a text value, got {}", Describe()));
  return node_.Scalar();
}

Vec3 YamlView::AsVector3(units::Quantity quantity) const {
  if (!node_.IsSequence() || node_.size() != 3) {
    Fail(fmt::format("expected a list of three values ({} each), got {}",
                     units::QuantityName(quantity), Describe()));
  }
  return Vec3(Item(0).AsQuantity(quantity), Item(1).AsQuantity(quantity),
              Item(2).AsQuantity(quantity));
}

double YamlView::Quantity(std::string_view key, units::Quantity quantity) const {
  return Child(key).AsQuantity(quantity);
}

double YamlView::QuantityOr(std::string_view key, units::Quantity quantity, double default_si) const {
  const auto child = OptionalChild(key);
  return child ? child->AsQuantity(quantity) : default_si;
}

std::optional<double> YamlView::OptionalQuantity(std::string_view key,
                                                 units::Quantity quantity) const {
  const auto child = OptionalChild(key);
  if (!child) return std::nullopt;
  return child->AsQuantity(quantity);
}

double YamlView::Positive(std::string_view key, units::Quantity quantity) const {
  return Child(key).AsPositive(quantity);
}

std::optional<double> YamlView::OptionalPositive(std::string_view key,
                                                 units::Quantity quantity) const {
  const auto child = OptionalChild(key);
  if (!child) return std::nullopt;
  return child->AsPositive(quantity);
}

int YamlView::IntegerOr(std::string_view key, int default_value) const {
  const auto child = OptionalChild(key);
  return child ? child->AsInteger() : default_value;
}

std::string YamlView::StringOr(std::string_view key, std::string default_value) const {
  const auto child = OptionalChild(key);
  return child ? child->AsString() : std::move(default_value);
}

std::string JoinWords(const std::vector<std::string>& words) {
  std::string text;
  for (const auto& word : words) text.append(text.empty() ? "" : ", ").append(word);
  return text;
}

int EditDistance(std::string_view a, std::string_view b) {
  std::vector<int> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      const int substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({above + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string ClosestMatch(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  int best_distance = 1 + static_cast<int>(word.size()) / 3;  // a third of the word, at least 1
  best_distance = std::min(best_distance, 3);
  for (const auto& candidate : candidates) {
    const int distance = EditDistance(word, candidate);
    if (distance <= best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

}  // namespace drillflex::io
