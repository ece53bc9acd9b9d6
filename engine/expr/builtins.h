#pragma once
// The language's built-in functions: one table that drives lookup, arity
// checks, the reserved words of the identifier rule, and lowering to the graph.

#include <span>
#include <string_view>

#include "expr/error.h"
#include "expr/value.h"

namespace sdfwb::expr {

struct Argument {
  Value value;
  SourceLocation where;
};

struct Builtin {
  std::string_view name;
  int minArguments;
  int maxArguments;
  std::string_view usage;  // shown in arity errors, e.g. "clamp(x, low, high)"
  // Builds the call's nodes; throws Error naming the offending argument.
  Value (*lower)(Graph& graph, SourceLocation call, std::span<const Argument> args);
};

// Every built-in: sin cos tan exp log sqrt abs sign floor fract min max clamp
// mix step smoothstep pow mod length distance dot cross normalize vec2 vec3.
// Semantics are GLSL's (genType functions apply per component; a scalar
// argument broadcasts), with these guards where GLSL leaves a result
// undefined: sqrt and log clamp their argument to 0 and 2^-126, pow its base
// to 2^-126, mod(x, 0) = x, normalize(0) = 0, smoothstep(e, e, x) = step(e, x),
// and clamp is min(max(x, low), high) whatever the order of the bounds.
// pow with a constant integer exponent expands to multiplications, like ^.
std::span<const Builtin> builtins();

// nullptr when `name` is no built-in.
const Builtin* findBuiltin(std::string_view name);

// The largest |n| accepted in x^n and pow(x, n) for a constant integer n.
constexpr long kMaxIntegerExponent = 65536;

// x^e per component with the language's rule: a constant integer exponent
// expands to multiplications, any other goes through the guarded pow.
// `exponentWhere` locates errors about the exponent.
NodeId power(Graph& graph, NodeId base, NodeId exponent, SourceLocation exponentWhere);

// The type of an operation whose arguments are each a scalar or one common
// vector type; throws Error at the first argument of a conflicting type.
Type commonType(std::string_view what, std::span<const Argument> args);

}  // namespace sdfwb::expr
