#include "expr/graph.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace sdfwb::expr {
namespace {

constexpr std::array<OpInfo, 20> kOps = {{
    {"constant", 0}, {"variable", 0}, {"neg", 1}, {"add", 2}, {"sub", 2}, {"mul", 2}, {"div", 2},
    {"sin", 1}, {"cos", 1}, {"tan", 1}, {"exp", 1}, {"log", 1}, {"sqrt", 1}, {"abs", 1}, {"floor", 1},
    {"min", 2}, {"max", 2}, {"pow", 2}, {"select_less", 4}, {"select_equal", 4},
}};
static_assert(kOps.size() == static_cast<std::size_t>(Op::SelectEqual) + 1, "one OpInfo per Op");

std::size_t bitsOf(const mpq_class& q) {
  return mpz_sizeinbase(q.get_num_mpz_t(), 2) + mpz_sizeinbase(q.get_den_mpz_t(), 2);
}

mpq_class floorOf(const mpq_class& q) {
  mpz_class f;
  mpz_fdiv_q(f.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return mpq_class(f);
}

bool isPerfectSquare(const mpq_class& q) {
  return sgn(q) >= 0 && mpz_perfect_square_p(q.get_num_mpz_t()) && mpz_perfect_square_p(q.get_den_mpz_t());
}

mpq_class exactSqrt(const mpq_class& q) {
  mpz_class n, d;
  mpz_sqrt(n.get_mpz_t(), q.get_num_mpz_t());
  mpz_sqrt(d.get_mpz_t(), q.get_den_mpz_t());
  return mpq_class(n, d);
}

}  // namespace

const OpInfo& opInfo(Op op) { return kOps[static_cast<std::size_t>(op)]; }

const mpq_class& tinyPositive() {
  static const mpq_class tiny = [] {
    mpz_class den;
    mpz_ui_pow_ui(den.get_mpz_t(), 2, 126);
    return mpq_class(mpz_class(1), den);
  }();
  return tiny;
}

double nearestDouble(const mpq_class& q) {
  if (sgn(q) == 0) return 0.0;
  const mpz_class n = abs(q.get_num());
  const mpz_class& d = q.get_den();
  // With k = 54 - (bits(n) - bits(d)), m = floor(n * 2^k / d) has 54 or 55
  // bits: keep 53, round to nearest even on the dropped bits and the remainder.
  const long k = 54 - static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) +
                 static_cast<long>(mpz_sizeinbase(d.get_mpz_t(), 2));
  mpz_class scaledN = n, scaledD = d;
  if (k >= 0) {
    scaledN <<= static_cast<mp_bitcnt_t>(k);
  } else {
    scaledD <<= static_cast<mp_bitcnt_t>(-k);
  }
  mpz_class m, r;
  mpz_fdiv_qr(m.get_mpz_t(), r.get_mpz_t(), scaledN.get_mpz_t(), scaledD.get_mpz_t());
  const long drop = static_cast<long>(mpz_sizeinbase(m.get_mpz_t(), 2)) - 53;
  mpz_class mantissa = m >> static_cast<mp_bitcnt_t>(drop);
  const mpz_class dropped = m - (mantissa << static_cast<mp_bitcnt_t>(drop));
  const mpz_class half = mpz_class(1) << static_cast<mp_bitcnt_t>(drop - 1);
  const bool sticky = sgn(r) != 0;
  if (dropped > half || (dropped == half && (sticky || mpz_odd_p(mantissa.get_mpz_t())))) ++mantissa;
  const double magnitude = std::ldexp(mantissa.get_d(), static_cast<int>(drop - k));
  return sgn(q) < 0 ? -magnitude : magnitude;
}

std::vector<NodeId> dependencies(const Graph& graph, NodeId root, const std::function<bool(NodeId)>& isLeaf) {
  std::vector<bool> seen(root + 1, false);
  std::vector<NodeId> stack{root};
  seen[root] = true;
  std::vector<NodeId> order;
  while (!stack.empty()) {
    const NodeId id = stack.back();
    stack.pop_back();
    order.push_back(id);
    if (isLeaf && isLeaf(id)) continue;
    const Node& n = graph.node(id);
    for (int i = 0; i < opInfo(n.op).arity; ++i) {
      if (!seen[n.args[i]]) {
        seen[n.args[i]] = true;
        stack.push_back(n.args[i]);
      }
    }
  }
  std::sort(order.begin(), order.end());
  return order;
}

