// Errors in input carry where they happened: file, line, column (1-based) and the field.
#pragma once

#include <stdexcept>
#include <string>

namespace frustum {

struct SourceLocation {
  std::string file;
  int line = 0;    // 1-based; 0 = unknown
  int column = 0;  // 1-based; 0 = unknown
};

struct Diagnostic {
  SourceLocation where;
  std::string field;    // "problems[2].given.triangle[1]"
  std::string message;  // "expected 3 numbers, got 2"

  // FILE:LINE:COLUMN: field: message
  std::string format() const;
};

// The one exception type of the library: bad input, with its location.
class InputError : public std::runtime_error {
 public:
  explicit InputError(Diagnostic d);
  const Diagnostic& diagnostic() const { return diagnostic_; }

 private:
  Diagnostic diagnostic_;
};

// A problem whose input is well-formed but has no solution (near = far, collinear points).
// The kind names the field; the loader adds the location.
class DomainError : public std::runtime_error {
 public:
  DomainError(std::string field, const std::string& message);
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

}  // namespace frustum
