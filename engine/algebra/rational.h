#pragma once
// Exact coefficients. Everything in the algebra module is exact: GMP
// rationals and integers, never floating point.

#include <gmpxx.h>

#include <string>

namespace sdfwb::algebra {

using Rational = mpq_class;
using Integer = mpz_class;

/// "a/b" with b > 1 omitted when the value is an integer ("-3", "3/2").
/// The text reads back as the same value.
std::string toString(const Rational& value);

}  // namespace sdfwb::algebra
