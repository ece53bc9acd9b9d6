#pragma once
// A monomial as its exponent vector: x^2*z in the ring (x, y, z) is (2, 0, 1).

#include "algebra/monomial_order.h"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace sdfwb::algebra {

class Monomial {
 public:
  Monomial() = default;
  /// The monomial 1 in `variableCount` variables.
  explicit Monomial(std::size_t variableCount) : exponents_(variableCount, 0) {}
  explicit Monomial(std::vector<Exponent> exponents) : exponents_(std::move(exponents)) {}
  Monomial(std::initializer_list<Exponent> exponents) : exponents_(exponents) {}

  std::size_t size() const { return exponents_.size(); }
  Exponent operator[](std::size_t variable) const { return exponents_[variable]; }
  Exponent& operator[](std::size_t variable) { return exponents_[variable]; }
  const std::vector<Exponent>& exponents() const { return exponents_; }

  std::uint64_t degree() const;
  bool isOne() const;
  /// True if this monomial divides `other` (same variable count).
  bool divides(const Monomial& other) const;

  friend Monomial operator*(const Monomial& a, const Monomial& b);
  /// Exact quotient; requires b.divides(a).
  friend Monomial operator/(const Monomial& a, const Monomial& b);
  friend bool operator==(const Monomial& a, const Monomial& b) = default;

 private:
  std::vector<Exponent> exponents_;
};

Monomial lcm(const Monomial& a, const Monomial& b);
Monomial gcd(const Monomial& a, const Monomial& b);
/// True if a and b share no variable (gcd is 1).
bool coprime(const Monomial& a, const Monomial& b);

}  // namespace sdfwb::algebra