std::size_t Graph::KeyHash::operator()(const Key& k) const {
  std::size_t h = static_cast<std::size_t>(k.op) * 0x9E3779B97F4A7C15ull ^ k.index;
  for (NodeId a : k.args) h = (h ^ a) * 0x100000001B3ull + (h >> 29);
  return h;
}

std::uint32_t Graph::declareVariable(std::string name) {
  variables_.push_back(std::move(name));
  return static_cast<std::uint32_t>(variables_.size() - 1);
}

NodeId Graph::make(Op op, std::array<NodeId, 4> args, std::uint32_t index) {
  const Key key{op, args, index};
  if (auto it = nodeIndex_.find(key); it != nodeIndex_.end()) return it->second;
  const auto id = static_cast<NodeId>(nodes_.size());
  nodes_.push_back(Node{op, args, index});
  origins_.push_back(origin_);
  nodeIndex_.emplace(key, id);
  return id;
}

NodeId Graph::constant(const mpq_class& value) {
  auto it = constantIndex_.find(value);
  if (it == constantIndex_.end()) {
    it = constantIndex_.emplace(value, static_cast<std::uint32_t>(constants_.size())).first;
    constants_.push_back(value);
    constantValues_.push_back(nearestDouble(value));
  }
  return make(Op::Constant, {}, it->second);
}

NodeId Graph::variable(std::uint32_t index) { return make(Op::Variable, {}, index); }

NodeId Graph::neg(NodeId a) {
  if (isConstant(a)) return constant(-exactValue(a));
  if (isNegative(a)) return operand(a);
  return make(Op::Neg, {a});
}

void Graph::checkFoldable(NodeId a, NodeId b) const {
  const std::size_t bits = bitsOf(exactValue(a)) + bitsOf(exactValue(b));
  if (bits <= kMaxConstantBits) return;
  constexpr double kDigitsPerBit = 0.30103;  // log10(2)
  throw Error(origin_.where, "the number is too large to compute exactly (about " +
                                 std::to_string(static_cast<std::uint64_t>(static_cast<double>(bits) * kDigitsPerBit)) +
                                 " digits; at most " +
                                 std::to_string(static_cast<std::uint64_t>(kMaxConstantBits * kDigitsPerBit)) + ")");
}

// The rewrites below are exact in IEEE arithmetic (a + -b == a - b,
// -a * b == -(a * b)), apart from the sign of zero and from x*0 = 0 for an
// infinite x, which symbolic differentiation relies on.
NodeId Graph::add(NodeId a, NodeId b) {
  if (isConstant(a) && isConstant(b)) {
    checkFoldable(a, b);
    return constant(exactValue(a) + exactValue(b));
  }
  if (isConstant(a, 0)) return b;
  if (isConstant(b, 0)) return a;
  if (isNegative(b)) return sub(a, operand(b));
  if (isNegative(a)) return sub(b, operand(a));
  return make(Op::Add, {a, b});
}

NodeId Graph::sub(NodeId a, NodeId b) {
  if (isConstant(a) && isConstant(b)) {
    checkFoldable(a, b);
    return constant(exactValue(a) - exactValue(b));
  }
  if (isConstant(b, 0)) return a;
  if (isConstant(a, 0)) return neg(b);
  if (isNegative(b)) return add(a, operand(b));
  return make(Op::Sub, {a, b});
}

NodeId Graph::mul(NodeId a, NodeId b) {
  if (isConstant(a) && isConstant(b)) {
    checkFoldable(a, b);
    return constant(exactValue(a) * exactValue(b));
  }
  if (isConstant(a, 0) || isConstant(b, 0)) return constant(0);
  if (isConstant(a, 1)) return b;
  if (isConstant(b, 1)) return a;
  if (isConstant(a, -1)) return neg(b);
  if (isConstant(b, -1)) return neg(a);
  if (isNegative(a)) return neg(mul(operand(a), b));
  if (isNegative(b)) return neg(mul(a, operand(b)));
  return make(Op::Mul, {a, b});
}

