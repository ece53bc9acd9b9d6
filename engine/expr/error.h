#pragma once
// User errors in formulas: one line naming where and what.

#include <stdexcept>
#include <string>

namespace sdfwb::expr {

// A position in the user's source text, 1-based.
struct SourceLocation {
  int line = 1;
  int column = 1;
};

// "column 7" on the first line, "line 2, column 7" after it (one-line formulas,
// the common case, never mention a line).
std::string describe(SourceLocation where);

// A user error in a formula. what() is the whole line, for example
// "column 7: expected ')' after function arguments".
class Error : public std::runtime_error {
 public:
  Error(SourceLocation where, const std::string& message);

  SourceLocation where() const { return where_; }
  // The message without its location prefix.
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

}  // namespace sdfwb::expr
