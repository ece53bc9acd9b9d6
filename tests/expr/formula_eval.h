#pragma once
// Test helpers: evaluate compiled formulas on the CPU.

#include <glm/glm.hpp>

#include <string_view>

#include "expr/derivative.h"
#include "expr/formula.h"
#include "expr/tape.h"

namespace sdfwb::expr::testing {

// The value of a formula over space at p, in precision T.
template <class T>
T evaluateAt(const SpaceFormula& f, glm::vec<3, T> p) {
  const NodeId outputs[] = {f.value};
  const Tape tape(f.graph, outputs);
  Evaluator<T> evaluate(tape);
  const T xyz[] = {p.x, p.y, p.z};
  return evaluate(xyz)[0];
}

template <class T>
T sdfAt(std::string_view source, glm::vec<3, T> p) {
  return evaluateAt(compileSdf(source), p);
}

// The exact value of a formula that folds to a constant (no free names).
inline mpq_class constantValue(std::string_view source) {
  ExpressionList list = compileExpressionList(source, {});
  if (!list.graph.isConstant(list.values.back())) throw std::logic_error("not a constant");
  return list.graph.exactValue(list.values.back());
}

// The error message compileSdf gives for `source`, or "" when it compiles.
template <class Compile>
std::string errorOf(Compile compile, std::string_view source) {
  try {
    compile(source);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

inline std::string sdfError(std::string_view source) { return errorOf(compileSdf, source); }

}  // namespace sdfwb::expr::testing
