#include "expr/to_algebra.h"

#include <algorithm>
#include <stdexcept>

#include "expr/formula.h"
#include "expr/graph_to_fractions.h"

namespace sdfwb::expr {
namespace {

GraphToFractions::Options byName(const Graph& graph, const algebra::RingPtr& ring) {
  GraphToFractions::Options options;
  for (const std::string& name : graph.variables()) {
    const auto index = ring->indexOf(name);
    options.variables.push_back(index ? std::optional(ring->var(*index)) : std::nullopt);
  }
  options.unmappedVariable = [](const std::string& name) -> std::string {
    throw std::invalid_argument("variable '" + name + "' is not in the ring");
  };
  return options;
}

}  // namespace

RationalFunction toRationalFunction(const Graph& graph, NodeId node, const algebra::RingPtr& ring) {
  FractionArithmetic arithmetic(ring);
  GraphToFractions converter(graph, arithmetic, byName(graph, ring));
  auto [numerator, denominator] = converter.convertToQuotient(node, graph.origin(node).where);
  return {std::move(numerator), std::move(denominator)};
}

algebra::Polynomial toPolynomial(const Graph& graph, NodeId node, const algebra::RingPtr& ring) {
  FractionArithmetic arithmetic(ring);
  GraphToFractions converter(graph, arithmetic, byName(graph, ring));
  // the denominator left is never expanded: it is 1 or the formula is no polynomial
  Fraction value = converter.convert(node, graph.origin(node).where);
  if (std::any_of(value.powers.begin(), value.powers.end(), [](unsigned power) { return power > 0; })) {
    const auto& division = converter.firstNonConstantDivision();
    throw Error(division ? division->where : graph.origin(node).where,
                "division by a non-constant expression: the formula is not a polynomial");
  }
  return std::move(value.numerator);
}

std::vector<algebra::Polynomial> parsePolynomials(std::string_view source, const algebra::RingPtr& ring) {
  const ExpressionList list = compileExpressionList(source, ring->variables());
  std::vector<algebra::Polynomial> result;
  for (const NodeId value : list.values) result.push_back(toPolynomial(list.graph, value, ring));
  return result;
}

}  // namespace sdfwb::expr
