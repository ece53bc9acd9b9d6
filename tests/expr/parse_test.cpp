// Parsing: precedence, numbers, and syntax errors with their exact columns.

#include <gtest/gtest.h>

#include "expr/identifier.h"
#include "formula_eval.h"

namespace sdfwb::expr {
namespace {

using testing::constantValue;
using testing::sdfError;

TEST(Parse, PrecedenceAndAssociativity) {
  EXPECT_EQ(constantValue("2 + 3 * 4"), 14);
  EXPECT_EQ(constantValue("(2 + 3) * 4"), 20);
  EXPECT_EQ(constantValue("10 - 4 - 3"), 3);
  EXPECT_EQ(constantValue("8 / 4 / 2"), 1);
  EXPECT_EQ(constantValue("2 ^ 3 ^ 2"), 512);  // right associative
  EXPECT_EQ(constantValue("-2 ^ 2"), -4);      // ^ binds tighter than unary minus
  EXPECT_EQ(constantValue("2 ^ -1"), mpq_class(1, 2));
  EXPECT_EQ(constantValue("--3"), 3);
  EXPECT_EQ(constantValue("+3 - -3"), 6);
  EXPECT_EQ(constantValue("-2 * 3 ^ 2 + 1"), -17);
  EXPECT_EQ(constantValue("2 * -3"), -6);
}

TEST(Parse, UnaryMinusOfPowerAtRuntime) {
  // -x^2 = -(x^2): at x = 3 this is -9, not 9.
  EXPECT_EQ(testing::sdfAt<double>("-x^2", {3, 0, 0}), -9);
  EXPECT_EQ(testing::sdfAt<double>("x^-2", {2, 0, 0}), 0.25);
}

TEST(Parse, NumbersAreExactDecimals) {
  EXPECT_EQ(constantValue("0.1"), mpq_class(1, 10));
  EXPECT_EQ(constantValue(".5"), mpq_class(1, 2));
  EXPECT_EQ(constantValue("2."), 2);
  EXPECT_EQ(constantValue("1.5e-3"), mpq_class(3, 2000));
  EXPECT_EQ(constantValue("12E2"), 1200);
  EXPECT_EQ(constantValue("0.1 + 0.2"), mpq_class(3, 10));
  EXPECT_EQ(constantValue("123456789012345678901234567890"), mpq_class("123456789012345678901234567890"));
}

TEST(Parse, LetBindingsCommentsAndLines) {
  EXPECT_EQ(constantValue("let a = 2; let b = a * 3; a + b"), 8);
  EXPECT_EQ(constantValue("let a = 2; // two\n  a ^ 2;"), 4);
}

TEST(Parse, ErrorsNameTheColumnAndWhatWasExpected) {
  EXPECT_EQ(sdfError("sin(x y)"), "column 7: expected ')' after function arguments");
  EXPECT_EQ(sdfError("1 +"), "column 4: expected an expression");
  EXPECT_EQ(sdfError("(1 + 2"), "column 7: expected ')'");
  EXPECT_EQ(sdfError("2 # 3"), "column 3: unexpected character '#'");
  EXPECT_EQ(sdfError("1e+"), "column 4: expected digits in the exponent of a number");
  EXPECT_EQ(sdfError("let = 2; 1"), "column 5: expected a name after 'let'");
  EXPECT_EQ(sdfError("let a 2; a"), "column 7: expected '=' after 'let a'");
  EXPECT_EQ(sdfError("x 2"), "column 3: expected an operator, ';' or the end of the formula");
  EXPECT_EQ(sdfError("p."), "column 3: expected a component name such as x after '.'");
  EXPECT_EQ(sdfError("2x"), "column 2: expected an operator, ';' or the end of the formula");
  EXPECT_EQ(sdfError("x + let"), "column 5: 'let' must start a statement");
  EXPECT_EQ(sdfError(""), "column 1: expected an expression");
  EXPECT_EQ(sdfError("1e5000"), "column 1: the exponent of this number is too large");
  EXPECT_EQ(sdfError("x \xc3\xa9"), "column 3: unexpected character (only ASCII is allowed)");
}

TEST(Parse, ErrorsAfterTheFirstLineNameTheLine) {
  EXPECT_EQ(sdfError("let a = 1;\n  foo(a)"), "line 2, column 3: unknown function 'foo'");
}

TEST(Parse, ErrorCarriesLocationAndMessage) {
  try {
    compileSdf("min(x, y");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().column, 9);
    EXPECT_EQ(e.message(), "expected ')' after function arguments");
  }
}

TEST(Identifier, OneRule) {
  for (const char* ok : {"u", "v", "theta", "u_1", "A2", "p", "x", "t0"}) EXPECT_TRUE(isIdentifier(ok)) << ok;
  for (const char* bad : {"", "$t", "1u", "_a", "a-b", "sin", "vec3", "let", "length", "\xc3\xa9"}) {
    EXPECT_FALSE(isIdentifier(bad)) << bad;
  }
  EXPECT_EQ(identifierProblem("sin"), "'sin' is the name of a built-in function");
  EXPECT_EQ(identifierProblem("_s"), "'_s' does not start with a letter");
}

}  // namespace
}  // namespace sdfwb::expr
