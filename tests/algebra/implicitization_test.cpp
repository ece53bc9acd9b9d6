// Textbook implicitizations (Cox, Little, O'Shea, "Ideals, Varieties, and
// Algorithms", chapter 3) with known answers, and the property that the
// result vanishes on the parametrization exactly.

#include "algebra/implicitization.h"
#include "algebra/rational_circles.h"

#include <gtest/gtest.h>

#include <map>

#include "example_systems.h"

namespace sdfwb::algebra {
namespace {

using testing::strings;

ImplicitizationResult checked(const RationalParametrization& p) {
  ImplicitizationResult r = implicitize(p);
  EXPECT_TRUE(r.ok()) << r.message;
  for (const Polynomial& g : r.generators) {
    EXPECT_TRUE(substituteParametrization(g, p).isZero()) << g;
  }
  return r;
}

TEST(Implicitization, TwistedCubic) {
  auto t = Ring::make({"t"});
  Polynomial tv = t->var("t");
  RationalParametrization p{{"t"}, {"x", "y", "z"}, {tv, pow(tv, 2), pow(tv, 3)}, {}, {}};
  ImplicitizationResult r = checked(p);
  EXPECT_EQ(strings(r.generators), (std::vector<std::string>{"y^2 - x*z", "x*y - z", "x^2 - y"}));
}

TEST(Implicitization, TangentSurfaceOfTwistedCubic) {
  // CLO 3.3: x = t + u, y = t^2 + 2tu, z = t^3 + 3t^2 u.
  auto ring = Ring::make({"t", "u"});
  Polynomial t = ring->var("t"), u = ring->var("u");
  RationalParametrization p{{"t", "u"}, {"x", "y", "z"},
                            {t + u, pow(t, 2) + 2 * t * u, pow(t, 3) + 3 * pow(t, 2) * u}, {}, {}};
  ImplicitizationResult r = checked(p);
  EXPECT_EQ(strings(r.generators),
            (std::vector<std::string>{"3*x^2*y^2 - 4*x^3*z - 4*y^3 + 6*x*y*z - z^2"}));
}

TEST(Implicitization, WhitneyUmbrella) {
  auto ring = Ring::make({"u", "v"});
  Polynomial u = ring->var("u"), v = ring->var("v");
  RationalParametrization p{{"u", "v"}, {"x", "y", "z"}, {u * v, v, pow(u, 2)}, {}, {}};
  ImplicitizationResult r = checked(p);
  EXPECT_EQ(strings(r.generators), (std::vector<std::string>{"y^2*z - x^2"}));
}

TEST(Implicitization, UnitSphereByStereographicProjection) {
  auto ring = Ring::make({"u", "v"});
  Polynomial u = ring->var("u"), v = ring->var("v");
  Polynomial d = pow(u, 2) + pow(v, 2) + 1;
  RationalParametrization p{{"u", "v"}, {"x", "y", "z"}, {2 * u, 2 * v, pow(u, 2) + pow(v, 2) - 1}, {d, d, d}, {}};
  ImplicitizationResult r = checked(p);
  EXPECT_EQ(strings(r.generators), (std::vector<std::string>{"x^2 + y^2 + z^2 - 1"}));
  // The product of the denominators gives the same ideal.
  ImplicitizationOptions product;
  product.denominator = DenominatorStrategy::Product;
  EXPECT_EQ(implicitize(p, product).generators, r.generators);
}

TEST(Implicitization, EnneperSurface) {
  // CLO 3.3 Exercise 11: x = 3u + 3uv^2 - u^3, y = 3v + 3u^2 v - v^3,
  // z = 3u^2 - 3v^2; the implicit equation has degree 9.
  auto ring = Ring::make({"u", "v"});
  Polynomial u = ring->var("u"), v = ring->var("v");
  RationalParametrization p{{"u", "v"},
                            {"x", "y", "z"},
                            {3 * u + 3 * u * pow(v, 2) - pow(u, 3), 3 * v + 3 * pow(u, 2) * v - pow(v, 3),
                             3 * pow(u, 2) - 3 * pow(v, 2)},
                            {},
                            {}};
  ImplicitizationResult r = checked(p);
  ASSERT_EQ(r.generators.size(), 1u);
  EXPECT_EQ(r.generators.front().totalDegree(), 9u);
  EXPECT_GT(r.generators.front().leadingCoefficient(), 0);
}

TEST(Implicitization, CircleWithTrigRelation) {
  // x = c, y = s with c^2 + s^2 = 1, and the half-angle form of the same circle.
  auto ring = Ring::make({"c", "s"});
  Polynomial c = ring->var("c"), s = ring->var("s");
  RationalParametrization trig{{"c", "s"}, {"x", "y"}, {c, s}, {}, {pow(c, 2) + pow(s, 2) - 1}};
  EXPECT_EQ(strings(checked(trig).generators), (std::vector<std::string>{"x^2 + y^2 - 1"}));
  auto half = Ring::make({"t"});
  Polynomial t = half->var("t");
  RationalParametrization rational{{"t"}, {"x", "y"}, {1 - pow(t, 2), 2 * t}, {1 + pow(t, 2), 1 + pow(t, 2)}, {}};
  EXPECT_EQ(strings(checked(rational).generators), (std::vector<std::string>{"x^2 + y^2 - 1"}));
}

TEST(Implicitization, CosSinRelationsBecomeTheCircleParametrization) {
  // Each c^2 + s^2 - 1 (times a constant) gives one parameter and no
  // relation; another relation is rewritten, one of another shape is kept.
  auto ring = Ring::make({"c", "s", "r"});
  Polynomial c = ring->var("c"), s = ring->var("s"), r = ring->var("r");
  RationalParametrization p{{"c", "s", "r"}, {"x", "y", "z"}, {r * c, r * s, c}, {r, 1 + 0 * r, 2 + s},
                            {3 * pow(c, 2) + 3 * pow(s, 2) - 3, pow(r, 2) - c}};
  std::optional<RationalParametrization> rational = rationalCircles(p);
  ASSERT_TRUE(rational);
  EXPECT_EQ(rational->parameters.size(), 2u);
  ASSERT_EQ(rational->relations.size(), 1u);
  EXPECT_FALSE(rationalCircles(*rational));
  RationalParametrization ellipse = p;
  ellipse.relations = {pow(c, 2) + 2 * pow(s, 2) - 1};
  EXPECT_FALSE(rationalCircles(ellipse));
  // Dupin's cyclide with cos/sin variables goes by interpolation of the
  // rational form; the equation is the one of the half-angle input.
  std::map<std::string, Polynomial> byName;
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    if (example.name.rfind("dupin-cyclide/", 0) != 0) continue;
    ImplicitizationResult result = implicitize(example.parametrization);
    ASSERT_TRUE(result.ok()) << result.message;
    byName.emplace(example.name, result.generators.at(0));
    if (example.name == "dupin-cyclide/cs") {
      EXPECT_EQ(result.method, "half-angle+interpolation");
    }
  }
  ASSERT_EQ(byName.size(), 2u);
  EXPECT_EQ(byName.at("dupin-cyclide/cs"), byName.at("dupin-cyclide/half-angle"));
}

TEST(Implicitization, ReducesFractionsBeforeTakingTheLcm) {
  // x = t^2/t = t, y = 1/(t+1): the fraction for x cancels completely.
  auto ring = Ring::make({"t"});
  Polynomial t = ring->var("t");
  RationalParametrization p{{"t"}, {"x", "y"}, {pow(t, 2), ring->one()}, {t, t + 1}, {}};
  EXPECT_EQ(strings(checked(p).generators), (std::vector<std::string>{"x*y + y - 1"}));
}

TEST(Implicitization, AuxiliaryNamesNeverCollide) {
  // A parameter called y (as the y of Theorem 1.8 is often written).
  auto ring = Ring::make({"y"});
  Polynomial y = ring->var("y");
  RationalParametrization p{{"y"}, {"a", "b"}, {ring->one(), y}, {y, ring->one()}, {}};
  EXPECT_EQ(strings(checked(p).generators), (std::vector<std::string>{"a*b - 1"}));
}

TEST(Implicitization, RejectsMalformedInput) {
  auto ring = Ring::make({"u", "x"});
  Polynomial u = ring->var("u");
  EXPECT_THROW(implicitize({{"u"}, {"x", "y"}, {u}, {}, {}}), std::invalid_argument);
  EXPECT_THROW(implicitize({{"u"}, {"u"}, {u}, {}, {}}), std::invalid_argument);
  EXPECT_THROW(implicitize({{"u"}, {"y"}, {ring->var("x")}, {}, {}}), std::invalid_argument);
  EXPECT_THROW(implicitize({{"u"}, {"y"}, {u}, {ring->zero()}, {}}), std::invalid_argument);
}


TEST(Implicitization, ClassicSurfacesVanishOnTheirParametrizations) {
  // Every classic surface gives one equation that vanishes exactly on the
  // parametrization, and the c/s-with-relation and half-angle forms of each
  // trigonometric surface give the same equation.
  std::map<std::string, Polynomial> bySurface;
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    SCOPED_TRACE(example.name);
    ImplicitizationResult r = implicitize(example.parametrization);
    ASSERT_TRUE(r.ok()) << r.message;
    ASSERT_EQ(r.generators.size(), 1u);
    const Polynomial& f = r.generators.front();
    EXPECT_TRUE(substituteParametrization(f, example.parametrization).isZero()) << f;
    const std::string surface = example.name.substr(0, example.name.find('/'));
    auto [it, inserted] = bySurface.emplace(surface, f);
    if (!inserted) {
      EXPECT_EQ(it->second, f);
    }
  }
}


