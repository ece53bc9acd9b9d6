#pragma once
// Conversion of formulas to exact polynomials and rational functions over
// GMP rationals (engine/algebra). Decimals are exact: 0.1 is 1/10.

#include <string_view>
#include <vector>

#include "algebra/polynomial.h"
#include "expr/graph.h"

namespace sdfwb::expr {

struct RationalFunction {
  algebra::Polynomial numerator;
  // A product of primitive integer polynomials with positive leading
  // coefficients (1 for a polynomial): the lcm of the divisors the formula
  // uses, less the factors that cancel.
  algebra::Polynomial denominator;
};

// The value of `node` as a rational function over `ring`. Graph variable i is
// the ring variable named graph.variables()[i]. Throws Error at the column of
// the first operation that is not + - * / or an integer power, e.g.
// "column 5: 'sqrt' is not a polynomial or rational function", and
// std::invalid_argument when a variable the formula uses is not in the ring.
RationalFunction toRationalFunction(const Graph& graph, NodeId node, const algebra::RingPtr& ring);

// Like toRationalFunction, and throws Error at the first division by a
// non-constant when the result is not a polynomial.
algebra::Polynomial toPolynomial(const Graph& graph, NodeId node, const algebra::RingPtr& ring);

// Polynomials "f1; f2; ..." over the ring's variables (see
// compileExpressionList): the input of a Groebner basis computation.
std::vector<algebra::Polynomial> parsePolynomials(std::string_view source, const algebra::RingPtr& ring);

}  // namespace sdfwb::expr
