#include "algebra/polynomial_gcd.h"

#include "algebra/flint_polynomial.h"

#include <stdexcept>

namespace sdfwb::algebra {

Polynomial gcd(const Polynomial& a, const Polynomial& b) {
  if (!(*a.ring() == *b.ring())) throw std::invalid_argument("gcd of polynomials from different rings");
  if (a.isZero()) return b.primitive();
  if (b.isZero()) return a.primitive();
  if (a.isConstant() || b.isConstant()) return a.ring()->one();
  return flint::gcd(a, b).primitive();
}

Polynomial lcm(const Polynomial& a, const Polynomial& b) {
  if (!(*a.ring() == *b.ring())) throw std::invalid_argument("lcm of polynomials from different rings");
  if (a.isZero() || b.isZero()) return a.ring()->zero();
  if (a.isConstant()) return b.primitive();
  if (b.isConstant()) return a.primitive();
  return flint::lcm(a, b).primitive();
}

}  // namespace sdfwb::algebra
