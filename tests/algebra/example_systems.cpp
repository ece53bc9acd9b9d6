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

std::vector<NamedSystem> smallSystems() {
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

namespace {

// cos and sin of one angle, either as variables c, s with c^2 + s^2 = 1 or
// by the half-angle substitution in t: ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)).
struct Angle {
  Polynomial cosNum, sinNum, den;
};

struct TrigBuilder {
  bool halfAngle;
  std::vector<std::string> names;  // per angle: {"c", "s"} or {"t"}
  RingPtr ring;
  std::vector<Polynomial> relations;

  TrigBuilder(bool half, const std::vector<std::string>& angles) : halfAngle(half) {
    for (const std::string& a : angles) {
      if (half) {
        names.push_back("t" + a);
      } else {
        names.push_back("c" + a);
        names.push_back("s" + a);
      }
    }
  }
  void addParameter(const std::string& name) { names.push_back(name); }
  void finish() {
    ring = Ring::make(names);
    if (!halfAngle) {
      for (std::size_t i = 0; i + 1 < names.size(); i += 2) {
        if (names[i][0] != 'c') break;
        relations.push_back(pow(ring->var(names[i]), 2) + pow(ring->var(names[i + 1]), 2) - 1);
      }
    }
  }
  Angle angle(const std::string& a) const {
    if (halfAngle) {
      Polynomial t = ring->var("t" + a);
      return {1 - pow(t, 2), 2 * t, 1 + pow(t, 2)};
    }
    return {ring->var("c" + a), ring->var("s" + a), ring->one()};
  }
};

NamedParametrization torus(bool half) {
  // x = (2 + cos v) cos u, y = (2 + cos v) sin u, z = sin v.
  TrigBuilder b(half, {"u", "v"});
  b.finish();
  Angle u = b.angle("u"), v = b.angle("v");
  Polynomial ringRadius = 2 * v.den + v.cosNum;  // (2 + cos v) * den_v
  RationalParametrization p{b.names, {"x", "y", "z"},
                            {ringRadius * u.cosNum, ringRadius * u.sinNum, v.sinNum},
                            {v.den * u.den, v.den * u.den, v.den}, b.relations};
  return {std::string("torus/") + (half ? "half-angle" : "cs"), p};
}

NamedParametrization crossCap(bool half) {
  // x = cos u sin 2v, y = sin u sin 2v, z = cos^2 v - cos^2 u sin^2 v.
  TrigBuilder b(half, {"u", "v"});
  b.finish();
  Angle u = b.angle("u"), v = b.angle("v");
  Polynomial sin2v = 2 * v.sinNum * v.cosNum;  // / den_v^2
  Polynomial zNum = pow(v.cosNum, 2) * pow(u.den, 2) - pow(u.cosNum, 2) * pow(v.sinNum, 2);
  RationalParametrization p{b.names, {"x", "y", "z"},
                            {u.cosNum * sin2v, u.sinNum * sin2v, zNum},
                            {u.den * pow(v.den, 2), u.den * pow(v.den, 2), pow(u.den, 2) * pow(v.den, 2)},
                            b.relations};
  return {std::string("cross-cap/") + (half ? "half-angle" : "cs"), p};
}

NamedParametrization moebius(bool half) {
  // x = (1 + v/2 cos(u/2)) cos u, y = (1 + v/2 cos(u/2)) sin u, z = v/2 sin(u/2),
  // with w = u/2: cos u = cos^2 w - sin^2 w, sin u = 2 sin w cos w.
  TrigBuilder b(half, {"w"});
  b.addParameter("v");
  b.finish();
  Angle w = b.angle("w");
  Polynomial v = b.ring->var("v");
  Polynomial radius = 2 * w.den + v * w.cosNum;  // 2 * den_w * (1 + v/2 cos w)
  Polynomial cosU = pow(w.cosNum, 2) - pow(w.sinNum, 2), sinU = 2 * w.sinNum * w.cosNum;
  RationalParametrization p{b.names, {"x", "y", "z"},
                            {radius * cosU, radius * sinU, v * w.sinNum},
                            {2 * pow(w.den, 3), 2 * pow(w.den, 3), 2 * w.den}, b.relations};
  return {std::string("moebius/") + (half ? "half-angle" : "cs"), p};
}

NamedParametrization dupinCyclide(bool half) {
  // a = 5, c = 3, b = 4, d = 2:
  // x = (d (c - a cos u cos v) + b^2 cos u) / (a - c cos u cos v)
  // y = b sin u (a - d cos v) / (a - c cos u cos v)
  // z = b sin v (c cos u - d) / (a - c cos u cos v)
  TrigBuilder b(half, {"u", "v"});
  b.finish();
  Angle u = b.angle("u"), v = b.angle("v");
  Polynomial duv = u.den * v.den;
  Polynomial denominator = 5 * duv - 3 * u.cosNum * v.cosNum;  // (a - c cu cv) * du dv
  Polynomial x = 2 * (3 * duv - 5 * u.cosNum * v.cosNum) + 16 * u.cosNum * v.den;
  Polynomial y = 4 * u.sinNum * (5 * v.den - 2 * v.cosNum);
  Polynomial z = 4 * v.sinNum * (3 * u.cosNum - 2 * u.den);
  RationalParametrization p{b.names, {"x", "y", "z"}, {x, y, z}, {denominator, denominator, denominator},
                            b.relations};
  return {std::string("dupin-cyclide/") + (half ? "half-angle" : "cs"), p};
}

}  // namespace

std::vector<NamedParametrization> classicParametrizations() {
  std::vector<NamedParametrization> out;
  auto uv = Ring::make({"u", "v"});
  Polynomial u = uv->var("u"), v = uv->var("v");
  out.push_back({"tangent-surface", {{"u", "v"}, {"x", "y", "z"},
                                     {u + v, pow(u, 2) + 2 * u * v, pow(u, 3) + 3 * pow(u, 2) * v}, {}, {}}});
  out.push_back({"whitney-umbrella", {{"u", "v"}, {"x", "y", "z"}, {u * v, v, pow(u, 2)}, {}, {}}});
  Polynomial d = pow(u, 2) + pow(v, 2) + 1;
  out.push_back({"sphere-stereographic",
                 {{"u", "v"}, {"x", "y", "z"}, {2 * u, 2 * v, pow(u, 2) + pow(v, 2) - 1}, {d, d, d}, {}}});
  out.push_back({"enneper", {{"u", "v"}, {"x", "y", "z"},
                             {3 * u + 3 * u * pow(v, 2) - pow(u, 3), 3 * v + 3 * pow(u, 2) * v - pow(v, 3),
                              3 * pow(u, 2) - 3 * pow(v, 2)}, {}, {}}});
  for (bool half : {false, true}) {
    out.push_back(torus(half));
    out.push_back(crossCap(half));
    out.push_back(moebius(half));
    out.push_back(dupinCyclide(half));
  }
  return out;
}

std::vector<std::string> strings(const std::vector<Polynomial>& polys) {
  std::vector<std::string> out;
  for (const Polynomial& p : polys) out.push_back(p.toString());
  return out;
}

}  // namespace sdfwb::algebra::testing
