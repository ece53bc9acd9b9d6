#pragma once
// Exact rational functions whose denominators stay factored, for the
// conversions to algebra (to_algebra.h, trig.h).
//
// A Fraction is numerator / prod(factor_i ^ power_i) over a table of factors
// (primitive integer polynomials with positive leading coefficient, never
// constant). Sums take the least common multiple of the factored denominators
// rather than their product, so x/q + y/q stays over q, and the half-angle
// denominators (1 + t^2)^k do not multiply up. The denominator expand()
// returns for a cancelled fraction is therefore the lcm of the denominators
// the formula divides by, with common factors cancelled where a factor
// divides the numerator.

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

#include "algebra/polynomial.h"

namespace sdfwb::expr {

// Expanding products can take unbounded time and memory ((x+y+1)^600) and
// exponents must stay far from their type's range ((x^65536)^65536 would wrap
// at 2^32): every product is checked before it is computed.
inline constexpr std::uint64_t kMaxExpandedDegree = std::uint64_t(1) << 20;
// Work over one conversion, a few seconds: one unit per term-by-term product
// plus one per 16 products of coefficient limbs. A fuzz build (AddressSanitizer
// and coverage make each unit some 40 times slower) refuses at a fortieth of
// it, so an input that reaches the limit ends within the fuzzer's timeout and
// the refusal is what the fuzzer explores, as in the product.
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
inline constexpr std::uint64_t kMaxExpansionWork = 20'000'000 / 40;
#else
inline constexpr std::uint64_t kMaxExpansionWork = 20'000'000;
#endif

// Thrown by FractionArithmetic when a product would exceed either limit; the
// graph conversion reports it with the location of the operation.
class TooLargeToExpand : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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

  // Cancels the factors that divide the numerator: what is left is a
  // polynomial exactly when every power is 0 (factors are never constant).
  Fraction cancel(Fraction a) const;
  // {numerator, denominator} of a cancelled fraction, the denominator the
  // product of its factors (1 when there is none); throws TooLargeToExpand.
  std::pair<algebra::Polynomial, algebra::Polynomial> expand(const Fraction& a) const;

 private:
  // a * b after checking the degree and the work left (throws TooLargeToExpand).
  algebra::Polynomial product(const algebra::Polynomial& a, const algebra::Polynomial& b) const;
  // Multiplies n by prod(factor_i ^ powers_i).
  algebra::Polynomial withFactors(algebra::Polynomial n, const std::vector<unsigned>& powers) const;
  // {p / f^k, k} for the largest k <= limit with f^k dividing p.
  std::pair<algebra::Polynomial, unsigned> divideOut(algebra::Polynomial p, const algebra::Polynomial& f,
                                                     unsigned limit) const;
  // Splits p (nonzero) into a rational constant times a product of factors,
  // reusing known factors that divide it and adding the rest as a new one.
  std::pair<algebra::Rational, std::vector<unsigned>> factorize(algebra::Polynomial p);

  algebra::RingPtr ring_;
  std::vector<algebra::Polynomial> factors_;
  mutable std::uint64_t work_ = 0;  // term products so far
};

}  // namespace sdfwb::expr
