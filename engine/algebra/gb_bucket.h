#pragma once
// Internal to the Groebner engine: a geobucket (Yan, "The geobucket data
// structure for polynomials", 1998) holding the polynomial under reduction.
//
// Level i holds at most 4^(i+1) terms; adding a polynomial merges it into the
// level of its size and carries overflow upwards, so each term is merged
// O(log n) times instead of once per reduction step. The leading term is the
// largest head among the levels (heads with equal monomials are summed).

#include "algebra/gb_poly.h"

#include <algorithm>
#include <type_traits>
#include <vector>

namespace sdfwb::algebra::gb {

template <class Domain>
class Bucket {
 public:
  using Coeff = typename Domain::Coeff;

  Bucket(const Layout& layout, const Domain& domain) : layout_(layout), domain_(domain) {}

  void clear() {
    for (Level& level : levels_) {
      level.poly.clear();
      level.head = 0;
    }
  }

  /// Adds a polynomial in canonical order.
  void add(Poly<Coeff>&& p) {
    if (p.empty()) return;
    std::size_t i = 0;
    while (capacity(i) < p.size()) ++i;
    if (levels_.size() <= i) levels_.resize(i + 1);
    mergeInto(i, std::move(p));
    while (live(i) > capacity(i)) {
      if (levels_.size() <= i + 1) levels_.resize(i + 2);
      Poly<Coeff> moved = take(i);
      mergeInto(i + 1, std::move(moved));
      ++i;
    }
  }

  /// Adds factor * shift * (terms [from, end) of p).
  void addMultiple(const Poly<Coeff>& p, std::size_t from, const Coeff& factor, const Word* shift) {
    const std::size_t stride = layout_.stride();
    Poly<Coeff> product = acquire();
    product.mons.resize((p.size() - from) * stride);
    product.coeffs.resize(p.size() - from);
    for (std::size_t i = from; i < p.size(); ++i) {
      layout_.multiply(product.mons.data() + (i - from) * stride, p.mon(i, stride), shift);
    }
    domain_.mulAll(product.coeffs.data(), p.coeffs.data() + from, p.size() - from, factor);
    add(std::move(product));
  }

  /// Multiplies every coefficient by s.
  void scale(const Coeff& s) {
    for (Level& level : levels_) {
      for (std::size_t i = level.head; i < level.poly.size(); ++i) {
        domain_.mul(level.poly.coeffs[i], level.poly.coeffs[i], s);
      }
    }
  }

  /// Calls f on every coefficient (e.g. to compute or divide out a content).
  template <class F>
  void forEachCoefficient(F&& f) {
    for (Level& level : levels_) {
      for (std::size_t i = level.head; i < level.poly.size(); ++i) {
        if (!f(level.poly.coeffs[i])) return;
      }
    }
  }

  /// Removes the leading term into (mon, coeff); false when the bucket is 0.
  bool popLead(Word* mon, Coeff& coeff) {
    const std::size_t stride = layout_.stride();
    for (;;) {
      int best = -1;
      for (std::size_t i = 0; i < levels_.size(); ++i) {
        const Level& level = levels_[i];
        if (level.head >= level.poly.size()) continue;
        if (best < 0 || layout_.compare(level.poly.mon(level.head, stride),
                                        levels_[best].poly.mon(levels_[best].head, stride)) > 0) {
          best = static_cast<int>(i);
        }
      }
      if (best < 0) return false;
      Level& top = levels_[best];
      const Word* topMon = top.poly.mon(top.head, stride);
      layout_.copy(mon, topMon);
      coeff = std::move(top.poly.coeffs[top.head]);
      ++top.head;
      for (std::size_t i = 0; i < levels_.size(); ++i) {
        Level& level = levels_[i];
        if (static_cast<int>(i) == best || level.head >= level.poly.size()) continue;
        if (layout_.equal(level.poly.mon(level.head, stride), mon)) {
          domain_.add(coeff, level.poly.coeffs[level.head]);
          ++level.head;
        }
      }
      if (!Domain::isZero(coeff)) return true;
    }
  }

  std::size_t termCount() const {
    std::size_t n = 0;
    for (const Level& level : levels_) n += level.poly.size() - level.head;
    return n;
  }
  std::size_t bytes() const {
    std::size_t n = scratch_.bytes();
    for (const Level& level : levels_) n += level.poly.bytes();
    return n;
  }

 private:
  struct Level {
    Poly<Coeff> poly;
    std::size_t head = 0;  // terms before head were already popped
  };

  static std::size_t capacity(std::size_t level) { return std::size_t{4} << (2 * level); }
  std::size_t live(std::size_t i) const { return levels_[i].poly.size() - levels_[i].head; }

