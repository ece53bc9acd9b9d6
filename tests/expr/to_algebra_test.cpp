// Conversion to exact polynomials and rational functions.

#include <gtest/gtest.h>

#include "expr/formula.h"
#include "expr/to_algebra.h"
#include "formula_eval.h"

namespace sdfwb::expr {
namespace {

using algebra::Polynomial;
using algebra::Rational;

class ToAlgebra : public ::testing::Test {
 protected:
  algebra::RingPtr ring = algebra::Ring::make({"x", "y", "z"});
  Polynomial x = ring->var("x"), y = ring->var("y"), z = ring->var("z");

  Polynomial polynomial(std::string_view source) {
    const SpaceFormula f = compileImplicit(source);
    return toPolynomial(f.graph, f.value, ring);
  }
  RationalFunction rational(std::string_view source) {
    const SpaceFormula f = compileImplicit(source);
    return toRationalFunction(f.graph, f.value, ring);
  }
  std::string polynomialError(std::string_view source) {
    return testing::errorOf([&](std::string_view s) { return polynomial(s); }, source);
  }
};

TEST_F(ToAlgebra, DecimalsAreExact) {
  EXPECT_EQ(polynomial("0.1 * x"), Rational(1, 10) * x);
  EXPECT_EQ(polynomial("0.1 + 0.2 - 0.3"), ring->zero());
  EXPECT_EQ(polynomial("1.5e-3 * y^2"), Rational(3, 2000) * pow(y, 2));
  EXPECT_EQ(polynomial("x / 3 + y / 7"), Rational(1, 3) * x + Rational(1, 7) * y);
}

TEST_F(ToAlgebra, Polynomials) {
  EXPECT_EQ(polynomial("(x + 1)^2 - x^2"), 2 * x + 1);
  EXPECT_EQ(polynomial("x^2 + y^2 + z^2 = 1"), pow(x, 2) + pow(y, 2) + pow(z, 2) - 1);
  EXPECT_EQ(polynomial("dot(p, p) - 1"), pow(x, 2) + pow(y, 2) + pow(z, 2) - 1);
  EXPECT_EQ(polynomial("let q = p - vec3(1, 0, 0); dot(q, q)"), pow(x - 1, 2) + pow(y, 2) + pow(z, 2));
  EXPECT_EQ(polynomial("mix(x, y, 0.25)"), Rational(3, 4) * x + Rational(1, 4) * y);
  EXPECT_EQ(polynomial("cross(p, vec3(0, 0, 1)).x"), y);
  EXPECT_EQ(polynomial("pow(x - y, 3.0)"), pow(x - y, 3));
  EXPECT_EQ(polynomial("(x^2 - 1) / (x - 1)"), x + 1);  // the common factor cancels
  EXPECT_EQ(polynomial("x^-2 * x^3"), x);
  EXPECT_EQ(polynomial("sqrt(4) * x + abs(-3)"), 2 * x + 3);  // constants fold exactly
}

TEST_F(ToAlgebra, RationalFunctions) {
  const RationalFunction sum = rational("1/x + 1/y");
  EXPECT_EQ(sum.numerator, x + y);
  EXPECT_EQ(sum.denominator, x * y);
  // Denominators combine by their lcm, not their product.
  const RationalFunction common = rational("x/(z + 1) + y/(z + 1)");
  EXPECT_EQ(common.numerator, x + y);
  EXPECT_EQ(common.denominator, z + 1);
  const RationalFunction powers = rational("1/(z^2 + 1)^2 + 1/(z^2 + 1)");
  EXPECT_EQ(powers.numerator, pow(z, 2) + 2);
  EXPECT_EQ(powers.denominator, pow(pow(z, 2) + 1, 2));
  // Constants go to the numerator; the denominator is primitive.
  const RationalFunction scaled = rational("x / (2*y + 4)");
  EXPECT_EQ(scaled.numerator, Rational(1, 2) * x);
  EXPECT_EQ(scaled.denominator, y + 2);
  const RationalFunction nested = rational("1 / (1 / x + 1)");
  EXPECT_EQ(nested.numerator, x);
  EXPECT_EQ(nested.denominator, x + 1);
}

TEST_F(ToAlgebra, ErrorsNameTheFunctionAndColumn) {
  EXPECT_EQ(polynomialError("x + sqrt(y)"), "column 5: 'sqrt' is not a polynomial or rational function");
  EXPECT_EQ(polynomialError("x^0.5"), "column 2: a non-integer exponent is not a polynomial or rational function");
  EXPECT_EQ(polynomialError("length(p) - 1"), "column 1: 'length' is not a polynomial or rational function");
  EXPECT_EQ(polynomialError("x * sin(y)"), "column 5: 'sin' is not a polynomial or rational function");
  EXPECT_EQ(polynomialError("abs(x)"), "column 1: 'abs' is not a polynomial or rational function");
  EXPECT_EQ(polynomialError("mod(x, 2)"), "column 1: 'mod' is not a polynomial or rational function");
  EXPECT_EQ(polynomialError("max(x, y)"), "column 1: 'max' is not a polynomial or rational function");
  EXPECT_EQ(polynomialError("1 + 1/x"), "column 6: division by a non-constant expression: the formula is not a polynomial");
  EXPECT_EQ(polynomialError("1/((x+1)^2 - x^2 - 2*x - 1)"), "column 2: division by an expression that is identically 0");
}

// x^-65536 sixteen times over y + 1: nothing is expanded while the formula
// is read (the powers of the factors add up), and the denominator left at
// the end, of degree 2^20 + 1, is past the expansion's degree limit. That is
// an ordinary error at the formula's root, not an exception escaping the
// conversion (a fuzzer found one); a polynomial never expands it at all.
TEST_F(ToAlgebra, ADenominatorTooLargeToExpandIsAnErrorWithItsColumn) {
  std::string source = "1/(y+1)";
  for (int i = 0; i < 16; ++i) source += "*x^-65536";
  const SpaceFormula f = compileImplicit(source);
  const std::string rationalError =
      testing::errorOf([&](std::string_view) { return toRationalFunction(f.graph, f.value, ring); }, source);
  EXPECT_NE(rationalError.find("would have degree 1048577"), std::string::npos) << rationalError;
  EXPECT_EQ(rationalError.rfind("column 143: ", 0), 0u) << rationalError;  // the last product, the root
  EXPECT_EQ(polynomialError(source), "column 2: division by a non-constant expression: the formula is not a polynomial");
}

// A known factor is divided out by f, f^2, f^4, ... and back down, about
// 2 log2 k divisions for multiplicity k: one power at a time, x^-2 + x^-60000
// took 30000 divisions of degree 60000 (19 s) before its error. Each
// multiplicity comes out exact, up to the power the fraction holds.
TEST_F(ToAlgebra, KnownFactorsAreDividedOutWholeAtAnyMultiplicity) {
  EXPECT_EQ(polynomialError("x^-2 + x^-60000"),
            "column 2: division by a non-constant expression: the formula is not a polynomial");
  for (int k : {1, 2, 3, 5, 7, 8, 13, 64, 100}) {
    SCOPED_TRACE(k);
    const std::string power = std::to_string(k);
    // (z + 1) becomes a known factor; (z + 1)^(k + 1) then holds it k + 1 times
    EXPECT_EQ(polynomial("(z + 1)^" + std::to_string(k + 1) + " * y / (z + 1)"), pow(z + 1, k) * y);
    EXPECT_EQ(polynomial("x^-2 * x^" + std::to_string(k + 2) + " * y"), pow(x, k) * y);
    const RationalFunction r = rational("1 / (x^2 + 1) + x / (x^2 + 1)^" + power);
    EXPECT_EQ(r.denominator, pow(pow(x, 2) + 1, k));
    EXPECT_EQ(r.numerator, k == 1 ? x + 1 : pow(pow(x, 2) + 1, k - 1) + x);
  }
}

TEST_F(ToAlgebra, PolynomialLists) {
  const auto ring2 = algebra::Ring::make({"a", "b"}, algebra::MonomialOrder::lex());
  const auto list = parsePolynomials("a^2 - 0.25; let c = a*b; c - 1", ring2);
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0], pow(ring2->var("a"), 2) - Rational(1, 4));
  EXPECT_EQ(list[1].toString(), "a*b - 1");
  EXPECT_EQ(testing::errorOf([&](std::string_view s) { return parsePolynomials(s, ring2); }, "a + w"),
            "column 5: unknown name 'w' (the variables are the ones listed)");
}

}  // namespace
}  // namespace sdfwb::expr
