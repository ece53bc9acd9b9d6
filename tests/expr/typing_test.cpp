// Typing: vectors, components, built-in signatures, names, statement structure.

#include <gtest/gtest.h>

#include "formula_eval.h"

namespace sdfwb::expr {
namespace {

using testing::errorOf;
using testing::sdfError;

std::string parametricError(std::string_view source) { return errorOf(compileParametricEquations, source); }
std::string implicitError(std::string_view source) { return errorOf(compileImplicit, source); }

TEST(Typing, TypeErrors) {
  EXPECT_EQ(sdfError("length(p + vec2(1, 2))"), "column 10: cannot add vec3 and vec2");
  EXPECT_EQ(sdfError("p * 2"), "column 1: the formula must be a scalar, got vec3");
  EXPECT_EQ(sdfError("vec2(1, 2).z"), "column 11: vec2 has no component 'z'");
  EXPECT_EQ(sdfError("x.x"), "column 2: a scalar has no components");
  EXPECT_EQ(sdfError("p.w"), "column 2: 'w' is not a component: use x, y, z");
  EXPECT_EQ(sdfError("sin(1, 2)"), "column 1: sin takes 1 argument, got 2 (usage: sin(x))");
  EXPECT_EQ(sdfError("clamp(x)"), "column 1: clamp takes 3 arguments, got 1 (usage: clamp(x, low, high))");
  EXPECT_EQ(sdfError("foo(1)"), "column 1: unknown function 'foo'");
  EXPECT_EQ(sdfError("length(min(p, vec2(1, 1)))"),
            "column 15: min needs arguments of one type or scalars, got vec3 and vec2");
  EXPECT_EQ(sdfError("dot(p, 1)"), "column 8: dot needs arguments of the same type, got vec3 and scalar");
  EXPECT_EQ(sdfError("length(cross(p, p.xy))"), "column 17: cross needs vec3 arguments, got vec2");
  EXPECT_EQ(sdfError("x ^ p"), "column 3: the exponent of '^' must be a scalar, got vec3");
  EXPECT_EQ(sdfError("x / 0"), "column 3: division by zero");
  EXPECT_EQ(sdfError("length(vec3(1, 2))"), "column 8: vec3 needs 3 components, got 2");
  EXPECT_EQ(sdfError("length(vec2(p, 1))"), "column 13: vec2 needs 2 components, this argument gives too many");
  EXPECT_EQ(sdfError("x ^ 100000"), "column 3: the exponent is too large (at most 65536)");
}

TEST(Typing, Names) {
  EXPECT_EQ(sdfError("w + 1"), "column 1: unknown name 'w' (a formula over space uses p, x, y, z and its let names)");
  EXPECT_EQ(sdfError("let p = 1; p"), "column 5: 'p' is already defined");
  EXPECT_EQ(sdfError("let a = 1; let a = 2; a"), "column 16: 'a' is already defined");
  EXPECT_EQ(sdfError("let sin = 1; x"), "column 5: 'sin' is the name of a built-in function");
  EXPECT_EQ(sdfError("let _a = 1; x"), "column 5: '_a' does not start with a letter");
  EXPECT_EQ(sdfError("sin + 1"), "column 1: 'sin' is a function: expected '(' after it");
}

TEST(Typing, StatementStructure) {
  EXPECT_EQ(sdfError("x = 1"), "column 1: a distance formula cannot be an equation");
  EXPECT_EQ(sdfError("let a = 1"), "column 10: expected an expression after the let bindings");
  EXPECT_EQ(sdfError("1; 2"), "column 1: only the last statement gives the formula's value: bind this one with 'let'");
  EXPECT_EQ(implicitError("x^2 + y^2 = p"), "column 13: the right-hand side must be a scalar, got vec3");
  EXPECT_EQ(implicitError("x^2 + y^2 = 1"), "");
}

TEST(Typing, VectorsComponentsAndSwizzles) {
  const glm::dvec3 p(0.5, -2, 3);
  EXPECT_EQ(testing::sdfAt("vec3(p.xy, 7).z", p), 7);
  EXPECT_EQ(testing::sdfAt("vec2(p.zyx).y", p), -2);  // truncating constructor
  EXPECT_EQ(testing::sdfAt("vec3(x).y", p), 0.5);     // broadcasting constructor
  EXPECT_EQ(testing::sdfAt("(p * 2 + 1).y", p), -3);
  EXPECT_EQ(testing::sdfAt("(2 / p).x", p), 4);
  EXPECT_EQ(testing::sdfAt("dot(p.xz, vec2(2, 1))", p), 4);
  EXPECT_EQ(testing::sdfAt("cross(vec3(1, 0, 0), vec3(0, 1, 0)).z", p), 1);
  EXPECT_EQ(testing::sdfAt("(-p).y", p), 2);
  EXPECT_EQ(testing::sdfAt("(p ^ 2).y", p), 4);
}

TEST(Typing, ParametricEquations) {
  const ParametricEquations eq = compileParametricEquations("z = u^2; x = u*v; let w = v; y = w");
  ASSERT_EQ(eq.equations.size(), 3u);
  EXPECT_EQ(eq.equations[0].coordinate, "x");
  EXPECT_EQ(eq.equations[2].coordinate, "z");
  EXPECT_EQ(eq.graph.variables(), (std::vector<std::string>{"u", "v"}));

  EXPECT_EQ(parametricError("x = u; x = v"), "column 8: 'x' is given twice");
  EXPECT_EQ(parametricError("x = y"), "column 5: 'y' is a coordinate: the right-hand sides may use only parameters");
  EXPECT_EQ(parametricError("u = 1"), "column 1: the left-hand side of an equation must be x, y or z");
  EXPECT_EQ(parametricError("x = _t"), "column 5: '_t' does not start with a letter");
  EXPECT_EQ(parametricError("x = u; v"), "column 8: expected an equation such as 'x = u*v'");
  EXPECT_EQ(parametricError("let x = 1; y = x"), "column 5: 'x' is a coordinate and cannot be bound with let");
  EXPECT_EQ(parametricError(" "), "column 2: expected equations such as 'x = u*v; y = v; z = u^2'");
}

TEST(Typing, ExpressionLists) {
  const std::vector<std::string> vars{"a", "b"};
  const ExpressionList list = compileExpressionList("a^2 - b; let c = a; c*b", vars);
  EXPECT_EQ(list.values.size(), 2u);
  EXPECT_EQ(list.where[1].column, 21);
  EXPECT_EQ(errorOf([&](std::string_view s) { return compileExpressionList(s, vars); }, "a + x"),
            "column 5: unknown name 'x' (the variables are the ones listed)");
  const std::vector<std::string> bad{"a", "cos"};
  EXPECT_THROW(compileExpressionList("a", bad), std::invalid_argument);
  const std::vector<std::string> twice{"a", "a"};
  EXPECT_THROW(compileExpressionList("a", twice), std::invalid_argument);
}

}  // namespace
}  // namespace sdfwb::expr
