// The routes before any Groebner basis: solving for linear parameters, and
// interpolation modulo primes. Each result is checked against elimination
// or by exact substitution.

#include "algebra/implicit_interpolation.h"
#include "algebra/implicitization.h"
#include "example_systems.h"

#include <gtest/gtest.h>

namespace sdfwb::algebra {
namespace {

ImplicitizationOptions eliminationOnly() {
  ImplicitizationOptions options;
  options.substituteLinear = false;
  options.interpolate = false;
  return options;
}

TEST(LinearParameters, SolvedAndSubstituted) {
  auto uv = Ring::make({"u", "v"});
  Polynomial u = uv->var("u"), v = uv->var("v");
  // u = x and v = (x - y)/2 (a constant coefficient); z is then a polynomial.
  RationalParametrization p{{"u", "v"}, {"x", "y", "z"}, {u, u - 2 * v, u * pow(v, 3) - 1}, {}, {}};
  EliminationProblem reduced = substituteLinearParameters(implicitizationIdeal(p));
  EXPECT_TRUE(reduced.eliminated.empty());
  ASSERT_EQ(reduced.ideal.generators().size(), 1u);
  ImplicitizationResult r = implicitize(p);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.method, "substitution");
  ASSERT_EQ(r.generators.size(), 1u);
  EXPECT_EQ(r.generators[0].toString(), "x^4 - 3*x^3*y + 3*x^2*y^2 - x*y^3 - 8*z - 8");
  EXPECT_TRUE(substituteParametrization(r.generators[0], p).isZero());
}

TEST(LinearParameters, NotForANonConstantCoefficient) {
  auto uv = Ring::make({"u", "v"});
  Polynomial u = uv->var("u"), v = uv->var("v");
  // u occurs linearly in x = u*v only with the coefficient v: nothing to solve.
  RationalParametrization p{{"u", "v"}, {"x", "y", "z"}, {u * v, pow(v, 2), pow(u, 2)}, {}, {}};
  EliminationProblem reduced = substituteLinearParameters(implicitizationIdeal(p));
  EXPECT_EQ(reduced.eliminated.size(), 2u);
}

TEST(LinearParameters, HeightPatchWithDenominator) {
  for (const testing::NamedParametrization& example : testing::patchParametrizations()) {
    if (example.name.rfind("height-patch/", 0) != 0) continue;
    SCOPED_TRACE(example.name);
    ImplicitizationResult fast = implicitize(example.parametrization);
    ASSERT_TRUE(fast.ok()) << fast.message;
    EXPECT_EQ(fast.method, "substitution");
    ImplicitizationResult slow = implicitize(example.parametrization, eliminationOnly());
    ASSERT_TRUE(slow.ok()) << slow.message;
    EXPECT_EQ(fast.generators, slow.generators);
  }
}

TEST(Interpolation, AgreesWithEliminationOnLowDegrees) {
  std::vector<testing::NamedParametrization> examples = testing::patchParametrizations(4);
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    if (example.parametrization.relations.empty()) examples.push_back(example);
  }
  for (const testing::NamedParametrization& example : examples) {
    SCOPED_TRACE(example.name);
    ImplicitizationOptions options;
    options.substituteLinear = false;
    options.eliminationTrial = false;
    ImplicitizationResult fast = implicitize(example.parametrization, options);
    ASSERT_TRUE(fast.ok()) << fast.message;
    EXPECT_EQ(fast.method, "interpolation");
    ImplicitizationResult slow = implicitize(example.parametrization, eliminationOnly());
    ASSERT_TRUE(slow.ok()) << slow.message;
    EXPECT_EQ(fast.generators, slow.generators);
  }
}

