#include "algebra/division.h"

#include <stdexcept>

namespace sdfwb::algebra {

namespace {

DivisionResult divide_impl(const Polynomial& f, const std::vector<Polynomial>& divisors,
                           bool want_quotients) {
  const RingPtr& ring = f.ring();
  for (const Polynomial& g : divisors) {
    if (!(*g.ring() == *ring)) throw std::invalid_argument("divide: divisors from a different ring");
  }
  DivisionResult result{{}, ring->zero()};
  if (want_quotients) result.quotients.assign(divisors.size(), ring->zero());
  std::vector<Term> remainder_terms;
  Polynomial p = f;
  while (!p.is_zero()) {
    const Term lead = p.leading_term();
    bool divided = false;
    for (std::size_t i = 0; i < divisors.size() && !divided; ++i) {
      const Polynomial& g = divisors[i];
      if (g.is_zero() || !g.leading_monomial().divides(lead.monomial)) continue;
      Rational c = lead.coefficient / g.leading_coefficient();
      Monomial m = lead.monomial / g.leading_monomial();
      p -= multiply_by_term(g, c, m);
      if (want_quotients) result.quotients[i] += Polynomial(ring, {Term{m, c}});
      divided = true;
    }
    if (!divided) {
      // The leading term moves to the remainder; terms are produced in
      // decreasing order, so the list stays canonical.
      remainder_terms.push_back(lead);
      p -= Polynomial(ring, {lead});
    }
  }
  result.remainder = Polynomial(ring, std::move(remainder_terms));
  return result;
}

}  // namespace

DivisionResult divide(const Polynomial& f, const std::vector<Polynomial>& divisors) {
  return divide_impl(f, divisors, true);
}

Polynomial reduce(const Polynomial& f, const std::vector<Polynomial>& divisors) {
  return divide_impl(f, divisors, false).remainder;
}

std::optional<Polynomial> divide_exact(const Polynomial& f, const Polynomial& g) {
  if (g.is_zero()) throw std::domain_error("divide_exact: division by zero");
  DivisionResult r = divide(f, {g});
  if (!r.remainder.is_zero()) return std::nullopt;
  return std::move(r.quotients.front());
}

}  // namespace sdfwb::algebra
