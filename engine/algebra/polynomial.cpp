#include "algebra/polynomial.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace sdfwb::algebra {

namespace {

// Merges two canonical term lists (sign = +1 adds b, -1 subtracts it).
std::vector<Term> mergeTerms(const Ring& ring, std::vector<Term>&& a, const std::vector<Term>& b,
                              int sign) {
  std::vector<Term> out;
  out.reserve(a.size() + b.size());
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    int c = ring.compare(a[i].monomial, b[j].monomial);
    if (c > 0) {
      out.push_back(std::move(a[i++]));
    } else if (c < 0) {
      out.push_back(b[j]);
      if (sign < 0) out.back().coefficient = -out.back().coefficient;
      ++j;
    } else {
      Term t = std::move(a[i++]);
      if (sign > 0) {
        t.coefficient += b[j].coefficient;
      } else {
        t.coefficient -= b[j].coefficient;
      }
      ++j;
      if (sgn(t.coefficient) != 0) out.push_back(std::move(t));
    }
  }
  for (; i < a.size(); ++i) out.push_back(std::move(a[i]));
  for (; j < b.size(); ++j) {
    out.push_back(b[j]);
    if (sign < 0) out.back().coefficient = -out.back().coefficient;
  }
  return out;
}

}  // namespace

Polynomial::Polynomial(RingPtr ring) : ring_(std::move(ring)) {
  if (!ring_) throw std::invalid_argument("polynomial: null ring");
}

Polynomial::Polynomial(RingPtr ring, std::vector<Term> terms) : Polynomial(std::move(ring)) {
  for (const Term& t : terms) {
    if (t.monomial.size() != ring_->size()) {
      throw std::invalid_argument("polynomial: monomial with " + std::to_string(t.monomial.size()) +
                                  " exponents in a ring of " + std::to_string(ring_->size()) +
                                  " variables");
    }
  }
  const Ring& r = *ring_;
  std::sort(terms.begin(), terms.end(),
            [&r](const Term& a, const Term& b) { return r.compare(a.monomial, b.monomial) > 0; });
  for (Term& t : terms) {
    if (!terms_.empty() && terms_.back().monomial == t.monomial) {
      terms_.back().coefficient += t.coefficient;
      if (sgn(terms_.back().coefficient) == 0) terms_.pop_back();
    } else if (sgn(t.coefficient) != 0) {
      terms_.push_back(std::move(t));
    }
  }
}

bool Polynomial::isConstant() const {
  return terms_.empty() || (terms_.size() == 1 && terms_.front().monomial.isOne());
}

const Term& Polynomial::leadingTerm() const {
  if (terms_.empty()) throw std::logic_error("leading term of the zero polynomial");
  return terms_.front();
}

std::uint64_t Polynomial::totalDegree() const {
  std::uint64_t d = 0;
  for (const Term& t : terms_) d = std::max(d, t.monomial.degree());
  return d;
}

Exponent Polynomial::degreeIn(std::size_t variable) const {
  Exponent d = 0;
  for (const Term& t : terms_) d = std::max(d, t.monomial[variable]);
  return d;
}

bool Polynomial::containsVariable(std::size_t variable) const { return degreeIn(variable) > 0; }

Polynomial Polynomial::monic() const {
  if (isZero()) return *this;
  Polynomial p = *this;
  Rational lc = leadingCoefficient();
  for (Term& t : p.terms_) t.coefficient /= lc;
  return p;
}

Polynomial Polynomial::primitive() const {
  if (isZero()) return *this;
  // Multiply by the lcm of the denominators, then divide by the gcd of the
  // numerators.
  Integer den = 1, num = 0;
  for (const Term& t : terms_) {
    mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), t.coefficient.get_den_mpz_t());
    mpz_gcd(num.get_mpz_t(), num.get_mpz_t(), t.coefficient.get_num_mpz_t());
  }
  Rational scale(den, num);
  scale.canonicalize();
  if (sgn(leadingCoefficient()) < 0) scale = -scale;
  Polynomial p = *this;
  for (Term& t : p.terms_) t.coefficient *= scale;
  return p;
}

