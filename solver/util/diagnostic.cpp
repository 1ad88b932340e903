#include "solver/util/diagnostic.hpp"

namespace frustum {

std::string Diagnostic::format() const {
  std::string s = where.file.empty() ? std::string("<input>") : where.file;
  if (where.line > 0) {
    s += ":" + std::to_string(where.line);
    if (where.column > 0) s += ":" + std::to_string(where.column);
  }
  s += ": ";
  if (!field.empty()) s += field + ": ";
  return s + message;
}

InputError::InputError(Diagnostic d) : std::runtime_error(d.format()), diagnostic_(std::move(d)) {}

DomainError::DomainError(std::string field, const std::string& message)
    : std::runtime_error(message), field_(std::move(field)) {}

}  // namespace frustum
