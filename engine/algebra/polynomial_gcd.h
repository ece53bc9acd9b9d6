#pragma once
// Greatest common divisors and least common multiples of polynomials over Q,
// e.g. to reduce the fractions of a rational parametrization and to take the
// lcm of their denominators.

#include "algebra/polynomial.h"

namespace sdfwb::algebra {

/// gcd(a, b), normalized by Polynomial::primitive (integer coefficients,
/// content 1, positive leading coefficient); gcd(0, 0) = 0, and the gcd with
/// a nonzero constant is 1. Both in one ring.
Polynomial gcd(const Polynomial& a, const Polynomial& b);

/// lcm(a, b) normalized like gcd; 0 if either is 0.
Polynomial lcm(const Polynomial& a, const Polynomial& b);

}  // namespace sdfwb::algebra
