#include "expr/identifier.h"

#include "expr/builtins.h"
#include "io/quoted_text.h"

namespace sdfwb::expr {
namespace {

bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string identifierProblem(std::string_view name) {
  const std::string quoted = "'" + io::escapedExcerpt(name) + "'";
  if (name.empty()) return "a name cannot be empty";
  if (!isLetter(name.front())) return quoted + " does not start with a letter";
  for (char c : name) {
    if (!isLetter(c) && !isDigit(c) && c != '_') {
      return quoted + " contains a character other than letters, digits and '_'";
    }
  }
  if (name == "let") return "'let' is a keyword";
  if (findBuiltin(name) != nullptr) return quoted + " is the name of a built-in function";
  return {};
}

bool isIdentifier(std::string_view name) { return identifierProblem(name).empty(); }

bool isCoordinate(std::string_view name) { return name == "x" || name == "y" || name == "z"; }

}  // namespace sdfwb::expr
