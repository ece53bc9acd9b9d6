#include "algebra/rational_circles.h"

#include <algorithm>
#include <vector>

namespace sdfwb::algebra {

namespace {

// (c, s) when r is a * (v_c^2 + v_s^2 - 1) with c != s, else nullopt.
std::optional<std::pair<std::size_t, std::size_t>> unitCircle(const Polynomial& r) {
  if (r.termCount() != 3) return std::nullopt;
  std::vector<std::size_t> squares;
  std::optional<Rational> a;
  bool constant = false;
  for (const Term& t : r.terms()) {
    if (t.monomial.degree() == 0) {
      constant = true;
      continue;
    }
    if (t.monomial.degree() != 2) return std::nullopt;
    for (std::size_t v = 0; v < r.ring()->size(); ++v) {
      if (t.monomial[v] == 2) squares.push_back(v);
    }
    if (a && *a != t.coefficient) return std::nullopt;
    a = t.coefficient;
  }
  if (!constant || squares.size() != 2) return std::nullopt;
  const Ring& ring = *r.ring();
  if (!(r == *a * (pow(ring.var(squares[0]), 2) + pow(ring.var(squares[1]), 2) - 1))) return std::nullopt;
  return std::pair{squares[0], squares[1]};
}

// f(c = A/W, s = B/W) = hat / W^d: (hat, d) with d f's degree in (c, s).
std::pair<Polynomial, std::uint64_t> substituteCircle(const Polynomial& f, std::size_t c, std::size_t s,
                                                       const Polynomial& a, const Polynomial& b, const Polynomial& w) {
  std::uint64_t d = 0;
  for (const Term& t : f.terms()) d = std::max<std::uint64_t>(d, t.monomial[c] + t.monomial[s]);
  // Powers computed once each (recomputing them per term was most of the
  // substitution's cost).
  std::vector<Polynomial> powersA{f.ring()->one()}, powersB{f.ring()->one()}, powersW{f.ring()->one()};
  auto power = [](std::vector<Polynomial>& powers, const Polynomial& base, std::uint64_t k) -> const Polynomial& {
    while (powers.size() <= k) powers.push_back(powers.back() * base);
    return powers[k];
  };
  Polynomial hat = f.ring()->zero();
  for (const Term& t : f.terms()) {
    Monomial rest = t.monomial;
    rest[c] = 0;
    rest[s] = 0;
    hat += Polynomial(f.ring(), {Term{rest, t.coefficient}}) * power(powersA, a, t.monomial[c]) *
           power(powersB, b, t.monomial[s]) * power(powersW, w, d - t.monomial[c] - t.monomial[s]);
  }
  return {hat, d};
}

}  // namespace

std::optional<RationalParametrization> rationalCircles(const RationalParametrization& p) {
  RingPtr params = Ring::make(p.parameters);
  std::optional<std::pair<std::size_t, std::size_t>> circle;
  std::size_t which = 0;
  for (; which < p.relations.size() && !circle; ++which) circle = unitCircle(p.relations[which].inRing(params));
  if (!circle) return std::nullopt;
  --which;
  std::vector<std::string> taken = p.parameters;
  taken.insert(taken.end(), p.coordinates.begin(), p.coordinates.end());
  const std::string tName = internalVariableName("t", taken);
  std::vector<std::string> names = p.parameters;
  names.push_back(tName);
  RingPtr ring = Ring::make(names);
  const std::size_t c = circle->first, s = circle->second;
  const Polynomial t = ring->var(tName);
  const Polynomial a = 1 - t * t, b = 2 * t, w = 1 + t * t;

  std::vector<std::string> kept;
  for (std::size_t v = 0; v < p.parameters.size(); ++v) {
    if (v == c) kept.push_back(tName);
    else if (v != s) kept.push_back(p.parameters[v]);
  }
  RingPtr outRing = Ring::make(kept);
  RationalParametrization out{kept, p.coordinates, {}, {}, {}};
  for (std::size_t i = 0; i < p.numerators.size(); ++i) {
    auto [num, dn] = substituteCircle(p.numerators[i].inRing(ring), c, s, a, b, w);
    auto [den, dd] = p.denominators.empty() ? std::pair{ring->one(), std::uint64_t{0}}
                                            : substituteCircle(p.denominators[i].inRing(ring), c, s, a, b, w);
    // num / W^dn over den / W^dd.
    if (dn >= dd) den *= pow(w, dn - dd);
    else num *= pow(w, dd - dn);
    out.numerators.push_back(num.inRing(outRing));
    out.denominators.push_back(den.inRing(outRing));
  }
  for (std::size_t k = 0; k < p.relations.size(); ++k) {
    if (k == which) continue;
    Polynomial r = substituteCircle(p.relations[k].inRing(ring), c, s, a, b, w).first;
    if (!r.isZero()) out.relations.push_back(r.inRing(outRing));
  }
  if (std::optional<RationalParametrization> more = rationalCircles(out)) return more;
  return out;
}

}  // namespace sdfwb::algebra
