#pragma once
// Internal: Polynomial through FLINT's fmpq_mpoly for what FLINT does far
// faster than our sparse arithmetic: multivariate gcds (FLINT picks Brown,
// Zippel or Hensel lifting; ours went through an ideal intersection, a
// Groebner basis), the exact divisions around them, and the large products
// of implicitization's substitutions (our term-by-term products allocate a
// monomial and a rational per term and were a fifth of a small
// implicitization).

#include "algebra/polynomial.h"

#include <optional>
#include <vector>

namespace sdfwb::algebra::flint {

/// The monic gcd over Q (0 when both are 0). Both in one ring.
Polynomial gcd(const Polynomial& a, const Polynomial& b);

/// a / b when b divides a exactly, else nullopt (b nonzero).
std::optional<Polynomial> divideExact(const Polynomial& a, const Polynomial& b);

/// The monic lcm over Q (0 when either is 0). Both in one ring.
Polynomial lcm(const Polynomial& a, const Polynomial& b);

/// a * b. Both in one ring.
Polynomial multiply(const Polynomial& a, const Polynomial& b);

/// q^e * f(values[0] / q, ..., values[n-1] / q) with e the total degree of
/// f: one value per variable of f's ring, the values and q in one (other)
/// ring. Throws std::runtime_error when FLINT's exponents would overflow.
Polynomial substituteHomogeneous(const Polynomial& f, const std::vector<Polynomial>& values, const Polynomial& q);

}  // namespace sdfwb::algebra::flint
