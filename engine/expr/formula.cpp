#include "expr/formula.h"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "expr/identifier.h"
#include "expr/lower.h"
#include "expr/parser.h"

namespace sdfwb::expr {
namespace {

Value requireScalar(const Value& value, SourceLocation where, std::string_view what) {
  if (value.type != Type::Scalar) {
    throw Error(where, std::string(what) + " must be a scalar, got " + std::string(typeName(value.type)));
  }
  return value;
}

Lowerer::FreeNameResolver rejectFreeNames(std::string_view known) {
  return [known = std::string(known)](const std::string& name, SourceLocation where) -> Value {
    throw Error(where, "unknown name '" + name + "' (" + known + ")");
  };
}

// `let` statements, then the value: an expression, or an equation when allowed.
SpaceFormula compileOverSpace(std::string_view source, bool allowEquation) {
  const Program program = parse(source);
  SpaceFormula formula;
  Graph& g = formula.graph;
  Lowerer lowerer(g, rejectFreeNames("a formula over space uses p, x, y, z and its let names"));
  Value coordinates{Type::Vec3, {}};
  const char* names[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    coordinates.components[i] = g.variable(g.declareVariable(names[i]));
    lowerer.bind(names[i], Value::scalar(coordinates.components[i]));
  }
  lowerer.bind("p", coordinates);

  const auto& statements = program.statements;
  if (statements.empty() || statements.back().kind == Statement::Kind::Let) {
    throw Error(program.end, statements.empty() ? "expected an expression" : "expected an expression after the let bindings");
  }
  for (std::size_t i = 0; i + 1 < statements.size(); ++i) {
    if (statements[i].kind != Statement::Kind::Let) {
      throw Error(statements[i].where, "only the last statement gives the formula's value: bind this one with 'let'");
    }
    lowerer.let(statements[i]);
  }
  const Statement& last = statements.back();
  if (last.kind == Statement::Kind::Equation) {
    if (!allowEquation) throw Error(last.where, "a distance formula cannot be an equation");
    const Value lhs = requireScalar(lowerer.lower(*last.value), last.where, "the left-hand side");
    const Value rhs = requireScalar(lowerer.lower(*last.rhs), last.rhsWhere, "the right-hand side");
    g.setOrigin({last.where, "="});
    formula.value = g.sub(lhs[0], rhs[0]);
  } else {
    formula.value = requireScalar(lowerer.lower(*last.value), last.where, "the formula")[0];
  }
  return formula;
}

}  // namespace

SpaceFormula compileSdf(std::string_view source) { return compileOverSpace(source, false); }

SpaceFormula compileImplicit(std::string_view source) { return compileOverSpace(source, true); }

ParametricEquations compileParametricEquations(std::string_view source) {
  const Program program = parse(source);
  ParametricEquations result;
  Graph& g = result.graph;
  Lowerer lowerer(g, [&g](const std::string& name, SourceLocation where) {
    if (isCoordinate(name)) {
      throw Error(where, "'" + name + "' is a coordinate: the right-hand sides may use only parameters");
    }
    if (g.variables().size() >= kMaxVariables) {
      throw Error(where, "more than " + std::to_string(kMaxVariables) + " parameters");
    }
    return Value::scalar(g.variable(g.declareVariable(name)));
  });
  for (const Statement& s : program.statements) {
    if (s.kind == Statement::Kind::Let) {
      if (isCoordinate(s.name)) throw Error(s.nameWhere, "'" + s.name + "' is a coordinate and cannot be bound with let");
      lowerer.let(s);
      continue;
    }
    if (s.kind == Statement::Kind::Expression) {
      throw Error(s.where, "expected an equation such as 'x = u*v'");
    }
    if (s.value->kind != Expr::Kind::Name || !isCoordinate(s.value->name)) {
      throw Error(s.where, "the left-hand side of an equation must be x, y or z");
    }
    const std::string& coordinate = s.value->name;
    for (const CoordinateEquation& e : result.equations) {
      if (e.coordinate == coordinate) throw Error(s.where, "'" + coordinate + "' is given twice");
    }
    const Value value = requireScalar(lowerer.lower(*s.rhs), s.rhsWhere, "the right-hand side");
    result.equations.push_back({coordinate, value[0], s.where});
  }
  if (result.equations.empty()) throw Error(program.end, "expected equations such as 'x = u*v; y = v; z = u^2'");
  std::sort(result.equations.begin(), result.equations.end(),
            [](const CoordinateEquation& a, const CoordinateEquation& b) { return a.coordinate < b.coordinate; });
  return result;
}

ExpressionList compileExpressionList(std::string_view source, std::span<const std::string> variables) {
  ExpressionList result;
  Graph& g = result.graph;
  Lowerer lowerer(g, rejectFreeNames("the variables are the ones listed"));
  if (variables.size() > kMaxVariables) {
    throw std::invalid_argument(std::to_string(variables.size()) + " variables (at most " +
                                std::to_string(kMaxVariables) + ")");
  }
  std::set<std::string> seen;
  for (const std::string& name : variables) {
    if (const std::string problem = identifierProblem(name); !problem.empty()) {
      throw std::invalid_argument("variable " + problem);
    }
    if (!seen.insert(name).second) throw std::invalid_argument("variable '" + name + "' is listed twice");
    lowerer.bind(name, Value::scalar(g.variable(g.declareVariable(name))));
  }
  const Program program = parse(source);
  for (const Statement& s : program.statements) {
    if (s.kind == Statement::Kind::Let) {
      lowerer.let(s);
    } else if (s.kind == Statement::Kind::Equation) {
      throw Error(s.where, "expected an expression, not an equation");
    } else {
      result.values.push_back(requireScalar(lowerer.lower(*s.value), s.where, "each expression")[0]);
      result.where.push_back(s.where);
    }
  }
  if (result.values.empty()) throw Error(program.end, "expected an expression");
  return result;
}

}  // namespace sdfwb::expr
