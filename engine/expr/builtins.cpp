#include "expr/builtins.h"

#include <algorithm>
#include <array>
#include <string>

namespace sdfwb::expr {
namespace {

using Args = std::span<const Argument>;

// Applies f to the i-th components of all arguments, for each component of `type`.
template <class F>
Value perComponent(Type type, Args args, F f) {
  Value out{type, {}};
  for (int i = 0; i < out.size(); ++i) {
    std::array<NodeId, 3> c{};
    for (std::size_t k = 0; k < args.size(); ++k) c[k] = args[k].value[i];
    out.components[i] = f(c);
  }
  if (type == Type::Scalar) out = Value::scalar(out.components[0]);
  return out;
}

NodeId sumOfProducts(Graph& g, const Value& a, const Value& b) {
  NodeId sum = g.mul(a[0], b[0]);
  for (int i = 1; i < a.size(); ++i) sum = g.add(sum, g.mul(a[i], b[i]));
  return sum;
}

void requireSameType(std::string_view function, Args args) {
  for (std::size_t k = 1; k < args.size(); ++k) {
    if (args[k].value.type != args[0].value.type) {
      throw Error(args[k].where, std::string(function) + " needs arguments of the same type, got " +
                                     std::string(typeName(args[0].value.type)) + " and " +
                                     std::string(typeName(args[k].value.type)));
    }
  }
}

template <Op Operation>
Value lowerUnary(Graph& g, SourceLocation, Args args) {
  return perComponent(args[0].value.type, args, [&](auto c) { return g.unary(Operation, c[0]); });
}

Value lowerLog(Graph& g, SourceLocation, Args args) {
  return perComponent(args[0].value.type, args, [&](auto c) { return g.logGuarded(c[0]); });
}

Value lowerSqrt(Graph& g, SourceLocation, Args args) {
  return perComponent(args[0].value.type, args, [&](auto c) { return g.sqrtGuarded(c[0]); });
}

Value lowerSign(Graph& g, SourceLocation, Args args) {
  return perComponent(args[0].value.type, args, [&](auto c) {
    const NodeId zero = g.constant(0);
    return g.selectLess(zero, c[0], g.constant(1), g.selectLess(c[0], zero, g.constant(-1), zero));
  });
}

Value lowerFract(Graph& g, SourceLocation, Args args) {
  return perComponent(args[0].value.type, args, [&](auto c) { return g.sub(c[0], g.unary(Op::Floor, c[0])); });
}

Value lowerMin(Graph& g, SourceLocation, Args args) {
  return perComponent(commonType("min", args), args, [&](auto c) { return g.min(c[0], c[1]); });
}

Value lowerMax(Graph& g, SourceLocation, Args args) {
  return perComponent(commonType("max", args), args, [&](auto c) { return g.max(c[0], c[1]); });
}

Value lowerClamp(Graph& g, SourceLocation, Args args) {
  return perComponent(commonType("clamp", args), args, [&](auto c) { return g.min(g.max(c[0], c[1]), c[2]); });
}

// GLSL: mix(a, b, t) = a*(1 - t) + b*t.
Value lowerMix(Graph& g, SourceLocation, Args args) {
  return perComponent(commonType("mix", args), args, [&](auto c) {
    return g.add(g.mul(c[0], g.sub(g.constant(1), c[2])), g.mul(c[1], c[2]));
  });
}

// GLSL: step(edge, x) = x < edge ? 0 : 1.
Value lowerStep(Graph& g, SourceLocation, Args args) {
  return perComponent(commonType("step", args), args,
                      [&](auto c) { return g.selectLess(c[1], c[0], g.constant(0), g.constant(1)); });
}

// GLSL: t = clamp((x - e0)/(e1 - e0), 0, 1); t*t*(3 - 2*t); and step(e0, x) when e0 == e1.
Value lowerSmoothstep(Graph& g, SourceLocation, Args args) {
  return perComponent(commonType("smoothstep", args), args, [&](auto c) {
    const NodeId zero = g.constant(0), one = g.constant(1);
    const NodeId t = g.min(g.max(g.div(g.sub(c[2], c[0]), g.sub(c[1], c[0])), zero), one);
    const NodeId smooth = g.mul(g.mul(t, t), g.sub(g.constant(3), g.mul(g.constant(2), t)));
    return g.selectEqual(c[0], c[1], g.selectLess(c[2], c[0], zero, one), smooth);
  });
}

Value lowerPow(Graph& g, SourceLocation, Args args) {
  return perComponent(commonType("pow", args), args,
                      [&](auto c) { return power(g, c[0], c[1], args[1].where); });
}

Value lowerMod(Graph& g, SourceLocation, Args args) {
  return perComponent(commonType("mod", args), args, [&](auto c) { return g.modGuarded(c[0], c[1]); });
}

Value lowerLength(Graph& g, SourceLocation, Args args) {
  return Value::scalar(g.sqrtGuarded(sumOfProducts(g, args[0].value, args[0].value)));
}

Value lowerDistance(Graph& g, SourceLocation, Args args) {
  requireSameType("distance", args);
  const Value difference = perComponent(args[0].value.type, args, [&](auto c) { return g.sub(c[0], c[1]); });
  return Value::scalar(g.sqrtGuarded(sumOfProducts(g, difference, difference)));
}

Value lowerDot(Graph& g, SourceLocation, Args args) {
  requireSameType("dot", args);
  return Value::scalar(sumOfProducts(g, args[0].value, args[1].value));
}

Value lowerCross(Graph& g, SourceLocation, Args args) {
  for (const Argument& a : args) {
    if (a.value.type != Type::Vec3) {
      throw Error(a.where, "cross needs vec3 arguments, got " + std::string(typeName(a.value.type)));
    }
  }
  const Value& a = args[0].value;
  const Value& b = args[1].value;
  return Value{Type::Vec3,
               {g.sub(g.mul(a[1], b[2]), g.mul(a[2], b[1])), g.sub(g.mul(a[2], b[0]), g.mul(a[0], b[2])),
                g.sub(g.mul(a[0], b[1]), g.mul(a[1], b[0]))}};
}

// v / max(length(v), 2^-126): the zero vector stays zero.
Value lowerNormalize(Graph& g, SourceLocation, Args args) {
  const Value& v = args[0].value;
  const NodeId length = g.max(g.sqrtGuarded(sumOfProducts(g, v, v)), g.constant(tinyPositive()));
  return perComponent(v.type, args, [&](auto c) { return g.div(c[0], length); });
}

// GLSL constructor rules: one scalar broadcasts, one longer vector truncates,
// otherwise the components of all arguments are concatenated and must number exactly n.
template <int N>
Value lowerVector(Graph&, SourceLocation call, Args args) {
  Value out{vectorType(N), {}};
  if (args.size() == 1 && (args[0].value.type == Type::Scalar || args[0].value.size() >= N)) {
    for (int i = 0; i < N; ++i) out.components[i] = args[0].value[i];
    return out;
  }
  int count = 0;
  for (const Argument& a : args) {
    for (int i = 0; i < a.value.size(); ++i) {
      if (count == N) {
        throw Error(a.where, "vec" + std::to_string(N) + " needs " + std::to_string(N) +
                                 " components, this argument gives too many");
      }
      out.components[count++] = a.value[i];
    }
  }
  if (count != N) {
    throw Error(call, "vec" + std::to_string(N) + " needs " + std::to_string(N) + " components, got " +
                          std::to_string(count));
  }
  return out;
}

constexpr Builtin kBuiltins[] = {
    {"sin", 1, 1, "sin(x)", lowerUnary<Op::Sin>},
    {"cos", 1, 1, "cos(x)", lowerUnary<Op::Cos>},
    {"tan", 1, 1, "tan(x)", lowerUnary<Op::Tan>},
    {"exp", 1, 1, "exp(x)", lowerUnary<Op::Exp>},
    {"log", 1, 1, "log(x)", lowerLog},
    {"sqrt", 1, 1, "sqrt(x)", lowerSqrt},
    {"abs", 1, 1, "abs(x)", lowerUnary<Op::Abs>},
    {"sign", 1, 1, "sign(x)", lowerSign},
    {"floor", 1, 1, "floor(x)", lowerUnary<Op::Floor>},
    {"fract", 1, 1, "fract(x)", lowerFract},
    {"min", 2, 2, "min(a, b)", lowerMin},
    {"max", 2, 2, "max(a, b)", lowerMax},
    {"clamp", 3, 3, "clamp(x, low, high)", lowerClamp},
    {"mix", 3, 3, "mix(a, b, t)", lowerMix},
    {"step", 2, 2, "step(edge, x)", lowerStep},
    {"smoothstep", 3, 3, "smoothstep(edge0, edge1, x)", lowerSmoothstep},
    {"pow", 2, 2, "pow(x, y)", lowerPow},
    {"mod", 2, 2, "mod(x, y)", lowerMod},
    {"length", 1, 1, "length(v)", lowerLength},
    {"distance", 2, 2, "distance(a, b)", lowerDistance},
    {"dot", 2, 2, "dot(a, b)", lowerDot},
    {"cross", 2, 2, "cross(a, b)", lowerCross},
    {"normalize", 1, 1, "normalize(v)", lowerNormalize},
    {"vec2", 1, 2, "vec2(x, y)", lowerVector<2>},
    {"vec3", 1, 3, "vec3(x, y, z)", lowerVector<3>},
};

}  // namespace

std::string_view typeName(Type type) {
  switch (type) {
    case Type::Scalar: return "scalar";
    case Type::Vec2: return "vec2";
    case Type::Vec3: return "vec3";
  }
  return "?";
}

std::span<const Builtin> builtins() { return kBuiltins; }

const Builtin* findBuiltin(std::string_view name) {
  const auto it = std::find_if(std::begin(kBuiltins), std::end(kBuiltins),
                               [&](const Builtin& b) { return b.name == name; });
  return it == std::end(kBuiltins) ? nullptr : it;
}

Type commonType(std::string_view what, std::span<const Argument> args) {
  Type type = Type::Scalar;
  for (const Argument& a : args) {
    if (a.value.type == Type::Scalar) continue;
    if (type == Type::Scalar) {
      type = a.value.type;
    } else if (a.value.type != type) {
      throw Error(a.where, std::string(what) + " needs arguments of one type or scalars, got " +
                               std::string(typeName(type)) + " and " + std::string(typeName(a.value.type)));
    }
  }
  return type;
}

NodeId power(Graph& graph, NodeId base, NodeId exponent, SourceLocation exponentWhere) {
  if (graph.isConstant(exponent) && graph.exactValue(exponent).get_den() == 1) {
    const mpz_class& n = graph.exactValue(exponent).get_num();
    if (abs(n) > kMaxIntegerExponent) {
      throw Error(exponentWhere, "the exponent is too large (at most " + std::to_string(kMaxIntegerExponent) + ")");
    }
    if (n < 0 && graph.isConstant(base, 0)) {
      throw Error(exponentWhere, "division by zero: 0 to a negative power");
    }
    return graph.powInteger(base, n.get_si());
  }
  return graph.powGuarded(base, exponent);
}

}  // namespace sdfwb::expr
