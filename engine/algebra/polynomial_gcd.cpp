#include "algebra/polynomial_gcd.h"

#include "algebra/division.h"
#include "algebra/ideal_operations.h"

#include <stdexcept>

namespace sdfwb::algebra {

namespace {

// The only variable occurring in p, or -1 if none or several.
long single_variable(const Polynomial& p) {
  long found = -1;
  for (std::size_t v = 0; v < p.ring()->size(); ++v) {
    if (!p.contains_variable(v)) continue;
    if (found >= 0) return -2;
    found = static_cast<long>(v);
  }
  return found;
}

// Euclid's algorithm in Q[x]; division by one polynomial is univariate
// division whatever the monomial order, since all orders agree on powers of
// one variable.
Polynomial univariate_gcd(Polynomial a, Polynomial b) {
  while (!b.is_zero()) {
    Polynomial r = reduce(a, {b});
    a = std::move(b);
    b = r.monic();
  }
  return a.primitive();
}

}  // namespace

Polynomial gcd(const Polynomial& a, const Polynomial& b) {
  if (!(*a.ring() == *b.ring())) throw std::invalid_argument("gcd of polynomials from different rings");
  if (a.is_zero()) return b.primitive();
  if (b.is_zero()) return a.primitive();
  if (a.is_constant() || b.is_constant()) return a.ring()->one();
  if (divide_exact(a, b)) return b.primitive();
  if (divide_exact(b, a)) return a.primitive();
  long va = single_variable(a), vb = single_variable(b);
  if (va >= 0 && va == vb) return univariate_gcd(a, b);
  // General case: lcm generates <a> ∩ <b>; gcd = a*b / lcm.
  Polynomial l = lcm(a, b);
  std::optional<Polynomial> g = divide_exact(a * b, l);
  if (!g) throw std::logic_error("gcd: lcm does not divide the product");
  return g->primitive();
}

Polynomial lcm(const Polynomial& a, const Polynomial& b) {
  if (!(*a.ring() == *b.ring())) throw std::invalid_argument("lcm of polynomials from different rings");
  if (a.is_zero() || b.is_zero()) return a.ring()->zero();
  if (a.is_constant()) return b.primitive();
  if (b.is_constant()) return a.primitive();
  if (divide_exact(a, b)) return a.primitive();
  if (divide_exact(b, a)) return b.primitive();
  long va = single_variable(a), vb = single_variable(b);
  if (va >= 0 && va == vb) {
    std::optional<Polynomial> l = divide_exact(a * b, univariate_gcd(a, b));
    return l->primitive();
  }
  GroebnerResult r = intersection(Ideal(a.ring(), {a}), Ideal(a.ring(), {b}));
  if (!r.ok() || r.basis.size() != 1) throw std::logic_error("lcm: intersection of principal ideals is not principal");
  return r.basis.front().primitive();
}

}  // namespace sdfwb::algebra
