#include "expr/fractions.h"

#include <algorithm>
#include <limits>

#include "algebra/division.h"

namespace sdfwb::expr {

using algebra::Polynomial;
using algebra::Rational;

namespace {

unsigned at(const std::vector<unsigned>& powers, std::size_t i) { return i < powers.size() ? powers[i] : 0; }

void checkDegree(std::uint64_t degree) {
  if (degree > kMaxExpandedDegree) {
    throw TooLargeToExpand("the expanded polynomial would have degree " + std::to_string(degree) + " (at most " +
                           std::to_string(kMaxExpandedDegree) + ")");
  }
}

// Machine words in the coefficients, numerators and denominators.
std::uint64_t coefficientLimbs(const Polynomial& p) {
  std::uint64_t limbs = 0;
  for (const algebra::Term& t : p.terms()) {
    limbs += mpz_size(t.coefficient.get_num_mpz_t()) + mpz_size(t.coefficient.get_den_mpz_t());
  }
  return limbs;
}

}  // namespace

Polynomial FractionArithmetic::product(const Polynomial& a, const Polynomial& b) const {
  checkDegree(a.totalDegree() + b.totalDegree());
  // A term product costs a monomial sum and a rational product: count both,
  // the latter by limb products (large binomial coefficients dominate (x+1)^n).
  work_ += static_cast<std::uint64_t>(a.termCount()) * b.termCount() +
           coefficientLimbs(a) * coefficientLimbs(b) / 16;
  if (work_ > kMaxExpansionWork) {
    throw TooLargeToExpand("the formula is too large to expand exactly (more than " +
                           std::to_string(kMaxExpansionWork) + " units of work: term and coefficient products)");
  }
  return a * b;
}

// Factor powers multiply one factor at a time, so that each product is checked.
Polynomial FractionArithmetic::withFactors(Polynomial n, const std::vector<unsigned>& powers) const {
  for (std::size_t i = 0; i < powers.size(); ++i) {
    checkDegree(n.totalDegree() + std::uint64_t(powers[i]) * factors_[i].totalDegree());
    for (unsigned k = 0; k < powers[i]; ++k) n = product(n, factors_[i]);
  }
  return n;
}

Fraction FractionArithmetic::negate(Fraction a) const {
  a.numerator = -a.numerator;
  return a;
}

Fraction FractionArithmetic::add(const Fraction& a, const Fraction& b) const {
  if (a.numerator.isZero()) return b;
  if (b.numerator.isZero()) return a;
  std::vector<unsigned> common(std::max(a.powers.size(), b.powers.size()), 0);
  std::vector<unsigned> missingA(common.size()), missingB(common.size());
  for (std::size_t i = 0; i < common.size(); ++i) {
    common[i] = std::max(at(a.powers, i), at(b.powers, i));
    missingA[i] = common[i] - at(a.powers, i);
    missingB[i] = common[i] - at(b.powers, i);
  }
  return {withFactors(a.numerator, missingA) + withFactors(b.numerator, missingB), common};
}

Fraction FractionArithmetic::multiply(const Fraction& a, const Fraction& b) const {
  if (a.numerator.isZero() || b.numerator.isZero()) return constant(0);
  std::vector<unsigned> powers(std::max(a.powers.size(), b.powers.size()), 0);
  for (std::size_t i = 0; i < powers.size(); ++i) {
    checkDegree(std::uint64_t(at(a.powers, i)) + at(b.powers, i));
    powers[i] = at(a.powers, i) + at(b.powers, i);
  }
  return {product(a.numerator, b.numerator), powers};
}

// By f, f^2, f^4, ... while they divide, then back down the same powers,
// each at most once: about 2 log2 k divisions. Dividing by f one power at a
// time cost a division per power, each as dear as p's degree (parsing
// x^-2 + x^-60000 took 19 s, past any --timeout, before saying it is no
// polynomial).
std::pair<Polynomial, unsigned> FractionArithmetic::divideOut(Polynomial p, const Polynomial& f,
                                                              unsigned limit) const {
  std::vector<Polynomial> ladder;  // f^(2^j), each divided out once on the way up
  unsigned count = 0;
  for (Polynomial power = f; ladder.size() < 32;) {
    const unsigned step = 1u << ladder.size();
    if (step > limit - count) break;
    auto q = algebra::divideExact(p, power);
    if (!q) break;
    p = std::move(*q);
    count += step;
    ladder.push_back(power);
    if (2 * power.totalDegree() > p.totalDegree()) break;  // its square cannot divide what is left
    power = product(power, power);
  }
  // what is left of the multiplicity is below the last step: one bit each
  for (std::size_t j = ladder.size(); j-- > 0;) {
    const unsigned step = 1u << j;
    if (step > limit - count) continue;
    if (auto q = algebra::divideExact(p, ladder[j])) {
      p = std::move(*q);
      count += step;
    }
  }
  return {std::move(p), count};
}

std::pair<Rational, std::vector<unsigned>> FractionArithmetic::factorize(Polynomial p) {
  std::vector<unsigned> powers(factors_.size(), 0);
  for (std::size_t i = 0; i < factors_.size() && !p.isConstant(); ++i) {
    auto [rest, k] = divideOut(std::move(p), factors_[i], std::numeric_limits<unsigned>::max());
    p = std::move(rest);
    powers[i] = k;
  }
  if (p.isConstant()) return {p.leadingCoefficient(), powers};
  Polynomial factor = p.primitive();
  const Rational scale = p.leadingCoefficient() / factor.leadingCoefficient();
  factors_.push_back(std::move(factor));
  powers.push_back(1);
  return {scale, powers};
}

Fraction FractionArithmetic::quotient(const Polynomial& numerator, const Polynomial& denominator) {
  auto [scale, powers] = factorize(denominator);
  return {numerator / scale, std::move(powers)};
}

std::optional<Fraction> FractionArithmetic::divide(const Fraction& a, const Fraction& b) {
  auto [bNumerator, bDenominator] = expand(cancel(b));
  if (bNumerator.isZero()) return std::nullopt;
  Fraction inverse = quotient(std::move(bDenominator), bNumerator);
  return multiply(a, inverse);
}

Fraction FractionArithmetic::cancel(Fraction a) const {
  if (a.numerator.isZero()) return {a.numerator, {}};
  for (std::size_t i = 0; i < a.powers.size(); ++i) {
    auto [rest, k] = divideOut(std::move(a.numerator), factors_[i], a.powers[i]);
    a.numerator = std::move(rest);
    a.powers[i] -= k;
  }
  return a;
}

std::pair<Polynomial, Polynomial> FractionArithmetic::expand(const Fraction& a) const {
  return {a.numerator, withFactors(ring_->one(), a.powers)};
}

}  // namespace sdfwb::expr
