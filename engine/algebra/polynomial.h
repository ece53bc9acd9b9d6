#pragma once
// Sparse polynomials with rational coefficients over a Ring.
//
// Canonical form: terms sorted by the ring's order, largest first, no zero
// coefficients, no repeated monomials. Two polynomials are equal iff their
// term lists are equal. Arithmetic between polynomials requires equal rings
// (Ring's operator==) and throws std::invalid_argument otherwise; move a
// polynomial to another ring with inRing.
//
// There is no operator^ for powers: C++ gives ^ a lower precedence than + and
// -, so "x^2 + 1" would silently mean x^(2+1). Use pow(x, 2).

#include "algebra/monomial.h"
#include "algebra/rational.h"
#include "algebra/ring.h"

#include <concepts>
#include <iosfwd>
#include <string>
#include <vector>

namespace sdfwb::algebra {

struct Term {
  Monomial monomial;
  Rational coefficient;
  friend bool operator==(const Term&, const Term&) = default;
};

class Polynomial {
 public:
  /// The zero polynomial of `ring`.
  explicit Polynomial(RingPtr ring);
  /// Terms in any order; like monomials are combined and zeros dropped. Each
  /// monomial must have ring->size() exponents.
  Polynomial(RingPtr ring, std::vector<Term> terms);

  const RingPtr& ring() const { return ring_; }
  const std::vector<Term>& terms() const { return terms_; }
  std::size_t termCount() const { return terms_.size(); }
  bool isZero() const { return terms_.empty(); }
  /// Zero or a nonzero constant.
  bool isConstant() const;

  // Leading data under the ring's order; all require a nonzero polynomial
  // (std::logic_error otherwise).
  const Term& leadingTerm() const;
  const Monomial& leadingMonomial() const { return leadingTerm().monomial; }
  const Rational& leadingCoefficient() const { return leadingTerm().coefficient; }
  const std::vector<Exponent>& leadingExponent() const { return leadingMonomial().exponents(); }

  /// Total degree (0 for the zero polynomial).
  std::uint64_t totalDegree() const;
  /// Largest exponent of `variable` in any term.
  Exponent degreeIn(std::size_t variable) const;
  /// True if `variable` occurs in some term.
  bool containsVariable(std::size_t variable) const;

  /// Divided by its leading coefficient (zero stays zero).
  Polynomial monic() const;
  /// Scaled by a nonzero rational to integer coefficients with gcd 1 and a
  /// positive leading coefficient (zero stays zero).
  Polynomial primitive() const;

  /// The same polynomial in another ring, variables matched by name; terms
  /// are re-sorted by the target's order. Throws std::invalid_argument naming
  /// the variable when one that occurs here is missing from `target`.
  Polynomial inRing(const RingPtr& target) const;

  /// Printed so that it reads back: "x^2 - 3/2*x*y + 1", "0".
  std::string toString() const;

  Polynomial operator-() const;
  Polynomial& operator+=(const Polynomial& other);
  Polynomial& operator-=(const Polynomial& other);
  Polynomial& operator*=(const Polynomial& other);
  Polynomial& operator*=(const Rational& factor);
  /// Division by a nonzero constant (std::domain_error for zero).
  Polynomial& operator/=(const Rational& divisor);

  friend bool operator==(const Polynomial& a, const Polynomial& b);

 private:
  void checkSameRing(const Polynomial& other, const char* operation) const;

  RingPtr ring_;
  std::vector<Term> terms_;
};

// Arithmetic; integers and rationals convert to constants of the other
// operand's ring.
Polynomial operator+(Polynomial a, const Polynomial& b);
Polynomial operator-(Polynomial a, const Polynomial& b);
Polynomial operator*(const Polynomial& a, const Polynomial& b);
Polynomial operator+(Polynomial a, const Rational& b);
Polynomial operator+(const Rational& a, Polynomial b);
Polynomial operator-(Polynomial a, const Rational& b);
Polynomial operator-(const Rational& a, const Polynomial& b);
Polynomial operator*(Polynomial a, const Rational& b);
Polynomial operator*(const Rational& a, Polynomial b);
Polynomial operator/(Polynomial a, const Rational& b);
// Integer operands (any integral type up to long). Floating-point operands
// are rejected at compile time: 0.1 as a double is not 1/10.
template <std::integral I> Polynomial operator+(Polynomial a, I b) { return std::move(a) + Rational(static_cast<long>(b)); }
template <std::integral I> Polynomial operator+(I a, Polynomial b) { return Rational(static_cast<long>(a)) + std::move(b); }
template <std::integral I> Polynomial operator-(Polynomial a, I b) { return std::move(a) - Rational(static_cast<long>(b)); }
template <std::integral I> Polynomial operator-(I a, const Polynomial& b) { return Rational(static_cast<long>(a)) - b; }
template <std::integral I> Polynomial operator*(Polynomial a, I b) { return std::move(a) * Rational(static_cast<long>(b)); }
template <std::integral I> Polynomial operator*(I a, Polynomial b) { return Rational(static_cast<long>(a)) * std::move(b); }
template <std::integral I> Polynomial operator/(Polynomial a, I b) { return std::move(a) / Rational(static_cast<long>(b)); }
template <std::floating_point F> Polynomial operator+(Polynomial, F) = delete;
template <std::floating_point F> Polynomial operator+(F, Polynomial) = delete;
template <std::floating_point F> Polynomial operator-(Polynomial, F) = delete;
template <std::floating_point F> Polynomial operator-(F, const Polynomial&) = delete;
template <std::floating_point F> Polynomial operator*(Polynomial, F) = delete;
template <std::floating_point F> Polynomial operator*(F, Polynomial) = delete;
template <std::floating_point F> Polynomial operator/(Polynomial, F) = delete;

/// a * coefficient * monomial.
Polynomial multiplyByTerm(const Polynomial& a, const Rational& coefficient, const Monomial& monomial);
/// base^exponent, with base^0 = 1 (also for base 0).
Polynomial pow(const Polynomial& base, unsigned exponent);

/// Replaces variable i of p's ring by values[i] (one value per variable, all
/// in one target ring) and expands. Throws std::invalid_argument on a count
/// or ring mismatch.
Polynomial substitute(const Polynomial& p, const std::vector<Polynomial>& values);
/// Value at a rational point (one value per variable).
Rational evaluate(const Polynomial& p, const std::vector<Rational>& point);
/// Partial derivative with respect to `variable`.
Polynomial derivative(const Polynomial& p, std::size_t variable);

std::ostream& operator<<(std::ostream& out, const Polynomial& p);

}  // namespace sdfwb::algebra
