#include "algebra/gb_homogenize.h"

namespace sdfwb::algebra::gb {

RingPtr homogenizedRing(const Ring& ring) {
  const std::size_t n = ring.size();
  std::vector<std::string> names = ring.variables();
  names.push_back(internalVariableName("h", names));
  return Ring::make(names, MonomialOrder::weighted(std::vector<std::int64_t>(n + 1, 1),
                                                   MonomialOrder::block({{n, ring.order()}, {1, MonomialOrder::lex()}})));
}

Polynomial homogenize(const Polynomial& f, const RingPtr& homogeneous) {
  const std::uint64_t degree = f.totalDegree();
  std::vector<Term> terms;
  terms.reserve(f.termCount());
  for (const Term& t : f.terms()) {
    std::vector<Exponent> e = t.monomial.exponents();
    e.push_back(static_cast<Exponent>(degree - t.monomial.degree()));
    terms.push_back(Term{Monomial(std::move(e)), t.coefficient});
  }
  return Polynomial(homogeneous, std::move(terms));
}

Polynomial dehomogenize(const Polynomial& f, const RingPtr& ring) {
  std::vector<Term> terms;
  terms.reserve(f.termCount());
  for (const Term& t : f.terms()) {
    std::vector<Exponent> e = t.monomial.exponents();
    e.pop_back();
    terms.push_back(Term{Monomial(std::move(e)), t.coefficient});
  }
  return Polynomial(ring, std::move(terms));
}

}  // namespace sdfwb::algebra::gb
