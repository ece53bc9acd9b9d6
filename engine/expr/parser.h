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

#include <cstddef>
#include <string_view>

#include "expr/ast.h"

namespace sdfwb::expr {

// Limits that keep every later stage (typing, derivatives, code generation)
// bounded: they all walk the syntax tree recursively.
inline constexpr std::size_t kMaxFormulaLength = std::size_t(1) << 20;  // characters
// Nesting of the syntax tree: parentheses, unary signs, and each operator of a
// chain (a + b + c nests two deep), so it also bounds sums of many terms.
inline constexpr int kMaxExpressionDepth = 2000;

// Throws Error, e.g. "column 7: expected ')' after function arguments", also
// for a source longer than kMaxFormulaLength or nested deeper than
// kMaxExpressionDepth.
Program parse(std::string_view source);

}  // namespace sdfwb::expr
