#include "core/error.hpp"

#include <utility>

namespace drillflex {

std::string FormatLocation(const SourceLocation& location) {
  std::string text = location.file.empty() ? std::string("<input>") : location.file;
  if (location.line > 0) {
    text.append(":").append(std::to_string(location.line));
    if (location.column > 0) text.append(":").append(std::to_string(location.column));
  }
  return text;
}

namespace {
std::string ComposeInputMessage(const SourceLocation& location, const std::string& key_path,
                                const std::string& message) {
  std::string text = FormatLocation(location);
  text.append(": ");
  if (!key_path.empty()) text.append(key_path).append(": ");
  text.append(message);
  return text;
}
}  // namespace

InputError::InputError(SourceLocation location, std::string key_path, std::string message)
    : std::runtime_error(ComposeInputMessage(location, key_path, message)),
      location_(std::move(location)),
      key_path_(std::move(key_path)),
      message_(std::move(message)) {}

}  // namespace drillflex
