#pragma once
// Splits formula text into tokens with their source locations.

#include <gmpxx.h>

#include <string>
#include <string_view>
#include <vector>

#include "expr/error.h"

namespace sdfwb::expr {

enum class TokenKind {
  Number,      // 12, 0.5, .5, 2., 1e-3: an exact decimal
  Identifier,  // any name; whether it is a valid identifier is checked where it is bound
  Let,         // the keyword `let`
  Plus, Minus, Star, Slash, Caret,
  LeftParen, RightParen, Comma, Dot, Semicolon, Equals,
  End,
};

struct Token {
  TokenKind kind = TokenKind::End;
  SourceLocation where;
  std::string text;  // the characters of the token as written
  mpq_class number;  // the exact value of a Number token (0.1 is 1/10)
};

// How a token kind is named in "expected ..." messages, e.g. "')'".
std::string describe(TokenKind kind);

// Tokenizes `source`; the result always ends with an End token. Whitespace
// and `//` comments (to the end of the line) separate tokens. Throws Error on
// a character the language does not use or a malformed number.
std::vector<Token> tokenize(std::string_view source);

}  // namespace sdfwb::expr