Polynomial Polynomial::inRing(const RingPtr& target) const {
  if (*target == *ring_) return Polynomial(target, terms_);
  std::vector<std::size_t> map(ring_->size());
  for (std::size_t i = 0; i < ring_->size(); ++i) {
    std::optional<std::size_t> j = target->indexOf(ring_->variable(i));
    if (!j) {
      if (containsVariable(i)) {
        throw std::invalid_argument("variable '" + ring_->variable(i) +
                                    "' does not exist in the target ring");
      }
      map[i] = target->size();  // unused: exponent is zero in every term
    } else {
      map[i] = *j;
    }
  }
  std::vector<Term> terms;
  terms.reserve(terms_.size());
  for (const Term& t : terms_) {
    Monomial m(target->size());
    for (std::size_t i = 0; i < ring_->size(); ++i) {
      if (t.monomial[i] != 0) m[map[i]] = t.monomial[i];
    }
    terms.push_back(Term{std::move(m), t.coefficient});
  }
  return Polynomial(target, std::move(terms));
}

void Polynomial::checkSameRing(const Polynomial& other, const char* operation) const {
  if (!(*ring_ == *other.ring_)) {
    throw std::invalid_argument(std::string(operation) + " of polynomials from different rings");
  }
}

Polynomial Polynomial::operator-() const {
  Polynomial p = *this;
  for (Term& t : p.terms_) t.coefficient = -t.coefficient;
  return p;
}

Polynomial& Polynomial::operator+=(const Polynomial& other) {
  checkSameRing(other, "sum");
  terms_ = mergeTerms(*ring_, std::move(terms_), other.terms_, +1);
  return *this;
}

Polynomial& Polynomial::operator-=(const Polynomial& other) {
  checkSameRing(other, "difference");
  terms_ = mergeTerms(*ring_, std::move(terms_), other.terms_, -1);
  return *this;
}

Polynomial& Polynomial::operator*=(const Polynomial& other) {
  checkSameRing(other, "product");
  // One sorted partial product per term of the shorter factor (monomial
  // orders respect multiplication), merged like a binary counter: a part of
  // level k holds 2^k partial products, and two parts of one level merge at
  // once. The same balanced merges as merging all parts pairwise, but at most
  // one part per level is alive, so memory follows the result's size, not
  // the number of term products (all of them at once were gigabytes for a
  // product the expansion budget allows, (x+y+1)^600).
  const Polynomial& small = terms_.size() <= other.terms_.size() ? *this : other;
  const Polynomial& large = terms_.size() <= other.terms_.size() ? other : *this;
  std::vector<std::pair<std::vector<Term>, int>> parts;  // (terms, level), levels decreasing
  for (const Term& s : small.terms_) {
    std::vector<Term> part;
    part.reserve(large.terms_.size());
    for (const Term& l : large.terms_) {
      part.push_back(Term{s.monomial * l.monomial, s.coefficient * l.coefficient});
    }
    int level = 0;
    while (!parts.empty() && parts.back().second == level) {
      part = mergeTerms(*ring_, std::move(parts.back().first), part, +1);
      parts.pop_back();
      ++level;
    }
    parts.emplace_back(std::move(part), level);
  }
  while (parts.size() > 1) {
    std::vector<Term> last = std::move(parts.back().first);
    parts.pop_back();
    parts.back().first = mergeTerms(*ring_, std::move(parts.back().first), last, +1);
  }
  terms_ = parts.empty() ? std::vector<Term>{} : std::move(parts.front().first);
  return *this;
}

Polynomial& Polynomial::operator*=(const Rational& factor) {
  if (sgn(factor) == 0) {
    terms_.clear();
  } else {
    for (Term& t : terms_) t.coefficient *= factor;
  }
  return *this;
}

Polynomial& Polynomial::operator/=(const Rational& divisor) {
  if (sgn(divisor) == 0) throw std::domain_error("polynomial divided by zero");
  for (Term& t : terms_) t.coefficient /= divisor;
  return *this;
}

bool operator==(const Polynomial& a, const Polynomial& b) {
  return *a.ring_ == *b.ring_ && a.terms_ == b.terms_;
}

