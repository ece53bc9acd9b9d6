#pragma once
// Walks a graph and builds exact rational functions: the shared core of the
// conversions to algebra (to_algebra.h and trig.h).

#include <functional>
#include <optional>
#include <string>

#include "expr/fractions.h"
#include "expr/graph.h"

namespace sdfwb::expr {

class GraphToFractions {
 public:
  struct Options {
    // The polynomial for each graph variable; std::nullopt for a variable
    // that may not occur outside leaves.
    std::vector<std::optional<algebra::Polynomial>> variables;
    // Why an unmapped variable cannot be used, given its name.
    std::function<std::string(const std::string& name)> unmappedVariable;
    // Nodes converted by `leaf` instead of by the rules (their operands are
    // not visited), e.g. sin and cos of a parametrization.
    std::function<bool(NodeId)> isLeaf;
    std::function<Fraction(NodeId)> leaf;
  };

  GraphToFractions(const Graph& graph, FractionArithmetic& arithmetic, Options options);

  // The exact value of `root`, cancelled (FractionArithmetic::cancel). Throws
  // Error at the origin of the first operation that is not + - * / (integer
  // powers were already expanded), e.g. "column 5: 'sqrt' is not a
  // polynomial or rational function", or whose product would be too large
  // to expand. `rootWhere` locates the error when root itself is an unmapped
  // variable.
  Fraction convert(NodeId root, SourceLocation rootWhere);
  // The same as {numerator, denominator}; a denominator too large to expand
  // is an Error at `rootWhere` (graph nodes are shared, so root's own origin
  // may be an earlier equal expression's).
  std::pair<algebra::Polynomial, algebra::Polynomial> convertToQuotient(NodeId root, SourceLocation rootWhere);

  // Where the first division by a non-constant happened, if any.
  const std::optional<Origin>& firstNonConstantDivision() const { return firstNonConstantDivision_; }

 private:
  const Graph& graph_;
  FractionArithmetic& arithmetic_;
  Options options_;
  std::optional<Origin> firstNonConstantDivision_;
};

}  // namespace sdfwb::expr
