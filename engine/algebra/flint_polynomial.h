#pragma once
// Internal: Polynomial through FLINT's fmpq_mpoly for what FLINT does far
// faster than our sparse arithmetic: multivariate gcds (FLINT picks Brown,
// Zippel or Hensel lifting; ours went through an ideal intersection, a
// Groebner basis) and the exact divisions around them.

#include "algebra/polynomial.h"

#include <optional>

namespace sdfwb::algebra::flint {

/// The monic gcd over Q (0 when both are 0). Both in one ring.
Polynomial gcd(const Polynomial& a, const Polynomial& b);

/// a / b when b divides a exactly, else nullopt (b nonzero).
std::optional<Polynomial> divide_exact(const Polynomial& a, const Polynomial& b);

}  // namespace sdfwb::algebra::flint
