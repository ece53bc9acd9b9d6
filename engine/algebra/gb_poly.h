#pragma once
// Internal to the Groebner engine: packed polynomials and the coefficient
// domains the engine is written against.
//
// A domain supplies the coefficient type and the three operations the
// reduction needs, so one Buchberger serves both exact rational work
// (IntegerDomain: integer coefficients, fraction-free steps, primitive
// results) and modular work (ModularDomain: Z/p, monic results).

#include "algebra/flint_fmpz.h"
#include "algebra/gb_layout.h"

#include <gmpxx.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace sdfwb::algebra::gb {

/// An allocator whose value-less construct leaves the words uninitialized:
/// the engine resizes monomial arrays and then writes every word, and the
/// zero-fill of vector::resize was a tenth of a modular Katsura run.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// Packed monomials, `stride` words each.
using Monomials = std::vector<Word, UninitializedAllocator<Word>>;

/// Terms in decreasing order of their monomials, no zero coefficients.
template <class Coeff>
struct Poly {
  // size() * stride words; only the geobucket's pooled polynomials and its
  // merge buffer keep a longer array (stale words, for reuse without a fill).
  Monomials mons;
  std::vector<Coeff> coeffs;
  std::uint32_t sugar = 0;

  std::size_t size() const { return coeffs.size(); }
  bool empty() const { return coeffs.empty(); }
  const Word* mon(std::size_t i, std::size_t stride) const { return mons.data() + i * stride; }
  void push(const Word* m, std::size_t stride, Coeff&& c) {
    // resize (no zero-fill, see UninitializedAllocator) and copy: vector's
    // generic range insert was a tenth of a modular reduction.
    const std::size_t end = mons.size();
    mons.resize(end + stride);
    std::copy_n(m, stride, mons.data() + end);
    coeffs.push_back(std::move(c));
  }
  void clear() {
    mons.clear();
    coeffs.clear();
  }
  std::size_t bytes() const { return mons.capacity() * sizeof(Word) + coeffs.capacity() * sizeof(Coeff); }
};

using IntPoly = Poly<mpz_class>;       // exact work over Q
using FmpzPoly = Poly<Fmpz>;           // exact checks over Q (see FmpzDomain)
using ModPoly = Poly<std::uint32_t>;   // work modulo a prime

/// Integers standing for rationals up to a nonzero factor (Q's fraction-free
/// arithmetic): to cancel the leading coefficient c of p with the reducer's
/// leading coefficient a, p becomes (a/g)*p - (c/g)*m*reducer, g = gcd(a, c).
struct IntegerDomain {
  using Coeff = mpz_class;
  /// Fraction-free steps make coefficients grow by common factors that the
  /// engine divides out now and then.
  static constexpr bool hasContent = true;

  static bool isZero(const Coeff& c) { return mpz_sgn(c.get_mpz_t()) == 0; }
  static bool isOne(const Coeff& c) { return mpz_cmp_ui(c.get_mpz_t(), 1) == 0; }
  static void add(Coeff& a, const Coeff& b) { mpz_add(a.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t()); }
  static void mul(Coeff& out, const Coeff& a, const Coeff& b) {
    mpz_mul(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  }
  static void negate(Coeff& a) { mpz_neg(a.get_mpz_t(), a.get_mpz_t()); }
  /// out[k] = in[k] * factor for k < n.
  static void mulAll(Coeff* out, const Coeff* in, std::size_t n, const Coeff& factor) {
    for (std::size_t k = 0; k < n; ++k) mul(out[k], in[k], factor);
  }
  /// scale = a/g, multiplier = c/g with g = gcd(a, c), sign moved into scale
  /// so that scale > 0: then p*scale - multiplier*(reducer) cancels c.
  static void cancelFactors(const Coeff& c, const Coeff& a, Coeff& scale, Coeff& multiplier) {
    mpz_gcd(multiplier.get_mpz_t(), a.get_mpz_t(), c.get_mpz_t());
    mpz_divexact(scale.get_mpz_t(), a.get_mpz_t(), multiplier.get_mpz_t());
    mpz_divexact(multiplier.get_mpz_t(), c.get_mpz_t(), multiplier.get_mpz_t());
    if (mpz_sgn(scale.get_mpz_t()) < 0) {
      negate(scale);
      negate(multiplier);
    }
  }
  /// Divides by the content and makes the leading coefficient positive.
  static void normalize(std::vector<Coeff>& coeffs);
  /// For the engine's content removal: |c| in bits; g = gcd(g, c), false
  /// once g is 1 (nothing to divide out); c /= g exactly.
  static std::size_t bits(const Coeff& c) { return mpz_sizeinbase(c.get_mpz_t(), 2); }
  static bool gcdAboveOne(Coeff& g, const Coeff& c) {
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
    return mpz_cmp_ui(g.get_mpz_t(), 1) != 0;
  }
  static void divideExact(Coeff& c, const Coeff& g) { mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t()); }
};

