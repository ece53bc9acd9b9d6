#pragma once
// Multivariate division by an ordered list of divisors (Cox-Little-O'Shea,
// Theorem 2.3.3; the thesis's Algorithm 1).

#include "algebra/polynomial.h"

#include <optional>
#include <vector>

namespace sdfwb::algebra {

struct DivisionResult {
  std::vector<Polynomial> quotients;  // one per divisor
  Polynomial remainder;
};

/// f = sum(quotients[i] * divisors[i]) + remainder, where no term of the
/// remainder is divisible by any divisor's leading monomial and, at each step,
/// the first divisor (in list order) whose leading monomial divides the
/// current leading term is used. Zero divisors are skipped (quotient 0).
/// All polynomials must share one ring (std::invalid_argument otherwise).
DivisionResult divide(const Polynomial& f, const std::vector<Polynomial>& divisors);

/// The remainder of divide(f, divisors) without the quotients.
Polynomial reduce(const Polynomial& f, const std::vector<Polynomial>& divisors);

/// f / g when g divides f exactly, std::nullopt otherwise (through FLINT,
/// which stops at the first term that cannot divide). g must be nonzero; both
/// in one ring (std::invalid_argument otherwise).
std::optional<Polynomial> divideExact(const Polynomial& f, const Polynomial& g);

}  // namespace sdfwb::algebra
