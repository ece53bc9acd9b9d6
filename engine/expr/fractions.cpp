#include "expr/fractions.h"

#include <algorithm>

#include "algebra/division.h"

namespace sdfwb::expr {

using algebra::Polynomial;
using algebra::Rational;

namespace {

unsigned at(const std::vector<unsigned>& powers, std::size_t i) { return i < powers.size() ? powers[i] : 0; }

}  // namespace

Polynomial FractionArithmetic::withFactors(Polynomial n, const std::vector<unsigned>& powers) const {
  for (std::size_t i = 0; i < powers.size(); ++i) {
    if (powers[i] > 0) n *= algebra::pow(factors_[i], powers[i]);
  }
  return n;
}

Fraction FractionArithmetic::negate(Fraction a) const {
  a.numerator = -a.numerator;
  return a;
}

Fraction FractionArithmetic::add(const Fraction& a, const Fraction& b) const {
  if (a.numerator.is_zero()) return b;
  if (b.numerator.is_zero()) return a;
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
  if (a.numerator.is_zero() || b.numerator.is_zero()) return constant(0);
  std::vector<unsigned> powers(std::max(a.powers.size(), b.powers.size()), 0);
  for (std::size_t i = 0; i < powers.size(); ++i) powers[i] = at(a.powers, i) + at(b.powers, i);
  return {a.numerator * b.numerator, powers};
}

std::pair<Rational, std::vector<unsigned>> FractionArithmetic::factorize(Polynomial p) {
  std::vector<unsigned> powers(factors_.size(), 0);
  for (std::size_t i = 0; i < factors_.size() && !p.is_constant(); ++i) {
    while (!p.is_constant()) {
      auto q = algebra::divide_exact(p, factors_[i]);
      if (!q) break;
      p = std::move(*q);
      ++powers[i];
    }
  }
  if (p.is_constant()) return {p.leading_coefficient(), powers};
  Polynomial factor = p.primitive();
  const Rational scale = p.leading_coefficient() / factor.leading_coefficient();
  factors_.push_back(std::move(factor));
  powers.push_back(1);
  return {scale, powers};
}

Fraction FractionArithmetic::quotient(const Polynomial& numerator, const Polynomial& denominator) {
  auto [scale, powers] = factorize(denominator);
  return {numerator / scale, std::move(powers)};
}

std::optional<Fraction> FractionArithmetic::divide(const Fraction& a, const Fraction& b) {
  auto [bNumerator, bDenominator] = reduce(b);
  if (bNumerator.is_zero()) return std::nullopt;
  Fraction inverse = quotient(std::move(bDenominator), bNumerator);
  return multiply(a, inverse);
}

std::pair<Polynomial, Polynomial> FractionArithmetic::reduce(Fraction a) const {
  if (a.numerator.is_zero()) return {a.numerator, ring_->one()};
  for (std::size_t i = 0; i < a.powers.size(); ++i) {
    while (a.powers[i] > 0) {
      auto q = algebra::divide_exact(a.numerator, factors_[i]);
      if (!q) break;
      a.numerator = std::move(*q);
      --a.powers[i];
    }
  }
  return {a.numerator, withFactors(ring_->one(), a.powers)};
}

}  // namespace sdfwb::expr
