#include "algebra/gb_convert.h"

namespace sdfwb::algebra::gb {

IntPoly toIntegerPoly(const Polynomial& p, const Layout& layout, mpz_class* denominator) {
  const std::size_t stride = layout.stride();
  mpz_class den = 1;
  for (const Term& t : p.terms()) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), t.coefficient.get_den_mpz_t());
  IntPoly out;
  out.mons.resize(p.termCount() * stride);
  out.coeffs.resize(p.termCount());
  for (std::size_t i = 0; i < p.termCount(); ++i) {
    const Term& t = p.terms()[i];
    Word* m = out.mons.data() + i * stride;
    for (std::size_t v = 0; v < layout.vars(); ++v) m[layout.keys() + v] = static_cast<Word>(t.monomial[v]);
    layout.encodeKeys(m);
    mpz_divexact(out.coeffs[i].get_mpz_t(), den.get_mpz_t(), t.coefficient.get_den_mpz_t());
    out.coeffs[i] *= t.coefficient.get_num();
  }
  if (denominator) *denominator = den;
  return out;
}

FmpzPoly toFmpzPoly(const IntPoly& p) {
  FmpzPoly out;
  out.mons = p.mons;
  out.coeffs.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) fmpz_set_mpz(out.coeffs[i].v, p.coeffs[i].get_mpz_t());
  out.sugar = p.sugar;
  return out;
}

Polynomial toPolynomial(const IntPoly& p, const Layout& layout, const RingPtr& ring, bool monic,
                         const mpz_class* divisor) {
  const std::size_t stride = layout.stride();
  std::vector<Term> terms;
  terms.reserve(p.size());
  mpz_class den = 1;
  if (monic && !p.empty()) den = p.coeffs.front();
  if (divisor) den *= *divisor;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Monomial m(layout.vars());
    const Word* e = layout.exponents(p.mon(i, stride));
    for (std::size_t v = 0; v < layout.vars(); ++v) m[v] = static_cast<Exponent>(e[v]);
    Rational c(p.coeffs[i], den);
    c.canonicalize();
    terms.push_back(Term{std::move(m), std::move(c)});
  }
  return Polynomial(ring, std::move(terms));
}

}  // namespace sdfwb::algebra::gb
