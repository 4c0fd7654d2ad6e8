// Values of a case set by their key paths (io::ParseCaseWithValues): each is written into the case's YAML
// tree before the reader reads it, so the reader checks a set value as any other and names its key.
#include <algorithm>
#include <charconv>
#include <optional>

#include <fmt/format.h>

#include "io/case_sections.hpp"

namespace drillflex::io {
namespace {

// One step of a key path: a map's key, or (key empty) a list's item.
struct KeyStep {
  std::string key;
  std::size_t index = 0;
};

[[noreturn]] void FailKeyPath(const CaseValue& value, const std::string& file) {
  throw InputError({file, 0, 0}, value.key,
                   "not a key path: keys joined by '.' and list items as [index], e.g. string[4].length");
}

// "string[4].length" -> string, [4], length.
std::vector<KeyStep> ParseKeyPath(const CaseValue& value, const std::string& file) {
  const std::string& path = value.key;
  std::vector<KeyStep> steps;
  std::size_t at = 0;
  while (at < path.size()) {
    const std::size_t end = std::min(path.find_first_of(".[", at), path.size());
    if (end == at) FailKeyPath(value, file);
    steps.push_back({path.substr(at, end - at)});
    at = end;
    while (at < path.size() && path[at] == '[') {
      const std::size_t close = path.find(']', at);
      if (close == std::string::npos || close == at + 1) FailKeyPath(value, file);
      std::size_t index = 0;
      const auto [last, error] = std::from_chars(path.data() + at + 1, path.data() + close, index);
      if (error != std::errc() || last != path.data() + close) FailKeyPath(value, file);
      steps.push_back({"", index});
      at = close + 1;
    }
    if (at < path.size()) {
      if (path[at] != '.' || at + 1 == path.size()) FailKeyPath(value, file);
      ++at;
    }
  }
  if (steps.empty()) FailKeyPath(value, file);
  return steps;
}

// A copy of `node` without positions of its own: the reader then places an error in a value set here at
// the place of the value it replaces (or of the map it is added to), not at a line of the value's text.
YAML::Node Unplaced(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return YAML::Node(node.Scalar());
    case YAML::NodeType::Sequence: {
      YAML::Node copy(YAML::NodeType::Sequence);
      for (const YAML::Node& item : node) copy.push_back(Unplaced(item));
      return copy;
    }
    case YAML::NodeType::Map: {
      YAML::Node copy(YAML::NodeType::Map);
      for (const auto& entry : node) copy[entry.first.Scalar()] = Unplaced(entry.second);
      return copy;
    }
    default:
      return YAML::Node(YAML::NodeType::Null);
  }
}

// The node one step below `here`, which must be in the case.
YamlView Descend(const YamlView& here, const KeyStep& step, const CaseValue& value) {
  const std::string name = here.path().empty() ? std::string("the case") : fmt::format("'{}'", here.path());
  if (step.key.empty()) {
    if (!here.IsSequence()) {
      throw InputError(here.location(), value.key, fmt::format("{} is not a list: it has no item [{}]", name, step.index));
    }
    if (step.index >= here.size()) {
      throw InputError(here.location(), value.key,
                       fmt::format("{} has {} items ([0] to [{}]): no item [{}]", name, here.size(),
                                   here.size() == 0 ? 0 : here.size() - 1, step.index));
    }
    return here.Item(step.index);
  }
  if (!here.IsMap()) {
    throw InputError(here.location(), value.key, fmt::format("{} is not a map: it has no key '{}'", name, step.key));
  }
  const auto child = here.PresentChild(step.key);
  if (!child) {
    throw InputError(here.location(), value.key,
                     fmt::format("{} has no key '{}' (it has {})", name, step.key, JoinWords(here.Keys())));
  }
  return *child;
}

void SetCaseValue(const YamlView& root, const CaseValue& value) {
  const std::string& file = root.context().file;
  const std::vector<KeyStep> steps = ParseKeyPath(value, file);
  YAML::Node parsed;
  try {
    parsed = YAML::Load(value.value);
  } catch (const YAML::Exception& error) {
    throw InputError({file, 0, 0}, value.key, fmt::format("the value '{}' is not YAML: {}", value.value, error.msg));
  }
  // Never assigned: assigning a YAML::Node (in a YamlView too) overwrites the node it refers to.
  std::optional<YamlView> here(root);
  for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
    // A map the case leaves out (`model.contact` when the case gives no contact settings, `fluid` in a
    // dry case): created empty; the reader checks its keys as any other, so a misspelled one is still
    // named ("unknown key 'fluidd' (did you mean 'fluid'?)"). A list's item must be there.
    const KeyStep& step = steps[i];
    if (!step.key.empty() && (here->IsNull() || (here->IsMap() && !here->PresentChild(step.key)))) {
      YAML::Node parent = here->node();
      parent[step.key] = YAML::Node(YAML::NodeType::Map);
    }
    here.emplace(Descend(*here, step, value));
  }
  // The last key may be one the case leaves out (the reader checks it); a list's item must be there.
  const KeyStep& last = steps.back();
  if (!last.key.empty() && !here->IsMap() && !here->IsNull()) Descend(*here, last, value);  // throws: not a map
  YAML::Node parent = here->node();
  YAML::Node target = last.key.empty() ? Descend(*here, last, value).node() : parent[last.key];
  if (parsed.IsScalar() && target.IsDefined()) {
    target = parsed.Scalar();  // in place: the node keeps its position in the file
  } else {
    target = Unplaced(parsed);
  }
}

}  // namespace

void SetCaseValues(const YamlView& root, const std::vector<CaseValue>& values) {
  for (const CaseValue& value : values) SetCaseValue(root, value);
}

}  // namespace drillflex::io