NodeId Graph::div(NodeId a, NodeId b) {
  if (isConstant(a) && isConstant(b) && !isConstant(b, 0)) {
    checkFoldable(a, b);
    return constant(exactValue(a) / exactValue(b));
  }
  if (isConstant(b, 1)) return a;
  if (isConstant(b, -1)) return neg(a);
  if (isConstant(a, 0) && !isConstant(b, 0)) return a;
  if (isNegative(a)) return neg(div(operand(a), b));
  if (isNegative(b)) return neg(div(a, operand(b)));
  return make(Op::Div, {a, b});
}

NodeId Graph::unary(Op op, NodeId a) {
  if (isConstant(a)) {
    const mpq_class& v = exactValue(a);
    switch (op) {
      case Op::Abs: return constant(abs(v));
      case Op::Floor: return constant(floorOf(v));
      case Op::Sin:
      case Op::Tan:
        if (v == 0) return a;
        break;
      case Op::Cos:
      case Op::Exp:
        if (v == 0) return constant(1);
        break;
      case Op::Log:
        if (v == 1) return constant(0);
        break;
      case Op::Sqrt:
        if (isPerfectSquare(v)) return constant(exactSqrt(v));
        break;
      default: break;
    }
  }
  if (op == Op::Abs && isNegative(a)) return unary(Op::Abs, operand(a));
  if (op == Op::Abs && nodes_[a].op == Op::Abs) return a;
  return make(op, {a});
}

NodeId Graph::min(NodeId a, NodeId b) {
  if (isConstant(a) && isConstant(b)) return exactValue(b) < exactValue(a) ? b : a;
  if (a == b) return a;
  if (nodes_[a].op == Op::Min && nodes_[a].args[1] == b) return a;
  return make(Op::Min, {a, b});
}

NodeId Graph::max(NodeId a, NodeId b) {
  if (isConstant(a) && isConstant(b)) return exactValue(a) < exactValue(b) ? b : a;
  if (a == b) return a;
  if (nodes_[a].op == Op::Max && nodes_[a].args[1] == b) return a;
  return make(Op::Max, {a, b});
}

NodeId Graph::selectLess(NodeId a, NodeId b, NodeId ifLess, NodeId otherwise) {
  if (isConstant(a) && isConstant(b)) return exactValue(a) < exactValue(b) ? ifLess : otherwise;
  if (ifLess == otherwise) return ifLess;
  return make(Op::SelectLess, {a, b, ifLess, otherwise});
}

NodeId Graph::selectEqual(NodeId a, NodeId b, NodeId ifEqual, NodeId otherwise) {
  if (isConstant(a) && isConstant(b)) return exactValue(a) == exactValue(b) ? ifEqual : otherwise;
  if (ifEqual == otherwise) return ifEqual;
  return make(Op::SelectEqual, {a, b, ifEqual, otherwise});
}

NodeId Graph::powInteger(NodeId a, long n) {
  if (n == 0) return constant(1);
  if (n < 0) return div(constant(1), powInteger(a, -n));
  const unsigned long u = static_cast<unsigned long>(n);
  int top = 63;
  while (((u >> top) & 1ul) == 0) --top;
  NodeId result = a;
  for (int bit = top - 1; bit >= 0; --bit) {
    result = mul(result, result);
    if ((u >> bit) & 1ul) result = mul(result, a);
  }
  return result;
}

NodeId Graph::sqrtGuarded(NodeId a) { return unary(Op::Sqrt, max(a, constant(0))); }

NodeId Graph::logGuarded(NodeId a) { return unary(Op::Log, max(a, constant(tinyPositive()))); }

NodeId Graph::powGuarded(NodeId a, NodeId b) {
  if (isConstant(b, 0)) return constant(1);
  return make(Op::Pow, {max(a, constant(tinyPositive())), b});
}

NodeId Graph::modGuarded(NodeId a, NodeId b) {
  const NodeId r = sub(a, mul(b, unary(Op::Floor, div(a, b))));
  return selectEqual(b, constant(0), a, r);
}

}  // namespace sdfwb::expr
