#include "algebra/flint_polynomial.h"

#include <flint/fmpq_mpoly.h>

#include <algorithm>
#include <deque>
#include <stdexcept>

namespace sdfwb::algebra::flint {

namespace {

// One FLINT context and the polynomials made in it, freed together.
class Context {
 public:
  explicit Context(const RingPtr& ring, std::size_t extraVariables = 0) : ring_(ring) {
    // The order only decides FLINT's term layout; results are re-sorted.
    fmpq_mpoly_ctx_init(ctx_, static_cast<slong>(std::max<std::size_t>(ring->size() + extraVariables, 1)), ORD_LEX);
  }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context() {
    for (fmpq_mpoly_struct& p : polys_) fmpq_mpoly_clear(&p, ctx_);
    fmpq_mpoly_ctx_clear(ctx_);
  }

  fmpq_mpoly_struct* make() {
    polys_.emplace_back();
    fmpq_mpoly_init(&polys_.back(), ctx_);
    return &polys_.back();
  }

  fmpq_mpoly_struct* from(const Polynomial& p) {
    fmpq_mpoly_struct* out = make();
    std::vector<ulong> exponents(ring_->size() + 1, 0);
    fmpq_t c;
    fmpq_init(c);
    for (const Term& t : p.terms()) {
      for (std::size_t v = 0; v < ring_->size(); ++v) exponents[v] = t.monomial[v];
      fmpq_set_mpq(c, t.coefficient.get_mpq_t());
      fmpq_mpoly_push_term_fmpq_ui(out, c, exponents.data(), ctx_);
    }
    fmpq_clear(c);
    fmpq_mpoly_sort_terms(out, ctx_);
    fmpq_mpoly_combine_like_terms(out, ctx_);
    return out;
  }

  Polynomial to(const fmpq_mpoly_struct* p) {
    std::vector<Term> terms;
    std::vector<ulong> exponents(ring_->size() + 1, 0);
    fmpq_t c;
    fmpq_init(c);
    for (slong i = 0; i < fmpq_mpoly_length(p, ctx_); ++i) {
      fmpq_mpoly_get_term_coeff_fmpq(c, p, i, ctx_);
      fmpq_mpoly_get_term_exp_ui(exponents.data(), p, i, ctx_);
      Monomial m(ring_->size());
      for (std::size_t v = 0; v < ring_->size(); ++v) m[v] = static_cast<Exponent>(exponents[v]);
      Rational q;
      fmpq_get_mpq(q.get_mpq_t(), c);
      terms.push_back({std::move(m), std::move(q)});
    }
    fmpq_clear(c);
    return Polynomial(ring_, std::move(terms));
  }

  const fmpq_mpoly_ctx_struct* ctx() const { return ctx_; }

 private:
  RingPtr ring_;
  fmpq_mpoly_ctx_t ctx_;
  std::deque<fmpq_mpoly_struct> polys_;
};

}  // namespace

Polynomial gcd(const Polynomial& a, const Polynomial& b) {
  Context context(a.ring());
  fmpq_mpoly_struct* g = context.make();
  if (!fmpq_mpoly_gcd(g, context.from(a), context.from(b), context.ctx())) {
    throw std::runtime_error("gcd: FLINT could not compute the gcd (exponents too large)");
  }
  return context.to(g);
}

Polynomial lcm(const Polynomial& a, const Polynomial& b) {
  Context context(a.ring());
  fmpq_mpoly_struct* fa = context.from(a);
  fmpq_mpoly_struct* fb = context.from(b);
  fmpq_mpoly_struct* g = context.make();
  if (!fmpq_mpoly_gcd(g, fa, fb, context.ctx())) {
    throw std::runtime_error("lcm: FLINT could not compute the gcd (exponents too large)");
  }
  fmpq_mpoly_struct* l = context.make();
  if (!fmpq_mpoly_is_zero(g, context.ctx())) {
    if (!fmpq_mpoly_divides(l, fa, g, context.ctx())) throw std::logic_error("lcm: the gcd does not divide");
    fmpq_mpoly_mul(l, l, fb, context.ctx());
    fmpq_mpoly_make_monic(l, l, context.ctx());
  }
  return context.to(l);
}

Polynomial multiply(const Polynomial& a, const Polynomial& b) {
  Context context(a.ring());
  fmpq_mpoly_struct* product = context.make();
  fmpq_mpoly_mul(product, context.from(a), context.from(b), context.ctx());
  return context.to(product);
}

Polynomial substituteHomogeneous(const Polynomial& f, const std::vector<Polynomial>& values, const Polynomial& q) {
  const std::size_t n = f.ring()->size();
  if (values.size() != n) throw std::invalid_argument("substitute_homogeneous: one value per variable");
  // f homogenized by one more variable w (f^h(x, w) = w^e f(x / w)), then
  // composed with (values, q): FLINT caches the powers of each value.
  Context source(f.ring(), 1);
  fmpq_mpoly_struct* homogeneous = source.make();
  const std::uint64_t degree = f.totalDegree();
  std::vector<ulong> exponents(n + 1, 0);
  fmpq_t c;
  fmpq_init(c);
  for (const Term& t : f.terms()) {
    for (std::size_t v = 0; v < n; ++v) exponents[v] = t.monomial[v];
    exponents[n] = degree - t.monomial.degree();
    fmpq_set_mpq(c, t.coefficient.get_mpq_t());
    fmpq_mpoly_push_term_fmpq_ui(homogeneous, c, exponents.data(), source.ctx());
  }
  fmpq_clear(c);
  fmpq_mpoly_sort_terms(homogeneous, source.ctx());
  fmpq_mpoly_combine_like_terms(homogeneous, source.ctx());
  Context target(q.ring());
  std::vector<fmpq_mpoly_struct*> substituted;
  for (const Polynomial& value : values) substituted.push_back(target.from(value));
  substituted.push_back(target.from(q));
  fmpq_mpoly_struct* result = target.make();
  if (!fmpq_mpoly_compose_fmpq_mpoly(result, homogeneous, substituted.data(), source.ctx(), target.ctx())) {
    throw std::runtime_error("substitution: FLINT's exponents would overflow");
  }
  return target.to(result);
}

std::optional<Polynomial> divideExact(const Polynomial& a, const Polynomial& b) {
  Context context(a.ring());
  fmpq_mpoly_struct* q = context.make();
  if (!fmpq_mpoly_divides(q, context.from(a), context.from(b), context.ctx())) return std::nullopt;
  return context.to(q);
}

}  // namespace sdfwb::algebra::flint
