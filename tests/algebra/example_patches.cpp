// CAD-style patches for the implicitization tests and benchmark.

#include "example_systems.h"

#include <random>

namespace sdfwb::algebra::testing {

namespace {

// Small integers from a fixed generator: the same patches on every machine.
class Coefficients {
 public:
  explicit Coefficients(unsigned seed) : random_(seed) {}
  long next(long low, long high) { return std::uniform_int_distribution<long>(low, high)(random_); }

 private:
  std::mt19937 random_;
};

RingPtr uv_ring() { return Ring::make({"u", "v"}); }

// Bernstein basis polynomial B_i^n(t) = C(n, i) t^i (1 - t)^(n - i).
Polynomial bernstein(unsigned n, unsigned i, const Polynomial& t) {
  long binomial = 1;
  for (unsigned k = 0; k < i; ++k) binomial = binomial * static_cast<long>(n - k) / static_cast<long>(k + 1);
  return binomial * pow(t, i) * pow(1 - t, n - i);
}

// A polynomial of bidegree (m, n) in u, v with coefficients in [low, high].
Polynomial random_bidegree(unsigned m, unsigned n, Coefficients& c, long low, long high) {
  RingPtr ring = uv_ring();
  Polynomial f = ring->zero();
  for (unsigned i = 0; i <= m; ++i) {
    for (unsigned j = 0; j <= n; ++j) f += c.next(low, high) * pow(ring->var("u"), i) * pow(ring->var("v"), j);
  }
  return f;
}

NamedParametrization height_patch(unsigned m, unsigned n, unsigned seed) {
  Coefficients c(seed);
  RingPtr ring = uv_ring();
  Polynomial one = ring->one();
  Polynomial p = random_bidegree(m, n, c, -9, 9);
  Polynomial q = random_bidegree(m, n, c, 1, 9);  // positive coefficients: no pole on u, v >= 0
  return {"height-patch/rational-" + std::to_string(m) + "x" + std::to_string(n),
          {{"u", "v"}, {"x", "y", "z"}, {ring->var("u"), ring->var("v"), p}, {one, one, q}, {}}};
}

// x, y, z of total degree 2 in u, v with 9-digit coefficients (degree 4).
NamedParametrization big_coefficient_quadratic() {
  Coefficients c(9);
  RingPtr ring = uv_ring();
  Polynomial u = ring->var("u"), v = ring->var("v");
  const std::vector<Polynomial> monomials{ring->one(), u, v, u * u, u * v, v * v};
  std::vector<Polynomial> xyz;
  for (int k = 0; k < 3; ++k) {
    Polynomial f = ring->zero();
    for (const Polynomial& m : monomials) f += c.next(-999999999, 999999999) * m;
    xyz.push_back(f);
  }
  return {"quadratic-patch/9-digit", {{"u", "v"}, {"x", "y", "z"}, xyz, {}, {}}};
}

// A rational quadratic (Steiner) patch: x, y, z, w of total degree 2.
NamedParametrization rational_steiner() {
  Coefficients c(7);
  RingPtr ring = uv_ring();
  Polynomial u = ring->var("u"), v = ring->var("v");
  const std::vector<Polynomial> monomials{ring->one(), u, v, u * u, u * v, v * v};
  std::vector<Polynomial> f;
  for (int k = 0; k < 4; ++k) {
    Polynomial g = ring->zero();
    for (const Polynomial& m : monomials) g += c.next(k == 3 ? 1 : -9, 9) * m;
    f.push_back(g);
  }
  return {"rational-patch/steiner", {{"u", "v"}, {"x", "y", "z"}, {f[0], f[1], f[2]}, {f[3], f[3], f[3]}, {}}};
}

std::string bezier_name(unsigned m, unsigned n, bool rational) {
  const char* shape = m == 1 && n == 1 ? "bilinear" : m == 2 && n == 2 ? "biquadratic" : m == 3 && n == 3 ? "bicubic" : "";
  std::string name = *shape ? shape : std::to_string(m) + "x" + std::to_string(n);
  return std::string(rational ? "rational-bezier/" : "bezier/") + name;
}

}  // namespace

RationalParametrization bezier_patch(unsigned m, unsigned n, bool rational, unsigned seed) {
  Coefficients c(seed);
  RingPtr ring = uv_ring();
  Polynomial u = ring->var("u"), v = ring->var("v");
  std::vector<Polynomial> xyz(3, ring->zero());
  Polynomial w = ring->zero();
  for (unsigned i = 0; i <= m; ++i) {
    for (unsigned j = 0; j <= n; ++j) {
      const Polynomial basis = bernstein(m, i, u) * bernstein(n, j, v);
      const long weight = rational ? c.next(1, 3) : 1;
      for (Polynomial& coordinate : xyz) coordinate += weight * c.next(-5, 5) * basis;
      w += weight * basis;
    }
  }
  if (!rational) return {{"u", "v"}, {"x", "y", "z"}, xyz, {}, {}};
  return {{"u", "v"}, {"x", "y", "z"}, xyz, {w, w, w}, {}};
}

std::vector<NamedParametrization> patch_parametrizations(unsigned max_degree) {
  std::vector<NamedParametrization> out;
  out.push_back(height_patch(1, 1, 1));
  out.push_back(height_patch(2, 2, 2));
  out.push_back(height_patch(3, 3, 3));
  out.push_back(big_coefficient_quadratic());
  out.push_back(rational_steiner());
  for (unsigned d : {1u, 2u, 3u}) {
    for (bool rational : {false, true}) {
      if (2 * d * d > max_degree) continue;
      out.push_back({bezier_name(d, d, rational), bezier_patch(d, d, rational, 10 * d + (rational ? 1 : 0))});
    }
  }
  if (4 <= max_degree) out.push_back({bezier_name(2, 1, true), bezier_patch(2, 1, true, 21)});
  return out;
}

}  // namespace sdfwb::algebra::testing
