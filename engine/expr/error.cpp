#include "expr/error.h"

namespace sdfwb::expr {

std::string describe(SourceLocation where) {
  std::string column = "column " + std::to_string(where.column);
  if (where.line == 1) return column;
  return "line " + std::to_string(where.line) + ", " + column;
}

Error::Error(SourceLocation where, const std::string& message)
    : std::runtime_error(describe(where) + ": " + message), where_(where), message_(message) {}

}  // namespace sdfwb::expr
