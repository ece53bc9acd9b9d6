#pragma once
// Typing: turns syntax trees into typed values on a graph, checking types and
// names and reporting each error at its column.

#include <functional>
#include <map>
#include <string>

#include "expr/ast.h"
#include "expr/value.h"

namespace sdfwb::expr {

class Lowerer {
 public:
  // Called for a name that is neither bound nor a built-in: returns its value
  // (declaring a parameter, say) or throws Error.
  using FreeNameResolver = std::function<Value(const std::string& name, SourceLocation where)>;

  Lowerer(Graph& graph, FreeNameResolver resolveFreeName);

  // Binds a name (p, x, y, z, a parameter, a let) for the rest of the formula;
  // throws Error at `where` if it is not an identifier or is already bound.
  void bind(const std::string& name, Value value, SourceLocation where = {});
  bool isBound(const std::string& name) const { return scope_.count(name) != 0; }

  Value lower(const Expr& expr);
  // Lowers a `let` statement and binds its name.
  void let(const Statement& statement);

 private:
  void checkBindable(const std::string& name, SourceLocation where) const;
  Value lowerName(const Expr& expr);
  Value lowerCall(const Expr& expr);
  Value lowerBinary(const Expr& expr);
  Value lowerComponent(const Expr& expr);

  Graph& graph_;
  FreeNameResolver resolveFreeName_;
  std::map<std::string, Value, std::less<>> scope_;
};

}  // namespace sdfwb::expr
