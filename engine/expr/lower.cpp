#include "expr/lower.h"

#include "expr/builtins.h"
#include "expr/identifier.h"

namespace sdfwb::expr {
namespace {

std::string_view operatorVerb(char op) {
  switch (op) {
    case '+': return "add";
    case '-': return "subtract";
    case '*': return "multiply";
    default: return "divide";
  }
}

// Static storage for Origin::construct.
std::string_view operatorName(char op) {
  switch (op) {
    case '+': return "+";
    case '-': return "-";
    case '*': return "*";
    case '/': return "/";
    default: return "^";
  }
}

}  // namespace

Lowerer::Lowerer(Graph& graph, FreeNameResolver resolveFreeName)
    : graph_(graph), resolveFreeName_(std::move(resolveFreeName)) {}

void Lowerer::checkBindable(const std::string& name, SourceLocation where) const {
  if (const std::string problem = identifierProblem(name); !problem.empty()) throw Error(where, problem);
  if (isBound(name)) throw Error(where, "'" + name + "' is already defined");
}

void Lowerer::bind(const std::string& name, Value value, SourceLocation where) {
  checkBindable(name, where);
  scope_.emplace(name, value);
}

void Lowerer::let(const Statement& statement) {
  // The name is checked first: an error in it is the one the user should see.
  checkBindable(statement.name, statement.nameWhere);
  scope_.emplace(statement.name, lower(*statement.value));
}

Value Lowerer::lower(const Expr& expr) {
  switch (expr.kind) {
    case Expr::Kind::Number:
      return Value::scalar(graph_.constant(expr.number));
    case Expr::Kind::Name:
      return lowerName(expr);
    case Expr::Kind::Call:
      return lowerCall(expr);
    case Expr::Kind::Negate: {
      const Value operand = lower(*expr.operands[0]);
      graph_.setOrigin({expr.where, "-"});
      Value out = operand;
      for (int i = 0; i < out.size(); ++i) out.components[i] = graph_.neg(operand[i]);
      return operand.type == Type::Scalar ? Value::scalar(out.components[0]) : out;
    }
    case Expr::Kind::Binary:
      return lowerBinary(expr);
    case Expr::Kind::Component:
      return lowerComponent(expr);
  }
  throw Error(expr.where, "unknown expression");
}

Value Lowerer::lowerName(const Expr& expr) {
  if (auto it = scope_.find(expr.name); it != scope_.end()) return it->second;
  if (findBuiltin(expr.name) != nullptr) {
    throw Error(expr.where, "'" + expr.name + "' is a function: expected '(' after it");
  }
  if (const std::string problem = identifierProblem(expr.name); !problem.empty()) {
    throw Error(expr.where, problem);
  }
  Value value = resolveFreeName_(expr.name, expr.where);
  scope_.emplace(expr.name, value);
  return value;
}

Value Lowerer::lowerCall(const Expr& expr) {
  const Builtin* builtin = findBuiltin(expr.name);
  if (builtin == nullptr) throw Error(expr.where, "unknown function '" + expr.name + "'");
  const int count = static_cast<int>(expr.operands.size());
  if (count < builtin->minArguments || count > builtin->maxArguments) {
    std::string expected = std::to_string(builtin->minArguments);
    if (builtin->maxArguments != builtin->minArguments) {
      expected += " to " + std::to_string(builtin->maxArguments);
    }
    throw Error(expr.where, std::string(builtin->name) + " takes " + expected +
                                (builtin->maxArguments == 1 ? " argument" : " arguments") + ", got " +
                                std::to_string(count) + " (usage: " + std::string(builtin->usage) + ")");
  }
  std::vector<Argument> args;
  for (int i = 0; i < count; ++i) args.push_back({lower(*expr.operands[i]), expr.operandLocations[i]});
  graph_.setOrigin({expr.where, builtin->name});
  return builtin->lower(graph_, expr.where, args);
}

Value Lowerer::lowerBinary(const Expr& expr) {
  const Value lhs = lower(*expr.operands[0]);
  const Value rhs = lower(*expr.operands[1]);
  graph_.setOrigin({expr.where, operatorName(expr.op)});
  if (expr.op == '^') {
    if (rhs.type != Type::Scalar) {
      throw Error(expr.where, "the exponent of '^' must be a scalar, got " + std::string(typeName(rhs.type)));
    }
    Value out = lhs;
    for (int i = 0; i < lhs.size(); ++i) out.components[i] = power(graph_, lhs[i], rhs[0], expr.where);
    return lhs.type == Type::Scalar ? Value::scalar(out.components[0]) : out;
  }
  if (lhs.type != rhs.type && lhs.type != Type::Scalar && rhs.type != Type::Scalar) {
    throw Error(expr.where, "cannot " + std::string(operatorVerb(expr.op)) + " " + std::string(typeName(lhs.type)) +
                                " and " + std::string(typeName(rhs.type)));
  }
  if (expr.op == '/') {
    for (int i = 0; i < rhs.size(); ++i) {
      if (graph_.isConstant(rhs[i], 0)) throw Error(expr.where, "division by zero");
    }
  }
  const Type type = lhs.type == Type::Scalar ? rhs.type : lhs.type;
  Value out{type, {}};
  for (int i = 0; i < out.size(); ++i) {
    switch (expr.op) {
      case '+': out.components[i] = graph_.add(lhs[i], rhs[i]); break;
      case '-': out.components[i] = graph_.sub(lhs[i], rhs[i]); break;
      case '*': out.components[i] = graph_.mul(lhs[i], rhs[i]); break;
      default: out.components[i] = graph_.div(lhs[i], rhs[i]); break;
    }
  }
  return type == Type::Scalar ? Value::scalar(out.components[0]) : out;
}

// Components and swizzles: .x .y .z and combinations such as .xz or .zyx.
Value Lowerer::lowerComponent(const Expr& expr) {
  const Value base = lower(*expr.operands[0]);
  if (base.type == Type::Scalar) throw Error(expr.where, "a scalar has no components");
  if (expr.name.size() > 3) throw Error(expr.where, "'" + expr.name + "' has more than 3 components");
  Value out{vectorType(static_cast<int>(expr.name.size())), {}};
  for (std::size_t i = 0; i < expr.name.size(); ++i) {
    const char c = expr.name[i];
    const int index = c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1;
    if (index < 0) throw Error(expr.where, "'" + expr.name + "' is not a component: use x, y, z");
    if (index >= base.size()) {
      throw Error(expr.where, std::string(typeName(base.type)) + " has no component '" + std::string(1, c) + "'");
    }
    out.components[i] = base[index];
  }
  return out.type == Type::Scalar ? Value::scalar(out.components[0]) : out;
}

}  // namespace sdfwb::expr
