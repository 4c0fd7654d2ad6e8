// The error types of drillflex. Every error carries enough context for the user to act on it:
// an input error names the file, the line and column, and the key path; a solver error names
// where and why it stopped.
#pragma once

#include <stdexcept>
#include <string>

namespace drillflex {

// Where in a case (or data) file a value came from. line and column are 1-based; 0 = unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

// Bad input: the message reads "case.yaml:12:5: string[2].id: <what was expected>".
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation location, std::string key_path, std::string message);

  const SourceLocation& location() const { return location_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation location_;
  std::string key_path_;
  std::string message_;
};

// A value with a unit that cannot be read or has the wrong dimension. Thrown by units/, where no
// file position is known; the case reader turns it into an InputError at the value's position.
class UnitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A numerical method that did not reach its goal: the message says which, where and why.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A broken internal invariant (a bug, not bad input).
class LogicError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// Formats "file:line:column" (omitting what is unknown).
std::string FormatLocation(const SourceLocation& location);

}  // namespace drillflex
