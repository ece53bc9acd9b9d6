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

RingPtr uvRing() { return Ring::make({"u", "v"}); }

// Bernstein basis polynomial B_i^n(t) = C(n, i) t^i (1 - t)^(n - i).
Polynomial bernstein(unsigned n, unsigned i, const Polynomial& t) {
  long binomial = 1;
  for (unsigned k = 0; k < i; ++k) binomial = binomial * static_cast<long>(n - k) / static_cast<long>(k + 1);
  return binomial * pow(t, i) * pow(1 - t, n - i);
}

// A polynomial of bidegree (m, n) in u, v with coefficients in [low, high].
Polynomial randomBidegree(unsigned m, unsigned n, Coefficients& c, long low, long high) {
  RingPtr ring = uvRing();
  Polynomial f = ring->zero();
  for (unsigned i = 0; i <= m; ++i) {
    for (unsigned j = 0; j <= n; ++j) f += c.next(low, high) * pow(ring->var("u"), i) * pow(ring->var("v"), j);
  }
  return f;
}

NamedParametrization heightPatch(unsigned m, unsigned n, unsigned seed) {
  Coefficients c(seed);
  RingPtr ring = uvRing();
  Polynomial one = ring->one();
  Polynomial p = randomBidegree(m, n, c, -9, 9);
  Polynomial q = randomBidegree(m, n, c, 1, 9);  // positive coefficients: no pole on u, v >= 0
  return {"height-patch/rational-" + std::to_string(m) + "x" + std::to_string(n),
          {{"u", "v"}, {"x", "y", "z"}, {ring->var("u"), ring->var("v"), p}, {one, one, q}, {}}};
}

// x, y, z of total degree 2 in u, v with 9-digit coefficients (degree 4).
NamedParametrization bigCoefficientQuadratic() {
  Coefficients c(9);
  RingPtr ring = uvRing();
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
NamedParametrization rationalSteiner() {
  Coefficients c(7);
  RingPtr ring = uvRing();
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

std::string bezierName(unsigned m, unsigned n, bool rational) {
  const char* shape = m == 1 && n == 1 ? "bilinear" : m == 2 && n == 2 ? "biquadratic" : m == 3 && n == 3 ? "bicubic" : "";
  std::string name = *shape ? shape : std::to_string(m) + "x" + std::to_string(n);
  return std::string(rational ? "rational-bezier/" : "bezier/") + name;
}

}  // namespace

RationalParametrization bezierPatch(unsigned m, unsigned n, bool rational, unsigned seed) {
  Coefficients c(seed);
  RingPtr ring = uvRing();
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

std::vector<NamedParametrization> patchParametrizations(unsigned maxDegree) {
  std::vector<NamedParametrization> out;
  out.push_back(heightPatch(1, 1, 1));
  out.push_back(heightPatch(2, 2, 2));
  out.push_back(heightPatch(3, 3, 3));
  out.push_back(bigCoefficientQuadratic());
  out.push_back(rationalSteiner());
  for (unsigned d : {1u, 2u, 3u}) {
    for (bool rational : {false, true}) {
      if (2 * d * d > maxDegree) continue;
      out.push_back({bezierName(d, d, rational), bezierPatch(d, d, rational, 10 * d + (rational ? 1 : 0))});
    }
  }
  if (4 <= maxDegree) out.push_back({bezierName(2, 1, true), bezierPatch(2, 1, true, 21)});
  return out;
}

}  // namespace sdfwb::algebra::testing
