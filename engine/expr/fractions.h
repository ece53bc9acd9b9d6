#pragma once
// Exact rational functions whose denominators stay factored, for the
// conversions to algebra (to_algebra.h, trig.h).
//
// A Fraction is numerator / prod(factor_i ^ power_i) over a table of factors
// (primitive integer polynomials with positive leading coefficient, never
// constant). Sums take the least common multiple of the factored denominators
// rather than their product, so x/q + y/q stays over q, and the half-angle
// denominators (1 + t^2)^k do not multiply up. The denominator returned by
// reduce() is therefore the lcm of the denominators the formula divides by,
// with common factors cancelled where a factor divides the numerator.

#include <optional>
#include <vector>

#include "algebra/polynomial.h"

namespace sdfwb::expr {

struct Fraction {
  algebra::Polynomial numerator;
  std::vector<unsigned> powers;  // by factor index; missing entries are 0
};

class FractionArithmetic {
 public:
  explicit FractionArithmetic(algebra::RingPtr ring) : ring_(std::move(ring)) {}

  const algebra::RingPtr& ring() const { return ring_; }

  Fraction constant(const algebra::Rational& value) const { return {ring_->constant(value), {}}; }
  Fraction polynomial(algebra::Polynomial p) const { return {std::move(p), {}}; }
  // numerator / denominator (denominator nonzero).
  Fraction quotient(const algebra::Polynomial& numerator, const algebra::Polynomial& denominator);

  Fraction negate(Fraction a) const;
  Fraction add(const Fraction& a, const Fraction& b) const;
  Fraction subtract(const Fraction& a, const Fraction& b) const { return add(a, negate(b)); }
  Fraction multiply(const Fraction& a, const Fraction& b) const;
  // std::nullopt when b is zero.
  std::optional<Fraction> divide(const Fraction& a, const Fraction& b);

  // Cancels factors that divide the numerator; returns {numerator, denominator}
  // with the denominator a product of factors (1 when there is none).
  std::pair<algebra::Polynomial, algebra::Polynomial> reduce(Fraction a) const;

 private:
  // Multiplies n by prod(factor_i ^ powers_i).
  algebra::Polynomial withFactors(algebra::Polynomial n, const std::vector<unsigned>& powers) const;
  // Splits p (nonzero) into a rational constant times a product of factors,
  // reusing known factors that divide it and adding the rest as a new one.
  std::pair<algebra::Rational, std::vector<unsigned>> factorize(algebra::Polynomial p);

  algebra::RingPtr ring_;
  std::vector<algebra::Polynomial> factors_;
};

}  // namespace sdfwb::expr
