#include "expr/derivative.h"

#include <vector>

namespace sdfwb::expr {

NodeId derivative(Graph& g, NodeId root, std::uint32_t variable) {
  std::vector<NodeId> d(root + 1, 0);
  const Origin saved = g.currentOrigin();
  for (const NodeId id : dependencies(g, root)) {
    const Node n = g.node(id);  // a copy: building nodes may reallocate
    const NodeId a = n.args[0], b = n.args[1];
    const NodeId da = d[a], db = d[b];
    const NodeId zero = g.constant(0);
    g.setOrigin(g.origin(id));
    NodeId r = zero;
    switch (n.op) {
      case Op::Constant: r = zero; break;
      case Op::Variable: r = g.constant(n.index == variable ? 1 : 0); break;
      case Op::Neg: r = g.neg(da); break;
      case Op::Add: r = g.add(da, db); break;
      case Op::Sub: r = g.sub(da, db); break;
      case Op::Mul: r = g.add(g.mul(da, b), g.mul(a, db)); break;
      // (a/b)' = (a' - (a/b) b') / b, reusing the quotient.
      case Op::Div: r = g.div(g.sub(da, g.mul(id, db)), b); break;
      case Op::Sin: r = g.mul(g.unary(Op::Cos, a), da); break;
      case Op::Cos: r = g.neg(g.mul(g.unary(Op::Sin, a), da)); break;
      case Op::Tan: r = g.mul(g.add(g.constant(1), g.mul(id, id)), da); break;
      case Op::Exp: r = g.mul(id, da); break;
      case Op::Log: r = g.div(da, a); break;
      case Op::Sqrt:
        if (da != zero) r = g.div(da, g.mul(g.constant(2), g.max(id, g.constant(tinyPositive()))));
        break;
      case Op::Abs: r = g.selectLess(a, zero, g.neg(da), da); break;
      case Op::Floor: r = zero; break;
      case Op::Min: r = g.selectLess(b, a, db, da); break;
      case Op::Max: r = g.selectLess(a, b, db, da); break;
      case Op::Pow: {
        NodeId rate = g.div(g.mul(b, da), a);
        if (db != zero) rate = g.add(rate, g.mul(g.logGuarded(a), db));
        r = g.mul(id, rate);
        break;
      }
      case Op::SelectLess: r = g.selectLess(a, b, d[n.args[2]], d[n.args[3]]); break;
      case Op::SelectEqual: r = g.selectEqual(a, b, d[n.args[2]], d[n.args[3]]); break;
    }
    d[id] = r;
  }
  g.setOrigin(saved);
  return d[root];
}

std::array<NodeId, 3> gradient(Graph& g, NodeId node) {
  return {derivative(g, node, 0), derivative(g, node, 1), derivative(g, node, 2)};
}

}  // namespace sdfwb::expr
