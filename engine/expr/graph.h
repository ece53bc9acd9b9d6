#pragma once
// The typed form of a formula: a graph of scalar operations.
//
// Typing lowers vectors to their components, so everything downstream (CPU
// evaluation, GLSL generation, the symbolic derivative, conversion to exact
// polynomials) handles scalars only and each operation is written once. Nodes
// are hash-consed (a repeated subexpression is one node) and are stored in
// creation order, which is a topological order: operands come before users.
// The builders simplify as they go: constants fold exactly (over the
// rationals), and additions of 0 and multiplications by 0 or 1 disappear, so
// derivatives stay small.

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "expr/error.h"

namespace sdfwb::expr {

using NodeId = std::uint32_t;

// Every operation is exactly the IEEE / GLSL built-in of the same name; where
// GLSL leaves a result undefined, the graph holds an explicit guard instead
// (see Graph::sqrtGuarded and friends), so both backends compute the same thing.
enum class Op : std::uint8_t {
  Constant,     // exact rational constants()[index]
  Variable,     // input number index
  Neg, Add, Sub, Mul, Div,
  Sin, Cos, Tan, Exp, Log, Sqrt, Abs, Floor,
  Min,          // GLSL min(a, b) = b < a ? b : a; a NaN operand gives the other (sdf/shared_instance.inl)
  Max,          // GLSL max(a, b) = a < b ? b : a; likewise
  Pow,
  SelectLess,   // a < b ? c : d
  SelectEqual,  // a == b ? c : d
};

struct OpInfo {
  std::string_view name;  // the GLSL built-in or a word for the operator
  int arity;
};
const OpInfo& opInfo(Op op);

struct Node {
  Op op = Op::Constant;
  std::array<NodeId, 4> args{};  // the first opInfo(op).arity are used
  std::uint32_t index = 0;       // Constant: into constants(); Variable: variable number
};

// Which part of the user's text made a node, for errors found after typing
// (a formula that is not rational names the function that made it so).
struct Origin {
  SourceLocation where;
  std::string_view construct;  // a built-in's name ("sqrt") or an operator ("^", "/"); static storage
};

// The smallest positive normal float, 2^-126. Guards clamp to it so that the
// float and double evaluators and GLSL agree (llvmpipe flushes denormals).
const mpq_class& tinyPositive();

// Constants are folded exactly (GMP rationals). Powers of powers of constants
// grow without bound ((3 - 5^65536)^65535 needs some 10^10 bits: gigabytes and
// minutes), so a folded constant may have at most this many bits in its
// numerator and denominator together, checked before it is computed: about
// 315,000 decimal digits, far beyond any literal (100 digits, exponent 1000)
// and 5^65536 (152,000 bits).
inline constexpr std::size_t kMaxConstantBits = std::size_t(1) << 20;

class Graph {
 public:
  // Inputs, numbered in the order they are declared; names are for messages
  // and code generation only.
  std::uint32_t declareVariable(std::string name);
  const std::vector<std::string>& variables() const { return variables_; }

  std::size_t size() const { return nodes_.size(); }
  const Node& node(NodeId id) const { return nodes_[id]; }
  const Origin& origin(NodeId id) const { return origins_[id]; }
  bool isConstant(NodeId id) const { return nodes_[id].op == Op::Constant; }
  // Requires isConstant(id).
  const mpq_class& exactValue(NodeId id) const { return constants_[nodes_[id].index]; }
  bool isConstant(NodeId id, long value) const { return isConstant(id) && exactValue(id) == value; }

  // Constants in creation order, exact and as correctly rounded doubles.
  const std::vector<mpq_class>& constants() const { return constants_; }
  const std::vector<double>& constantValues() const { return constantValues_; }

  // Nodes built from now on are attributed to `origin`.
  void setOrigin(Origin origin) { origin_ = origin; }
  Origin currentOrigin() const { return origin_; }

  // ---- Builders: hash-consed and simplified.
  NodeId constant(const mpq_class& value);
  NodeId variable(std::uint32_t index);
  NodeId neg(NodeId a);
  NodeId add(NodeId a, NodeId b);
  NodeId sub(NodeId a, NodeId b);
  NodeId mul(NodeId a, NodeId b);
  NodeId div(NodeId a, NodeId b);
  // Sin, Cos, Tan, Exp, Abs, Floor (Log and Sqrt only through the guarded forms).
  NodeId unary(Op op, NodeId a);
  NodeId min(NodeId a, NodeId b);
  NodeId max(NodeId a, NodeId b);
  NodeId selectLess(NodeId a, NodeId b, NodeId ifLess, NodeId otherwise);
  NodeId selectEqual(NodeId a, NodeId b, NodeId ifEqual, NodeId otherwise);

  // a^n for an integer n by multiplications, square and multiply from the
  // most significant bit: x^3 = (x*x)*x, x^4 = (x*x)*(x*x); x^-n = 1/x^n; x^0 = 1.
  NodeId powInteger(NodeId a, long n);

  // The guarded forms: defined for every input, identically in both backends.
  NodeId sqrtGuarded(NodeId a);          // sqrt(max(a, 0))
  NodeId logGuarded(NodeId a);           // log(max(a, tiny))
  NodeId powGuarded(NodeId a, NodeId b); // pow(max(a, tiny), b)
  // mod(a, b) = a - b*floor(a/b) (GLSL's definition), and a when b == 0.
  NodeId modGuarded(NodeId a, NodeId b);

 private:
  struct Key {
    Op op;
    std::array<NodeId, 4> args;
    std::uint32_t index;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };

  NodeId make(Op op, std::array<NodeId, 4> args, std::uint32_t index = 0);
  bool isNegative(NodeId id) const { return nodes_[id].op == Op::Neg; }
  NodeId operand(NodeId id) const { return nodes_[id].args[0]; }
  // Throws Error at the current origin when folding constants a and b could
  // give more than kMaxConstantBits bits.
  void checkFoldable(NodeId a, NodeId b) const;

  std::vector<std::string> variables_;
  std::vector<Node> nodes_;
  std::vector<Origin> origins_;
  std::vector<mpq_class> constants_;
  std::vector<double> constantValues_;
  std::map<mpq_class, std::uint32_t> constantIndex_;
  std::unordered_map<Key, NodeId, KeyHash> nodeIndex_;
  Origin origin_;
};

// The nodes `root` depends on, itself included, in increasing (topological)
// order. The operands of nodes for which `isLeaf` returns true are not followed.
std::vector<NodeId> dependencies(const Graph& graph, NodeId root,
                                 const std::function<bool(NodeId)>& isLeaf = {});

// The double nearest to q (ties to even), unlike mpq_get_d, which truncates.
double nearestDouble(const mpq_class& q);

}  // namespace sdfwb::expr