RationalParametrization twistedCubic() {
  auto t = Ring::make({"t"});
  Polynomial tv = t->var("t");
  return {{"t"}, {"x", "y", "z"}, {tv, pow(tv, 2), pow(tv, 3)}, {}, {}};
}

std::vector<std::string> twistedCubicBasis(EliminationOrder order, GroebnerMethod method) {
  ImplicitizationOptions options;
  options.order = order;
  options.groebner.method = method;
  ImplicitizationResult r = implicitize(twistedCubic(), options);
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.ring->order(), coordinateOrder(order));
  std::vector<Polynomial> monic;
  for (const Polynomial& g : r.generators) monic.push_back(g.monic());
  EXPECT_TRUE(isReducedGroebnerBasis(monic));
  return strings(r.generators);
}

TEST(ImplicitizationOrder, EveryOrderGivesTheReducedBasisOfItsCoordinateOrder) {
  for (GroebnerMethod method : {GroebnerMethod::Automatic, GroebnerMethod::Rational}) {
    SCOPED_TRACE(method == GroebnerMethod::Rational ? "rational" : "automatic");
    EXPECT_EQ(twistedCubicBasis(EliminationOrder::BlockDegrevlex, method),
              (std::vector<std::string>{"y^2 - x*z", "x*y - z", "x^2 - y"}));
    const std::vector<std::string> lex{"y^3 - z^2", "x*z - y^2", "x*y - z", "x^2 - y"};
    EXPECT_EQ(twistedCubicBasis(EliminationOrder::BlockLex, method), lex);
    EXPECT_EQ(twistedCubicBasis(EliminationOrder::Lex, method), lex);
    // deglex ranks x*z above y^2, which leaves y^3 - z^2 outside the ideal
    // of the quadrics' leading monomials
    EXPECT_EQ(twistedCubicBasis(EliminationOrder::BlockDeglex, method),
              (std::vector<std::string>{"x*z - y^2", "x*y - z", "x^2 - y", "y^3 - z^2"}));
  }
}

TEST(ImplicitizationOrder, OneEquationIsTheSameUnderEveryOrder) {
  auto ring = Ring::make({"u", "v"});
  Polynomial u = ring->var("u"), v = ring->var("v");
  RationalParametrization whitney{{"u", "v"}, {"x", "y", "z"}, {u * v, v, pow(u, 2)}, {}, {}};
  for (const EliminationOrderName& entry : eliminationOrders()) {
    SCOPED_TRACE(entry.name);
    ImplicitizationOptions options;
    options.order = entry.order;
    ImplicitizationResult r = implicitize(whitney, options);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(strings(r.generators), (std::vector<std::string>{"y^2*z - x^2"}));
  }
}

TEST(ImplicitizationOrder, NamesReadBack) {
  EXPECT_EQ(eliminationOrders().front().order, ImplicitizationOptions{}.order);
  for (const EliminationOrderName& entry : eliminationOrders()) {
    EXPECT_EQ(eliminationOrderFromName(entry.name), entry.order);
  }
  EXPECT_FALSE(eliminationOrderFromName("degrevlex"));
}

}  // namespace
}  // namespace sdfwb::algebra
