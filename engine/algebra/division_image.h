#pragma once
// A fast proof that one polynomial does not divide another, for exact
// division (division.h). FLINT's exact division stops at the first quotient
// term that cannot divide, but before it gets there the quotient can grow
// without bound: a fuzzed polynomial, a numerator of degree 21460 in x over
// (x + y + 1), not exact, ran past 120 s and 19 GB computing quotient terms
// with binomial coefficients. If g divides f, then after substituting values
// for every variable but one, the images of f and g modulo a prime divide too;
// so a univariate remainder that is not zero proves g does not divide f, at
// the cost of one evaluation of f and one univariate division.

#include "algebra/polynomial.h"

namespace sdfwb::algebra {

// True when g (nonzero) provably does not divide f; false when it may (no
// variable of g, an image of g that vanishes, or a denominator the prime divides).
bool imageRefutesDivision(const Polynomial& f, const Polynomial& g);

}  // namespace sdfwb::algebra