// The route follows the input's cost, not its name: a sparse polynomial
// parametrization (Enneper's surface, implicit degree 9 with 23 of the 220
// possible terms) is eliminated within the trial's share, a dense one of
// the same degrees (random cubics) is not and is interpolated, and the
// equations agree with the other route.
TEST(Interpolation, EliminationTrialChoosesByCost) {
  auto uv = Ring::make({"u", "v"});
  Polynomial u = uv->var("u"), v = uv->var("v");
  RationalParametrization sparse{{"u", "v"}, {"x", "y", "z"},
                                 {3 * u + 3 * u * pow(v, 2) - pow(u, 3), 3 * v + 3 * pow(u, 2) * v - pow(v, 3),
                                  3 * pow(u, 2) - 3 * pow(v, 2)}, {}, {}};
  auto cubic = [&](int a, int b, int c, int d, int e) {
    return a * pow(u, 3) - b * pow(u, 2) * v + c * u * pow(v, 2) + d * pow(v, 3) - e * pow(u, 2) + 4 * u * v -
           2 * pow(v, 2) + 7 * u - v + 1;
  };
  RationalParametrization dense{
      {"u", "v"}, {"x", "y", "z"}, {cubic(3, 2, 1, 5, 1), cubic(-1, -4, 2, -3, -2), cubic(2, -1, -3, 1, -3)}, {}, {}};
  ImplicitizationOptions interpolationOnly;
  interpolationOnly.eliminationTrial = false;
  for (const auto& [p, route] : {std::pair{sparse, "elimination"}, std::pair{dense, "interpolation"}}) {
    ImplicitizationResult chosen = implicitize(p);
    ASSERT_TRUE(chosen.ok()) << chosen.message;
    EXPECT_EQ(chosen.method, route);
    EXPECT_EQ(chosen.degree(), 9u);
    ImplicitizationResult interpolated = implicitize(p, interpolationOnly);
    ASSERT_TRUE(interpolated.ok()) << interpolated.message;
    EXPECT_EQ(interpolated.method, "interpolation");
    EXPECT_EQ(chosen.generators, interpolated.generators);
  }
}

// Degree 8 (a biquadratic Bezier patch): far beyond what elimination does
// quickly; checked by exact substitution instead.
TEST(Interpolation, BiquadraticPatches) {
  for (bool rational : {false, true}) {
    RationalParametrization p = testing::bezierPatch(2, 2, rational, 7);
    ImplicitizationResult r = implicitize(p);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(r.method, "interpolation");
    ASSERT_EQ(r.generators.size(), 1u);
    EXPECT_EQ(r.degree(), 8u);
    EXPECT_TRUE(substituteParametrization(r.generators[0], p).isZero());
  }
}

TEST(Interpolation, DoesNotApplyToCurvesInSpaceOrRelations) {
  auto t = Ring::make({"t"});
  Polynomial x = t->var("t");
  GroebnerStats stats;
  Budget budget;
  BudgetMonitor monitor(budget);
  RingPtr xyz = Ring::make({"x", "y", "z"});
  RationalParametrization twisted{{"t"}, {"x", "y", "z"}, {x, pow(x, 2), pow(x, 3)}, {}, {}};
  EXPECT_FALSE(implicitizeByInterpolation(twisted, xyz, monitor, stats));
  // A surface that is really a curve: the nullspace never has dimension 1.
  auto uv = Ring::make({"u", "v"});
  Polynomial s = uv->var("u") + uv->var("v");
  RationalParametrization degenerate{{"u", "v"}, {"x", "y", "z"}, {s, pow(s, 2), pow(s, 3)}, {}, {}};
  EXPECT_FALSE(implicitizeByInterpolation(degenerate, xyz, monitor, stats));
  ImplicitizationResult r = implicitize(degenerate);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.method, "substitution+elimination");  // u = x - v, then Groebner
  EXPECT_EQ(r.generators.size(), 3u);               // the twisted cubic: x^2 - y, x*y - z, y^2 - x*z
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    if (example.parametrization.relations.empty()) continue;
    EXPECT_FALSE(implicitizeByInterpolation(example.parametrization, xyz, monitor, stats)) << example.name;
  }
}

TEST(Interpolation, PlaneCurves) {
  auto t = Ring::make({"t"});
  Polynomial x = t->var("t");
  RationalParametrization cusp{{"t"}, {"x", "y"}, {pow(x, 2), pow(x, 3)}, {}, {}};
  ImplicitizationOptions interpolation;
  interpolation.eliminationTrial = false;
  ImplicitizationResult r = implicitize(cusp, interpolation);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.method, "interpolation");
  ASSERT_EQ(r.generators.size(), 1u);
  EXPECT_EQ(r.generators[0].toString(), "x^3 - y^2");
  // The folium of Descartes, rational: x = 3t/(1+t^3), y = 3t^2/(1+t^3).
  Polynomial d = 1 + pow(x, 3);
  RationalParametrization folium{{"t"}, {"x", "y"}, {3 * x, 3 * pow(x, 2)}, {d, d}, {}};
  r = implicitize(folium);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.generators.size(), 1u);
  EXPECT_EQ(r.generators[0].toString(), "x^3 + y^3 - 3*x*y");
}

}  // namespace
}  // namespace sdfwb::algebra