  Poly<Coeff> take(std::size_t i) {
    Level& level = levels_[i];
    Poly<Coeff> p = acquire();
    if (level.head == 0) {
      std::swap(p, level.poly);
    } else {
      const std::size_t stride = layout_.stride();
      p.mons.assign(level.poly.mons.begin() + static_cast<std::ptrdiff_t>(level.head * stride),
                    level.poly.mons.end());
      p.coeffs.clear();
      p.coeffs.reserve(level.poly.size() - level.head);
      for (std::size_t k = level.head; k < level.poly.size(); ++k) {
        p.coeffs.push_back(std::move(level.poly.coeffs[k]));
      }
    }
    level.poly.clear();
    level.head = 0;
    return p;
  }

  // levels_[i] += p, merging two sorted runs.
  void mergeInto(std::size_t i, Poly<Coeff>&& p) {
    Level& level = levels_[i];
    if (live(i) == 0) {
      release(std::move(level.poly));
      level.poly = std::move(p);
      level.head = 0;
      return;
    }
    const std::size_t stride = layout_.stride();
    Poly<Coeff>& a = level.poly;
    Poly<Coeff>& out = scratch_;
    // Sized once for the worst case and trimmed after: cheaper than growing
    // the monomial array term by term. The scratch keeps its monomial words
    // between merges (only its coefficients are cleared), so only growth is
    // zero-filled.
    const std::size_t most = live(i) + p.size();
    if (out.mons.size() < most * stride) out.mons.resize(most * stride);
    // Coefficients are written in place (push_back's capacity check per
    // term was a twentieth of a modular run). Integers are swapped in, so
    // the merged polynomials are left holding the scratch's old integers:
    // released to the pool with them (see release), their allocations are
    // reused by the next products instead of freed and allocated again.
    constexpr bool words = std::is_trivially_copyable_v<Coeff>;
    out.coeffs.resize(most);
    Word* write = out.mons.data();
    Coeff* writeCoeff = out.coeffs.data();
    auto emit = [&](const Word* mon, Coeff&& c) {
      layout_.copy(write, mon);
      write += stride;
      if constexpr (words) {
        *writeCoeff++ = c;
      } else {
        std::swap(*writeCoeff++, c);
      }
    };
    std::size_t x = level.head, y = 0;
    while (x < a.size() && y < p.size()) {
      int c = layout_.compare(a.mon(x, stride), p.mon(y, stride));
      if (c > 0) {
        emit(a.mon(x, stride), std::move(a.coeffs[x]));
        ++x;
      } else if (c < 0) {
        emit(p.mon(y, stride), std::move(p.coeffs[y]));
        ++y;
      } else {
        domain_.add(a.coeffs[x], p.coeffs[y]);
        if (!Domain::isZero(a.coeffs[x])) emit(a.mon(x, stride), std::move(a.coeffs[x]));
        ++x;
        ++y;
      }
    }
    for (; x < a.size(); ++x) emit(a.mon(x, stride), std::move(a.coeffs[x]));
    for (; y < p.size(); ++y) emit(p.mon(y, stride), std::move(p.coeffs[y]));
    out.coeffs.resize(static_cast<std::size_t>(writeCoeff - out.coeffs.data()));
    out.mons.resize(out.coeffs.size() * stride);
    std::swap(a, out);
    level.head = 0;
    if constexpr (words) out.coeffs.clear();
    release(std::move(p));
  }

  // Polynomials whose storage is kept for reuse: a reduction creates and
  // merges thousands of short-lived polynomials, and reusing their arrays
  // saves most of the allocator traffic.
  Poly<Coeff> acquire() {
    if (pool_.empty()) return {};
    Poly<Coeff> p = std::move(pool_.back());
    pool_.pop_back();
    return p;
  }
  // A pooled polynomial keeps the size of its monomial array (stale words,
  // overwritten by whoever takes it: addMultiple resizes, take assigns or
  // swaps), so that reuse does not zero-fill it again.
  // Integer coefficients stay too (acquire's callers overwrite or clear
  // them), keeping their allocations for the next products.
  void release(Poly<Coeff>&& p) {
    if (pool_.size() >= kPoolSize || p.mons.capacity() == 0) return;
    if constexpr (std::is_trivially_copyable_v<Coeff>) p.coeffs.clear();
    pool_.push_back(std::move(p));
  }

  const Layout& layout_;
  const Domain& domain_;
  std::vector<Level> levels_;
  Poly<Coeff> scratch_;  // reused merge buffer
  static constexpr std::size_t kPoolSize = 16;
  std::vector<Poly<Coeff>> pool_;
};

}  // namespace sdfwb::algebra::gb
