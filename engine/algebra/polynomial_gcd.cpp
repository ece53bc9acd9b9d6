#include "algebra/polynomial_gcd.h"

#include "algebra/flint_polynomial.h"

#include <stdexcept>

namespace sdfwb::algebra {

Polynomial gcd(const Polynomial& a, const Polynomial& b) {
  if (!(*a.ring() == *b.ring())) throw std::invalid_argument("gcd of polynomials from different rings");
  if (a.is_zero()) return b.primitive();
  if (b.is_zero()) return a.primitive();
  if (a.is_constant() || b.is_constant()) return a.ring()->one();
  return flint::gcd(a, b).primitive();
}

Polynomial lcm(const Polynomial& a, const Polynomial& b) {
  if (!(*a.ring() == *b.ring())) throw std::invalid_argument("lcm of polynomials from different rings");
  if (a.is_zero() || b.is_zero()) return a.ring()->zero();
  if (a.is_constant()) return b.primitive();
  if (b.is_constant()) return a.primitive();
  return flint::lcm(a, b).primitive();
}

}  // namespace sdfwb::algebra
