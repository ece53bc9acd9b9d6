#pragma once
// The syntax tree of a formula, as parsed (untyped).

#include <gmpxx.h>

#include <memory>
#include <string>
#include <vector>

#include "expr/error.h"

namespace sdfwb::expr {

struct Expr {
  enum class Kind {
    Number,     // number
    Name,       // name
    Call,       // name(operands...)
    Negate,     // -operands[0]
    Binary,     // operands[0] op operands[1], op one of + - * / ^
    Component,  // operands[0].name, name a swizzle such as x or xz
  };

  Kind kind = Kind::Number;
  SourceLocation where;  // of the token that names the node: the operator, the name, the '.'
  std::string name;      // Name, Call, Component
  char op = 0;           // Binary
  mpq_class number;      // Number
  std::vector<std::unique_ptr<Expr>> operands;
  std::vector<SourceLocation> operandLocations;  // Call: where each argument starts
};

struct Statement {
  enum class Kind {
    Let,         // let name = value
    Expression,  // value
    Equation,    // value = rhs
  };

  Kind kind = Kind::Expression;
  SourceLocation where;  // start of the statement
  std::string name;      // Let
  SourceLocation nameWhere;
  std::unique_ptr<Expr> value;
  std::unique_ptr<Expr> rhs;  // Equation
  SourceLocation rhsWhere;
};

// Statements separated by ';'.
struct Program {
  std::vector<Statement> statements;
  SourceLocation end;  // where the text ends, for "expected ..." at the end
};

}  // namespace sdfwb::expr