/// IntegerDomain's arithmetic on FLINT integers, for the exact checks of
/// the modular method (S-pairs and memberships over Q): their coefficients
/// are often word-sized, which fmpz keeps without allocation, and larger
/// ones come from FLINT's cache of GMP integers instead of malloc (GMP
/// integers allocated and freed per term were a third of a verification).
struct FmpzDomain {
  using Coeff = Fmpz;
  static constexpr bool hasContent = true;

  static bool isZero(const Coeff& c) { return fmpz_is_zero(c.v); }
  static bool isOne(const Coeff& c) { return fmpz_is_one(c.v); }
  static void add(Coeff& a, const Coeff& b) { fmpz_add(a.v, a.v, b.v); }
  static void mul(Coeff& out, const Coeff& a, const Coeff& b) { fmpz_mul(out.v, a.v, b.v); }
  static void negate(Coeff& a) { fmpz_neg(a.v, a.v); }
  static void mulAll(Coeff* out, const Coeff* in, std::size_t n, const Coeff& factor) {
    for (std::size_t k = 0; k < n; ++k) fmpz_mul(out[k].v, in[k].v, factor.v);
  }
  /// As IntegerDomain::cancelFactors.
  static void cancelFactors(const Coeff& c, const Coeff& a, Coeff& scale, Coeff& multiplier) {
    fmpz_gcd(multiplier.v, a.v, c.v);
    fmpz_divexact(scale.v, a.v, multiplier.v);
    fmpz_divexact(multiplier.v, c.v, multiplier.v);
    if (fmpz_sgn(scale.v) < 0) {
      fmpz_neg(scale.v, scale.v);
      fmpz_neg(multiplier.v, multiplier.v);
    }
  }
  static void normalize(std::vector<Coeff>& coeffs);
  static std::size_t bits(const Coeff& c) { return fmpz_bits(c.v); }
  static bool gcdAboveOne(Coeff& g, const Coeff& c) {
    fmpz_gcd(g.v, g.v, c.v);
    return !fmpz_is_one(g.v);
  }
  static void divideExact(Coeff& c, const Coeff& g) { fmpz_divexact(c.v, c.v, g.v); }
};

/// Z/p for a prime p < 2^31; results are made monic.
struct ModularDomain {
  using Coeff = std::uint32_t;
  static constexpr bool hasContent = false;
  std::uint32_t p;

  static bool isZero(Coeff c) { return c == 0; }
  static bool isOne(Coeff c) { return c == 1; }
  // a, b < p < 2^31: the sum fits and needs at most one subtraction.
  void add(Coeff& a, Coeff b) const {
    a += b;
    if (a >= p) a -= p;
  }
  void mul(Coeff& out, Coeff a, Coeff b) const {
    out = static_cast<Coeff>(static_cast<std::uint64_t>(a) * b % p);
  }
  /// out[k] = in[k] * factor for k < n, by Shoup's precomputed quotient
  /// (w' = floor(factor * 2^32 / p)): a multiplication, a shift and one
  /// correction per term instead of a 64-bit division. With in[k], factor
  /// < p < 2^31, in[k] * factor - q * p lies in [0, 2p).
  void mulAll(Coeff* out, const Coeff* in, std::size_t n, Coeff factor) const {
    const std::uint64_t w = factor;
    const std::uint64_t wShoup = (w << 32) / p;
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint64_t a = in[k];
      const std::uint64_t q = (a * wShoup) >> 32;
      std::uint64_t r = a * w - q * p;
      if (r >= p) r -= p;
      out[k] = static_cast<Coeff>(r);
    }
  }
  void negate(Coeff& a) const { a = a == 0 ? 0 : p - a; }
  Coeff inverse(Coeff a) const;
  void cancelFactors(Coeff c, Coeff a, Coeff& scale, Coeff& multiplier) const {
    scale = 1;
    mul(multiplier, c, inverse(a));
  }
  void normalize(std::vector<Coeff>& coeffs) const;
};

}  // namespace sdfwb::algebra::gb
