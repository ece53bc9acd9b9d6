#include "algebra/division.h"

#include <stdexcept>

#include "algebra/division_image.h"
#include "algebra/flint_polynomial.h"

namespace sdfwb::algebra {

namespace {

DivisionResult divideImpl(const Polynomial& f, const std::vector<Polynomial>& divisors,
                           bool wantQuotients) {
  const RingPtr& ring = f.ring();
  for (const Polynomial& g : divisors) {
    if (!(*g.ring() == *ring)) throw std::invalid_argument("divide: divisors from a different ring");
  }
  DivisionResult result{{}, ring->zero()};
  if (wantQuotients) result.quotients.assign(divisors.size(), ring->zero());
  std::vector<Term> remainderTerms;
  Polynomial p = f;
  while (!p.isZero()) {
    const Term lead = p.leadingTerm();
    bool divided = false;
    for (std::size_t i = 0; i < divisors.size() && !divided; ++i) {
      const Polynomial& g = divisors[i];
      if (g.isZero() || !g.leadingMonomial().divides(lead.monomial)) continue;
      Rational c = lead.coefficient / g.leadingCoefficient();
      Monomial m = lead.monomial / g.leadingMonomial();
      p -= multiplyByTerm(g, c, m);
      if (wantQuotients) result.quotients[i] += Polynomial(ring, {Term{m, c}});
      divided = true;
    }
    if (!divided) {
      // The leading term moves to the remainder; terms are produced in
      // decreasing order, so the list stays canonical.
      remainderTerms.push_back(lead);
      p -= Polynomial(ring, {lead});
    }
  }
  result.remainder = Polynomial(ring, std::move(remainderTerms));
  return result;
}

}  // namespace

DivisionResult divide(const Polynomial& f, const std::vector<Polynomial>& divisors) {
  return divideImpl(f, divisors, true);
}

Polynomial reduce(const Polynomial& f, const std::vector<Polynomial>& divisors) {
  return divideImpl(f, divisors, false).remainder;
}

std::optional<Polynomial> divideExact(const Polynomial& f, const Polynomial& g) {
  if (g.isZero()) throw std::domain_error("divide_exact: division by zero");
  if (!(*g.ring() == *f.ring())) throw std::invalid_argument("divide_exact: polynomials from different rings");
  // FLINT's exact division refuses at once when g's degree in a variable
  // exceeds f's, and stops at the first term that cannot divide. The general
  // division above merges the whole rest of f at each step and runs to the
  // end: x^218 / (x + y + 1), not exact, took 51 s there (a fuzzed formula),
  // and a 3000-term numerator divided by z^24 one z at a time took a second.
  // Before that first term FLINT's quotient can still grow without bound,
  // which a univariate image rules out first (division_image.h).
  if (imageRefutesDivision(f, g)) return std::nullopt;
  return flint::divideExact(f, g);
}

}  // namespace sdfwb::algebra
