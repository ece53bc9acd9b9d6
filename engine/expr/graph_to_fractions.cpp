#include "expr/graph_to_fractions.h"

namespace sdfwb::expr {
namespace {

std::string notRational(const Origin& origin) {
  if (origin.construct == "^") return "a non-integer exponent is not a polynomial or rational function";
  return "'" + std::string(origin.construct) + "' is not a polynomial or rational function";
}

// Runs a step on the whole converted formula (cancelling its factors,
// expanding it): products that count against the budget as the conversion's
// own do, so running past it is reported at the formula's location.
template <class Step>
auto atRoot(SourceLocation rootWhere, Step step) {
  try {
    return step();
  } catch (const TooLargeToExpand& error) {
    throw Error(rootWhere, error.what());
  }
}

}  // namespace

GraphToFractions::GraphToFractions(const Graph& graph, FractionArithmetic& arithmetic, Options options)
    : graph_(graph), arithmetic_(arithmetic), options_(std::move(options)) {}

Fraction GraphToFractions::convert(NodeId root, SourceLocation rootWhere) {
  // Unmapped variables are empty entries; the first node that uses one reports it.
  std::vector<std::optional<Fraction>> values(root + 1);
  auto operand = [&](NodeId user, NodeId id) -> const Fraction& {
    if (!values[id]) {
      const std::string& name = graph_.variables()[graph_.node(id).index];
      throw Error(graph_.origin(user).where, options_.unmappedVariable(name));
    }
    return *values[id];
  };
  for (const NodeId id : dependencies(graph_, root, options_.isLeaf)) try {
    if (options_.isLeaf && options_.isLeaf(id)) {
      values[id] = options_.leaf(id);
      continue;
    }
    const Node& n = graph_.node(id);
    switch (n.op) {
      case Op::Constant: values[id] = arithmetic_.constant(graph_.exactValue(id)); break;
      case Op::Variable:
        if (n.index < options_.variables.size() && options_.variables[n.index]) {
          values[id] = arithmetic_.polynomial(*options_.variables[n.index]);
        }
        break;
      case Op::Neg: values[id] = arithmetic_.negate(operand(id, n.args[0])); break;
      case Op::Add: values[id] = arithmetic_.add(operand(id, n.args[0]), operand(id, n.args[1])); break;
      case Op::Sub: values[id] = arithmetic_.subtract(operand(id, n.args[0]), operand(id, n.args[1])); break;
      case Op::Mul: values[id] = arithmetic_.multiply(operand(id, n.args[0]), operand(id, n.args[1])); break;
      case Op::Div: {
        const Fraction& divisor = operand(id, n.args[1]);
        auto q = arithmetic_.divide(operand(id, n.args[0]), divisor);
        if (!q) throw Error(graph_.origin(id).where, "division by an expression that is identically 0");
        if (!firstNonConstantDivision_ && !divisor.numerator.isConstant()) {
          firstNonConstantDivision_ = graph_.origin(id);
        }
        values[id] = std::move(*q);
        break;
      }
      default: throw Error(graph_.origin(id).where, notRational(graph_.origin(id)));
    }
  } catch (const TooLargeToExpand& error) {
    throw Error(graph_.origin(id).where, error.what());
  }
  if (!values[root]) {
    const std::string& name = graph_.variables()[graph_.node(root).index];
    throw Error(rootWhere, options_.unmappedVariable(name));
  }
  return atRoot(rootWhere, [&] { return arithmetic_.cancel(*values[root]); });
}

std::pair<algebra::Polynomial, algebra::Polynomial> GraphToFractions::convertToQuotient(NodeId root,
                                                                                       SourceLocation rootWhere) {
  const Fraction value = convert(root, rootWhere);
  return atRoot(rootWhere, [&] { return arithmetic_.expand(value); });
}

}  // namespace sdfwb::expr
