#pragma once
// Internal: conversion between public Polynomials and the engine's packed
// integer polynomials.

#include "algebra/gb_poly.h"
#include "algebra/polynomial.h"

namespace sdfwb::algebra::gb {

/// p times the lcm of its coefficient denominators (integer coefficients,
/// same terms and order). `ring` of p must be the layout's ring.
IntPoly toIntegerPoly(const Polynomial& p, const Layout& layout, mpz_class* denominator = nullptr);

/// The same polynomial with FLINT integers.
FmpzPoly toFmpzPoly(const IntPoly& p);

/// Back to a public polynomial, optionally divided by its leading
/// coefficient; `divisor` (if given) divides every coefficient.
Polynomial toPolynomial(const IntPoly& p, const Layout& layout, const RingPtr& ring, bool monic,
                         const mpz_class* divisor = nullptr);

}  // namespace sdfwb::algebra::gb
