#pragma once
// Parses formula text into a syntax tree.
//
// Grammar (whitespace and `//` comments are free):
//   program    := [statement] { ';' [statement] }
//   statement  := 'let' name '=' expr  |  expr [ '=' expr ]
//   expr       := term { ('+' | '-') term }
//   term       := unary { ('*' | '/') unary }
//   unary      := ('-' | '+') unary  |  power
//   power      := postfix [ '^' unary ]          (right associative: 2^3^2 = 2^9)
//   postfix    := primary { '.' name }           (components and swizzles: p.x, p.xz)
//   primary    := number | name | name '(' [expr { ',' expr }] ')' | '(' expr ')'
// '^' binds tighter than unary minus: -x^2 is -(x^2), and x^-2 is x^(-2).
// Which statements a formula may hold (one final expression, equations, ...)
// is checked by the compiler (formula.h), not here.

#include <string_view>

#include "expr/ast.h"

namespace sdfwb::expr {

// Throws Error, e.g. "column 7: expected ')' after function arguments".
Program parse(std::string_view source);

}  // namespace sdfwb::expr
