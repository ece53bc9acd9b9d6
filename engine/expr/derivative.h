#pragma once
// The symbolic derivative, written once on the scalar graph and used by both
// the CPU evaluator and the GLSL generator (through the tape).

#include <array>
#include <cstdint>

#include "expr/graph.h"

namespace sdfwb::expr {

// d(node)/d(variable), built into the same graph. The rules are the usual
// ones; where a derivative does not exist they pick a value that keeps both
// backends finite and in agreement:
//   abs, min, max, floor, selects: the derivative of the branch taken (0 for floor);
//   sqrt(u):  u' / (2*max(sqrt(u), 2^-126))  (0 where u' = 0, as at the origin of length(p));
//   log(u):   u' / u       (u is already clamped to >= 2^-126 by the guard);
//   pow(a, b): pow(a, b) * (b*a'/a + log(a)*b'), a >= 2^-126 by the guard.
NodeId derivative(Graph& graph, NodeId node, std::uint32_t variable);

// The derivatives with respect to variables 0, 1, 2 (x, y, z in a SpaceFormula).
std::array<NodeId, 3> gradient(Graph& graph, NodeId node);

}  // namespace sdfwb::expr
