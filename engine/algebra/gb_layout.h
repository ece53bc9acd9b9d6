#pragma once
// Internal to the Groebner engine: the packed monomial representation.
//
// A monomial is `stride` consecutive 32-bit words: first the order keys M*e
// (M = MonomialOrder::matrix), then the exponents e. Comparing two monomials
// is a lexicographic comparison of their keys; multiplying adds all words,
// because keys are linear in the exponents. Divisibility reads the exponents,
// after a quick reject with a 64-bit divisibility mask.

#include "algebra/ring.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sdfwb::algebra::gb {

using Word = std::int32_t;

class Layout {
 public:
  explicit Layout(const Ring& ring);

  std::size_t vars() const { return vars_; }
  std::size_t keys() const { return keys_; }
  std::size_t stride() const { return stride_; }
  const Word* exponents(const Word* m) const { return m + keys_; }

  int compare(const Word* a, const Word* b) const {
    for (std::size_t i = 0; i < keys_; ++i) {
      if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    }
    return 0;
  }
  bool equal(const Word* a, const Word* b) const {
    for (std::size_t i = keys_; i < stride_; ++i) {
      if (a[i] != b[i]) return false;
    }
    return true;
  }
  /// out = m, inline: a monomial is a few dozen bytes, and std::copy_n
  /// with the stride known only at run time became a call to memmove per
  /// term (a fifteenth of a modular Katsura run). Fixed-size chunks of
  /// memcpy compile to plain vector moves.
  void copy(Word* out, const Word* m) const {
    std::size_t i = 0;
    for (; i + 4 <= stride_; i += 4) std::memcpy(out + i, m + i, 4 * sizeof(Word));
    for (; i < stride_; ++i) out[i] = m[i];
  }
  void multiply(Word* out, const Word* a, const Word* b) const {
    for (std::size_t i = 0; i < stride_; ++i) out[i] = a[i] + b[i];
  }
  /// out = b / a; requires divides(a, b).
  void divide(Word* out, const Word* b, const Word* a) const {
    for (std::size_t i = 0; i < stride_; ++i) out[i] = b[i] - a[i];
  }
  /// True if a divides b.
  bool divides(const Word* a, const Word* b) const {
    for (std::size_t i = keys_; i < stride_; ++i) {
      if (a[i] > b[i]) return false;
    }
    return true;
  }
  bool coprime(const Word* a, const Word* b) const {
    for (std::size_t i = keys_; i < stride_; ++i) {
      if (a[i] != 0 && b[i] != 0) return false;
    }
    return true;
  }
  void lcm(Word* out, const Word* a, const Word* b) const;
  /// The exponents of lcm(a, b) only (out's keys are left unset): enough for
  /// divides, equal, coprime and divmask; encodeKeys completes it.
  void lcmExponents(Word* out, const Word* a, const Word* b) const {
    for (std::size_t i = keys_; i < stride_; ++i) out[i] = std::max(a[i], b[i]);
  }
  /// Fills the keys from the exponents already stored in out[keys()..].
  void encodeKeys(Word* out) const;
  std::uint32_t degree(const Word* m) const {
    std::uint32_t d = 0;
    for (std::size_t i = keys_; i < stride_; ++i) d += static_cast<std::uint32_t>(m[i]);
    return d;
  }
  /// The degree the sugar strategy works with: the first row of the order
  /// matrix when it has no negative entry (total degree for degrevlex and
  /// deglex, the weighted degree for weighted orders, the degree in the first
  /// block for block orders), else the total degree. Selecting pairs by a
  /// degree that agrees with the order's first criterion keeps elimination
  /// orders from wandering through high total degrees (Singular's pFDeg does
  /// the same).
  std::uint32_t sugarDegree(const Word* m) const {
    return firstRowIsDegree_ ? static_cast<std::uint32_t>(m[0]) : degree(m);
  }
  /// Mask with a bit set for each (variable, threshold) the exponent reaches:
  /// divides(a, b) implies (mask(a) & ~mask(b)) == 0.
  std::uint64_t divmask(const Word* m) const;

 private:
  std::size_t vars_, keys_, stride_;
  bool firstRowIsDegree_ = false;
  std::vector<std::vector<Word>> matrix_;
  std::size_t maskBits_ = 0;  // divmask bits per variable
  std::size_t maskVars_ = 0;  // variables that get divmask bits
};

}  // namespace sdfwb::algebra::gb
