#include "algebra/monomial.h"

#include <algorithm>
#include <cassert>

namespace sdfwb::algebra {

std::uint64_t Monomial::degree() const {
  std::uint64_t d = 0;
  for (Exponent e : exponents_) d += e;
  return d;
}

bool Monomial::isOne() const {
  return std::all_of(exponents_.begin(), exponents_.end(), [](Exponent e) { return e == 0; });
}

bool Monomial::divides(const Monomial& other) const {
  assert(size() == other.size());
  for (std::size_t i = 0; i < exponents_.size(); ++i) {
    if (exponents_[i] > other.exponents_[i]) return false;
  }
  return true;
}

Monomial operator*(const Monomial& a, const Monomial& b) {
  assert(a.size() == b.size());
  Monomial m = a;
  for (std::size_t i = 0; i < m.size(); ++i) m[i] += b[i];
  return m;
}

Monomial operator/(const Monomial& a, const Monomial& b) {
  assert(b.divides(a));
  Monomial m = a;
  for (std::size_t i = 0; i < m.size(); ++i) m[i] -= b[i];
  return m;
}

Monomial lcm(const Monomial& a, const Monomial& b) {
  assert(a.size() == b.size());
  Monomial m = a;
  for (std::size_t i = 0; i < m.size(); ++i) m[i] = std::max(a[i], b[i]);
  return m;
}

Monomial gcd(const Monomial& a, const Monomial& b) {
  assert(a.size() == b.size());
  Monomial m = a;
  for (std::size_t i = 0; i < m.size(); ++i) m[i] = std::min(a[i], b[i]);
  return m;
}

bool coprime(const Monomial& a, const Monomial& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] != 0 && b[i] != 0) return false;
  }
  return true;
}

}  // namespace sdfwb::algebra
