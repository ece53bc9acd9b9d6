#pragma once
// Compiling user text into typed graphs: the entry points of the language.
//
// Statements are separated by ';'. `let name = value` binds a scalar or vector
// for the statements after it (names follow the identifier rule, identifier.h,
// and cannot be rebound). For example
//   let q = abs(p) - vec3(1, 1, 1); length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0)
// Every function throws Error with the column of the problem.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "expr/graph.h"

namespace sdfwb::expr {

// A scalar formula over space. Variables 0, 1, 2 of the graph are x, y, z;
// the formula may use them and p = vec3(x, y, z). Any other free name is an error.
struct SpaceFormula {
  Graph graph;
  NodeId value = 0;
};

// A signed distance: `let` statements, then one scalar expression.
SpaceFormula compileSdf(std::string_view source);

// An implicit surface F = 0, inside where F < 0: like compileSdf, and the last
// statement may also be an equation `lhs = rhs`, meaning F = lhs - rhs.
SpaceFormula compileImplicit(std::string_view source);

// One equation `coordinate = value` of a parametrization.
struct CoordinateEquation {
  std::string coordinate;  // "x", "y" or "z"
  NodeId value = 0;
  SourceLocation where;    // of the equation
};

// Parametric equations such as "x = u*v; y = v; z = u^2", with `let`
// statements allowed between them. Each coordinate is given at most once;
// equations are returned in the order x, y, z. The right-hand sides use
// parameters: any identifier other than x, y, z, declared as graph variables
// in order of first appearance.
// Variables of an expression list and parameters of a parametrization, at
// most: every exact monomial stores one exponent per variable.
inline constexpr std::size_t kMaxVariables = 256;

struct ParametricEquations {
  Graph graph;
  std::vector<CoordinateEquation> equations;
};
ParametricEquations compileParametricEquations(std::string_view source);

// Scalar expressions "f1; f2; ..." over the given variables (graph variables
// 0, 1, ... in that order), for example polynomials for a Groebner basis.
// `let` statements may come between them; any other free name is an error.
// Throws std::invalid_argument if a variable name breaks the identifier rule
// or is repeated (a caller's error, reported with identifierProblem's phrase).
struct ExpressionList {
  Graph graph;
  std::vector<NodeId> values;
  std::vector<SourceLocation> where;  // of each expression
};
ExpressionList compileExpressionList(std::string_view source, std::span<const std::string> variables);

}  // namespace sdfwb::expr
