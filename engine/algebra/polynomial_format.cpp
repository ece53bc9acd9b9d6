#include "algebra/polynomial.h"

#include <ostream>

namespace sdfwb::algebra {

namespace {

// "x^2*y"; empty for the monomial 1.
std::string formatMonomial(const Ring& ring, const Monomial& m) {
  std::string text;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m[i] == 0) continue;
    if (!text.empty()) text += '*';
    text += ring.variable(i);
    if (m[i] > 1) text += '^' + std::to_string(m[i]);
  }
  return text;
}

}  // namespace

std::string Polynomial::toString() const {
  if (terms_.empty()) return "0";
  std::string text;
  for (const Term& t : terms_) {
    const bool negative = sgn(t.coefficient) < 0;
    if (text.empty()) {
      if (negative) text += '-';
    } else {
      text += negative ? " - " : " + ";
    }
    Rational magnitude = abs(t.coefficient);
    std::string monomial = formatMonomial(*ring_, t.monomial);
    if (monomial.empty()) {
      text += algebra::toString(magnitude);
    } else if (magnitude == 1) {
      text += monomial;
    } else {
      text += algebra::toString(magnitude) + '*' + monomial;
    }
  }
  return text;
}

std::ostream& operator<<(std::ostream& out, const Polynomial& p) { return out << p.toString(); }

}  // namespace sdfwb::algebra
