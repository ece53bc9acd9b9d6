#include "algebra/ring.h"

#include "algebra/polynomial.h"

#include <algorithm>
#include <stdexcept>

namespace sdfwb::algebra {

RingPtr Ring::make(std::vector<std::string> variables, MonomialOrder order) {
  for (std::size_t i = 0; i < variables.size(); ++i) {
    if (variables[i].empty()) throw std::invalid_argument("ring: empty variable name");
    for (std::size_t j = 0; j < i; ++j) {
      if (variables[j] == variables[i]) {
        throw std::invalid_argument("ring: variable '" + variables[i] + "' appears twice");
      }
    }
  }
  order.checkFits(variables.size());
  return RingPtr(new Ring(std::move(variables), std::move(order)));
}

Ring::Ring(std::vector<std::string> variables, MonomialOrder order)
    : variables_(std::move(variables)), order_(std::move(order)) {
  if (order_.kind() == MonomialOrder::Kind::Weighted || order_.kind() == MonomialOrder::Kind::Block) {
    matrix_ = order_.matrix(variables_.size());
  }
}

std::optional<std::size_t> Ring::indexOf(std::string_view name) const {
  auto it = std::find(variables_.begin(), variables_.end(), name);
  if (it == variables_.end()) return std::nullopt;
  return static_cast<std::size_t>(it - variables_.begin());
}

int Ring::compare(const Monomial& a, const Monomial& b) const {
  const std::size_t n = variables_.size();
  switch (order_.kind()) {
    case MonomialOrder::Kind::Lex:
      for (std::size_t i = 0; i < n; ++i) {
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
      }
      return 0;
    case MonomialOrder::Kind::Deglex:
    case MonomialOrder::Kind::Degrevlex: {
      std::uint64_t da = a.degree(), db = b.degree();
      if (da != db) return da < db ? -1 : 1;
      if (order_.kind() == MonomialOrder::Kind::Deglex) {
        for (std::size_t i = 0; i < n; ++i) {
          if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
        }
        return 0;
      }
      // Reverse lex: a smaller exponent in the last differing variable makes
      // the larger monomial.
      for (std::size_t i = n; i-- > 0;) {
        if (a[i] != b[i]) return a[i] > b[i] ? -1 : 1;
      }
      return 0;
    }
    case MonomialOrder::Kind::Weighted:
    case MonomialOrder::Kind::Block:
      for (const auto& row : matrix_) {
        std::int64_t wa = 0, wb = 0;
        for (std::size_t i = 0; i < n; ++i) {
          wa += row[i] * static_cast<std::int64_t>(a[i]);
          wb += row[i] * static_cast<std::int64_t>(b[i]);
        }
        if (wa != wb) return wa < wb ? -1 : 1;
      }
      return 0;
  }
  return 0;
}

RingPtr Ring::withOrder(MonomialOrder order) const { return make(variables_, std::move(order)); }

Polynomial Ring::var(std::string_view name) const {
  std::optional<std::size_t> index = indexOf(name);
  if (!index) throw std::invalid_argument("unknown variable '" + std::string(name) + "'");
  return var(*index);
}

Polynomial Ring::var(std::size_t index) const {
  if (index >= size()) throw std::out_of_range("ring: variable index out of range");
  Monomial m(size());
  m[index] = 1;
  return Polynomial(shared_from_this(), {Term{std::move(m), Rational(1)}});
}

Polynomial Ring::constant(const Rational& value) const {
  return Polynomial(shared_from_this(), {Term{oneMonomial(), value}});
}

Polynomial Ring::zero() const { return Polynomial(shared_from_this()); }
Polynomial Ring::one() const { return constant(Rational(1)); }

bool operator==(const Ring& a, const Ring& b) {
  return &a == &b || (a.variables_ == b.variables_ && a.order_ == b.order_);
}

bool isUserIdentifier(std::string_view name) {
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (name.empty() || !alpha(name.front())) return false;
  return std::all_of(name.begin(), name.end(), [&](char c) { return alpha(c) || digit(c); });
}

std::string internalVariableName(std::string_view hint, const std::vector<std::string>& taken) {
  std::string base = "$" + std::string(hint);
  std::string name = base;
  for (int suffix = 1; std::find(taken.begin(), taken.end(), name) != taken.end(); ++suffix) {
    name = base + std::to_string(suffix);
  }
  return name;
}

}  // namespace sdfwb::algebra
