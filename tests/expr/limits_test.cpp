// Hostile formulas: deep nesting, long chains, huge literals, huge exponents and
// expansions that would take minutes end in one error with a column.

#include <gtest/gtest.h>

#include "expr/fractions.h"
#include "expr/parser.h"
#include "expr/to_algebra.h"
#include "formula_eval.h"

namespace sdfwb::expr {
namespace {

using testing::sdfError;

std::string repeated(std::string_view piece, int count) {
  std::string out;
  for (int i = 0; i < count; ++i) out += piece;
  return out;
}

std::string polynomialError(std::string_view source, const std::vector<std::string>& variables) {
  try {
    parsePolynomials(source, algebra::Ring::make(variables));
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

const std::string kTooDeep = "nests deeper than " + std::to_string(kMaxExpressionDepth) + " levels";

TEST(Limits, DeepParenthesesSignsAndChainsAreErrorsNotCrashes) {
  for (const std::string& source : {repeated("(", 100000) + "x" + repeated(")", 100000),
                                    repeated("-", 100000) + "x", repeated("+", 100000) + "x",
                                    "x" + repeated(" + x", 100000), "x" + repeated(" * x", 100000),
                                    "x" + repeated("^x", 100000), "p" + repeated(".x", 100000),
                                    repeated("abs(", 100000) + "x" + repeated(")", 100000)}) {
    const std::string error = sdfError(source);
    EXPECT_NE(error.find(kTooDeep), std::string::npos) << error.substr(0, 200);
    EXPECT_LT(error.size(), 200u);
  }
}

TEST(Limits, LegalDepthsStillCompile) {
  EXPECT_EQ(sdfError(repeated("(", 400) + "x" + repeated(")", 400)), "");
  EXPECT_EQ(sdfError("x" + repeated(" + y", 1500)), "");
  EXPECT_EQ(sdfError(repeated("-", 1500) + "x"), "");
}

TEST(Limits, LongSourcesLiteralsAndNamesAreRefused) {
  EXPECT_NE(sdfError(std::string(kMaxFormulaLength + 1, ' ') + "x").find("characters long (at most"), std::string::npos);
  EXPECT_EQ(sdfError("x + " + std::string(101, '7')), "column 5: a number of 101 digits (at most 100)");
  EXPECT_EQ(sdfError("x + 0.000" + std::string(100, '7')), "");
  EXPECT_EQ(sdfError("x + " + std::string(101, 'a')), "column 5: a name of 101 characters (at most 100)");
}

TEST(Limits, ZeroToANegativePowerIsADivisionByZero) {
  EXPECT_EQ(sdfError("x + 0^-1"), "column 6: division by zero: 0 to a negative power");
  EXPECT_EQ(sdfError("x + (1 - 1)^-2"), "column 12: division by zero: 0 to a negative power");
  EXPECT_EQ(sdfError("x + 0^2"), "");
}

TEST(Limits, ExponentsNeverWrap) {
  const std::string error = polynomialError("(x^65536)^65536 - 2", {"x"});
  EXPECT_NE(error.find("would have degree"), std::string::npos) << error;
  EXPECT_NE(error.find("(at most " + std::to_string(kMaxExpandedDegree) + ")"), std::string::npos) << error;
  EXPECT_NE(polynomialError("((((x^256)^256)^256)^256)", {"x"}).find("would have degree"), std::string::npos);
  // huge binomial coefficients stop the expansion long before the degree does
  EXPECT_NE(polynomialError("1/((x+1)^65536)^65536", {"x"}).find("too large to expand"), std::string::npos);
}

TEST(Limits, ExpansionStopsAtItsWorkLimit) {
  const std::string error = polynomialError("(x+y+1)^600", {"x", "y"});
  EXPECT_EQ(error.rfind("column 8: the formula is too large to expand exactly", 0), 0u) << error;
  EXPECT_EQ(polynomialError("(x+y+1)^60", {"x", "y"}), "");
}

// Constants fold exactly, and a power of a power of a constant grew without
// bound: (3 - 5^65536)^65535 took 23 s and 2.2 GB before libFuzzer gave up
// (fuzz_polynomial, kept in its regressions). Each folded constant is now
// bounded before it is computed, in polynomials and in sdf formulas alike.
TEST(Limits, FoldedConstantsAreBounded) {
  const std::string tooLarge = "the number is too large to compute exactly";
  const std::string error = polynomialError("(3- 5^65536)^65535 - 2", {"x"});
  EXPECT_EQ(error.rfind("column 13: " + tooLarge, 0), 0u) << error;  // the outer ^
  EXPECT_NE(sdfError("x + (3 - 5^65536)^65535").find(tooLarge), std::string::npos);
  EXPECT_NE(sdfError("x + 1/(7^65536)^17").find(tooLarge), std::string::npos);
  // the largest power of a literal stays exact: 5^65536 has 152,170 bits
  EXPECT_EQ(polynomialError("x - 5^65536", {"x"}), "");
  EXPECT_EQ(sdfError("x + 5^65536 - 5^65536"), "");
}

TEST(Limits, VariableAndParameterCountsAreBounded) {
  std::vector<std::string> many;
  for (std::size_t i = 0; i <= kMaxVariables; ++i) many.push_back("v" + std::to_string(i));
  EXPECT_THROW(compileExpressionList("v0", many), std::invalid_argument);
  std::string sum = "x = 0";
  for (std::size_t i = 0; i <= kMaxVariables; ++i) sum += " + u" + std::to_string(i);
  const std::string error = testing::errorOf(compileParametricEquations, sum + "; y = u0; z = u1");
  EXPECT_NE(error.find("more than " + std::to_string(kMaxVariables) + " parameters"), std::string::npos) << error;
}

}  // namespace
}  // namespace sdfwb::expr
