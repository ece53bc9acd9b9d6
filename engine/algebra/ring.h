#pragma once
// A polynomial ring Q[x_0, ..., x_{n-1}] with named variables and a monomial
// order. Rings are immutable and shared: create one with Ring::make and build
// polynomials from it.
//
//   auto ring = Ring::make({"x", "y", "z"}, MonomialOrder::degrevlex());
//   Polynomial x = ring->var("x"), y = ring->var("y");
//   Polynomial f = pow(x, 2) - Rational(3, 2) * x * y + 1;
//
// Two rings are interchangeable when they have the same variable names in the
// same order and the same monomial order, even if they are distinct objects.

#include "algebra/monomial.h"
#include "algebra/monomial_order.h"
#include "algebra/rational.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::algebra {

class Polynomial;
class Ring;
using RingPtr = std::shared_ptr<const Ring>;

class Ring : public std::enable_shared_from_this<Ring> {
 public:
  /// Throws std::invalid_argument when a name is empty or repeated, or when
  /// the order does not fit the variable count (weights, block sizes).
  /// Names are free-form here; names that users cannot type are reserved for
  /// internal variables (see internalVariableName).
  static RingPtr make(std::vector<std::string> variables,
                      MonomialOrder order = MonomialOrder::degrevlex());

  std::size_t size() const { return variables_.size(); }
  const std::vector<std::string>& variables() const { return variables_; }
  const std::string& variable(std::size_t index) const { return variables_[index]; }
  std::optional<std::size_t> indexOf(std::string_view name) const;
  const MonomialOrder& order() const { return order_; }

  /// Sign of the comparison of two monomials of this ring under its order:
  /// negative if a < b, zero if equal, positive if a > b.
  int compare(const Monomial& a, const Monomial& b) const;

  /// The same variables with another order.
  RingPtr withOrder(MonomialOrder order) const;

  // Building polynomials. var(name) throws std::invalid_argument for an
  // unknown name ("unknown variable 'w'").
  Polynomial var(std::string_view name) const;
  Polynomial var(std::size_t index) const;
  Polynomial constant(const Rational& value) const;
  Polynomial zero() const;
  Polynomial one() const;
  Monomial oneMonomial() const { return Monomial(size()); }

  /// Same variable names and same order.
  friend bool operator==(const Ring& a, const Ring& b);

 private:
  Ring(std::vector<std::string> variables, MonomialOrder order);

  std::vector<std::string> variables_;
  MonomialOrder order_;
  // Comparison matrix for weighted and block orders (see MonomialOrder::matrix).
  std::vector<std::vector<std::int64_t>> matrix_;
};

/// True for the names a user can type: [A-Za-z_][A-Za-z0-9_]*.
bool isUserIdentifier(std::string_view name);

/// A variable name for internal use (half-angle parameters, the auxiliary y
/// of Theorem 1.8, tags of ideal intersection) that can never collide with a
/// user identifier: "$" + hint, with a number appended if needed to differ
/// from every name in `taken`.
std::string internalVariableName(std::string_view hint, const std::vector<std::string>& taken);

}  // namespace sdfwb::algebra