Polynomial operator+(Polynomial a, const Polynomial& b) { return a += b; }
Polynomial operator-(Polynomial a, const Polynomial& b) { return a -= b; }
Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  Polynomial p = a;
  return p *= b;
}
Polynomial operator+(Polynomial a, const Rational& b) { return a += a.ring()->constant(b); }
Polynomial operator+(const Rational& a, Polynomial b) { return b += b.ring()->constant(a); }
Polynomial operator-(Polynomial a, const Rational& b) { return a -= a.ring()->constant(b); }
Polynomial operator-(const Rational& a, const Polynomial& b) { return b.ring()->constant(a) - b; }
Polynomial operator*(Polynomial a, const Rational& b) { return a *= b; }
Polynomial operator*(const Rational& a, Polynomial b) { return b *= a; }
Polynomial operator/(Polynomial a, const Rational& b) { return a /= b; }

Polynomial multiplyByTerm(const Polynomial& a, const Rational& coefficient,
                            const Monomial& monomial) {
  if (sgn(coefficient) == 0) return a.ring()->zero();
  std::vector<Term> terms;
  terms.reserve(a.termCount());
  for (const Term& t : a.terms()) terms.push_back(Term{t.monomial * monomial, t.coefficient * coefficient});
  return Polynomial(a.ring(), std::move(terms));
}

Polynomial pow(const Polynomial& base, unsigned exponent) {
  if (exponent == 0) return base.ring()->one();
  // The first factor is taken as it is, not multiplied into 1.
  std::optional<Polynomial> result;
  Polynomial square = base;
  while (exponent > 0) {
    if (exponent & 1u) {
      if (result) {
        *result *= square;
      } else {
        result = square;
      }
    }
    exponent >>= 1;
    if (exponent > 0) square *= square;
  }
  return std::move(*result);
}

Polynomial substitute(const Polynomial& p, const std::vector<Polynomial>& values) {
  if (values.size() != p.ring()->size()) {
    throw std::invalid_argument("substitute: " + std::to_string(values.size()) + " values for " +
                                std::to_string(p.ring()->size()) + " variables");
  }
  if (values.empty()) throw std::invalid_argument("substitute: no target ring");
  const RingPtr& target = values.front().ring();
  for (const Polynomial& v : values) {
    if (!(*v.ring() == *target)) throw std::invalid_argument("substitute: values from different rings");
  }
  // powers[i][k] = values[i]^k, built on demand.
  std::vector<std::vector<Polynomial>> powers(values.size());
  auto power = [&](std::size_t i, Exponent k) -> const Polynomial& {
    auto& list = powers[i];
    if (list.empty()) list.push_back(target->one());
    while (list.size() <= k) list.push_back(list.back() * values[i]);
    return list[k];
  };
  Polynomial sum = target->zero();
  for (const Term& t : p.terms()) {
    Polynomial product = target->constant(t.coefficient);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (t.monomial[i] != 0) product *= power(i, t.monomial[i]);
    }
    sum += product;
  }
  return sum;
}

Rational evaluate(const Polynomial& p, const std::vector<Rational>& point) {
  if (point.size() != p.ring()->size()) {
    throw std::invalid_argument("evaluate: " + std::to_string(point.size()) + " values for " +
                                std::to_string(p.ring()->size()) + " variables");
  }
  Rational sum = 0;
  for (const Term& t : p.terms()) {
    Rational product = t.coefficient;
    for (std::size_t i = 0; i < point.size(); ++i) {
      for (Exponent k = 0; k < t.monomial[i]; ++k) product *= point[i];
    }
    sum += product;
  }
  return sum;
}

Polynomial derivative(const Polynomial& p, std::size_t variable) {
  std::vector<Term> terms;
  for (const Term& t : p.terms()) {
    if (t.monomial[variable] == 0) continue;
    Term d = t;
    d.coefficient *= Rational(static_cast<unsigned long>(t.monomial[variable]));
    d.monomial[variable] -= 1;
    terms.push_back(std::move(d));
  }
  return Polynomial(p.ring(), std::move(terms));
}

}  // namespace sdfwb::algebra
