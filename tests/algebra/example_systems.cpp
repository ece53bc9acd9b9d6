#include "example_systems.h"

namespace sdfwb::algebra::testing {

namespace {

std::vector<std::string> names(const char* prefix, int count) {
  std::vector<std::string> out;
  for (int i = 0; i < count; ++i) out.push_back(prefix + std::to_string(i));
  return out;
}

}  // namespace

Ideal katsura(int n, const MonomialOrder& order) {
  auto ring = Ring::make(names("u", n + 1), order);
  auto u = [&](int i) {
    if (i < 0) i = -i;
    return i > n ? ring->zero() : ring->var(static_cast<std::size_t>(i));
  };
  std::vector<Polynomial> eqs;
  Polynomial linear = u(0) - 1;
  for (int i = 1; i <= n; ++i) linear += 2 * u(i);
  eqs.push_back(linear);
  for (int m = 0; m < n; ++m) {
    Polynomial sum = -u(m);
    for (int l = -n; l <= n; ++l) sum += u(l) * u(m - l);
    eqs.push_back(sum);
  }
  return Ideal(ring, eqs);
}

Ideal cyclic(int n, const MonomialOrder& order) {
  auto ring = Ring::make(names("x", n), order);
  std::vector<Polynomial> eqs;
  for (int k = 1; k < n; ++k) {
    Polynomial sum = ring->zero();
    for (int i = 0; i < n; ++i) {
      Polynomial product = ring->one();
      for (int j = 0; j < k; ++j) product *= ring->var(static_cast<std::size_t>((i + j) % n));
      sum += product;
    }
    eqs.push_back(sum);
  }
  Polynomial last = ring->one();
  for (int i = 0; i < n; ++i) last *= ring->var(static_cast<std::size_t>(i));
  eqs.push_back(last - 1);
  return Ideal(ring, eqs);
}

std::vector<NamedSystem> small_systems() {
  std::vector<NamedSystem> out;
  for (const MonomialOrder& order : {MonomialOrder::lex(), MonomialOrder::deglex(), MonomialOrder::degrevlex()}) {
    out.push_back({"katsura3 " + order.describe(), katsura(3, order)});
    out.push_back({"cyclic4 " + order.describe(), cyclic(4, order)});
    auto r = Ring::make({"x", "y", "z"}, order);
    Polynomial x = r->var("x"), y = r->var("y"), z = r->var("z");
    out.push_back({"clo-2.8 " + order.describe(),
                   Ideal(r, {pow(x, 2) + pow(y, 2) + pow(z, 2) - 1, pow(x, 2) + pow(z, 2) - y, x - z})});
    out.push_back({"mixed " + order.describe(),
                   Ideal(r, {Rational(1, 3) * pow(x, 2) * y - z + 2, x * pow(y, 3) - Rational(5, 7) * z * x,
                             pow(z, 3) - x * y + y})});
  }
  auto w = Ring::make({"x", "y", "z"}, MonomialOrder::weighted({1, 2, 3}, MonomialOrder::lex()));
  Polynomial x = w->var("x"), y = w->var("y"), z = w->var("z");
  out.push_back({"weighted", Ideal(w, {pow(x, 3) - y * z, pow(y, 2) - x * z + 1, x * y * z - 2})});
  auto b = Ring::make({"s", "t", "x", "y", "z"}, MonomialOrder::elimination(2));
  Polynomial s = b->var("s"), t = b->var("t");
  out.push_back({"elimination block",
                 Ideal(b, {b->var("x") - s * t, b->var("y") - s * pow(t, 2), b->var("z") - pow(s, 2)})});
  return out;
}

}  // namespace sdfwb::algebra::testing
