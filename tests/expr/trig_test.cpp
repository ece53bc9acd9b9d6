// Trigonometric parametrizations to exact rational ones: the torus, the
// Moebius strip and the cross-cap, with both strategies. Substituting the
// result into the known implicit equations gives exactly 0, and the result
// agrees with the trigonometric formulas evaluated in double precision.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "algebra/implicitization.h"
#include "algebra/ring.h"
#include "expr/identifier.h"
#include "expr/to_algebra.h"
#include "expr/trig.h"
#include "formula_eval.h"

namespace sdfwb::expr {
namespace {

using algebra::Rational;

constexpr const char* kTorus = "x = (2 + cos(v)/2)*cos(u); y = (2 + cos(v)/2)*sin(u); z = sin(v)/2";
constexpr const char* kMoebius =
    "let w = 1 + v/2*cos(u/2); x = w*cos(u); y = w*sin(u); z = v/2*sin(u/2)";
constexpr const char* kCrossCap = "x = sin(u)*sin(2*v)/2; y = sin(2*u)*cos(v)^2; z = cos(2*u)*cos(v)^2";

using Implicit = std::function<Rational(const Rational&, const Rational&, const Rational&)>;

Rational torusEquation(const Rational& x, const Rational& y, const Rational& z) {
  const Rational R = 2, r = Rational(1, 2);
  const Rational s = x * x + y * y + z * z + R * R - r * r;
  return s * s - 4 * R * R * (x * x + y * y);
}

Rational moebiusEquation(const Rational& x, const Rational& y, const Rational& z) {
  return -y + x * x * y + y * y * y - 2 * x * z - 2 * x * x * z - 2 * y * y * z + y * z * z;
}

Rational crossCapEquation(const Rational& x, const Rational& y, const Rational& z) {
  return 4 * x * x * (x * x + y * y + z * z + z) + y * y * (y * y + z * z - 1);
}

// A point of the rational parametrization from one rational t per angle (the
// tangent of half of psi) and a rational value per other parameter, with the
// matching values of the user's parameters.
struct Sample {
  std::vector<Rational> parameters;  // of the conversion's ring
  std::vector<double> userValues;    // of the equations' graph variables
};

Sample sample(const ParametricEquations& eq, const TrigConversion& c, std::mt19937& rng) {
  std::uniform_int_distribution<int> numerator(-40, 40);
  Sample s;
  s.parameters.resize(c.parametrization.parameters.size());
  auto indexOf = [&](const std::string& name) {
    return std::find(c.parametrization.parameters.begin(), c.parametrization.parameters.end(), name) - c.parametrization.parameters.begin();
  };
  for (const std::string& name : eq.graph.variables()) {
    Rational t(numerator(rng), 16);
    t.canonicalize();
    const auto angle = std::find_if(c.angles.begin(), c.angles.end(),
                                    [&](const AngleSubstitution& a) { return a.parameter == name; });
    if (angle == c.angles.end()) {
      s.parameters[indexOf(name)] = t;
      s.userValues.push_back(t.get_d());
      continue;
    }
    const Rational denominator = 1 + t * t;
    if (angle->replacements.size() == 1) {
      s.parameters[indexOf(angle->replacements[0])] = t;
    } else {
      s.parameters[indexOf(angle->replacements[0])] = (1 - t * t) / denominator;
      s.parameters[indexOf(angle->replacements[1])] = 2 * t / denominator;
    }
    s.userValues.push_back(angle->scale.get_d() * 2 * std::atan(t.get_d()));
  }
  return s;
}

void checkConversion(std::string_view source, TrigStrategy strategy, const Implicit& implicit) {
  SCOPED_TRACE(std::string(source) + (strategy == TrigStrategy::HalfAngle ? " (half-angle)" : " (c, s)"));
  const ParametricEquations eq = compileParametricEquations(source);
  const TrigConversion c = toRationalParametrization(eq, strategy);
  ASSERT_EQ(c.parametrization.coordinates, (std::vector<std::string>{"x", "y", "z"}));
  for (const AngleSubstitution& a : c.angles) {
    for (const std::string& name : a.replacements) EXPECT_FALSE(isIdentifier(name)) << name;
  }
  std::vector<NodeId> outputs;
  for (const CoordinateEquation& e : eq.equations) outputs.push_back(e.value);
  const Tape tape(eq.graph, outputs);
  Evaluator<double> evaluate(tape);
  std::mt19937 rng(17);
  for (int i = 0; i < 25; ++i) {
    const Sample s = sample(eq, c, rng);
    for (const algebra::Polynomial& relation : c.parametrization.relations) EXPECT_EQ(algebra::evaluate(relation, s.parameters), 0);
    Rational xyz[3];
    for (int k = 0; k < 3; ++k) {
      const Rational denominator = algebra::evaluate(c.parametrization.denominators[k], s.parameters);
      ASSERT_NE(denominator, 0);
      xyz[k] = algebra::evaluate(c.parametrization.numerators[k], s.parameters) / denominator;
    }
    EXPECT_EQ(implicit(xyz[0], xyz[1], xyz[2]), 0);
    const auto expected = evaluate(s.userValues);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(xyz[k].get_d(), expected[k], 1e-12);
  }
}

TEST(Trig, ClassicSurfacesBothStrategies) {
  for (TrigStrategy strategy : {TrigStrategy::HalfAngle, TrigStrategy::CosSinRelation}) {
    checkConversion(kTorus, strategy, torusEquation);
    checkConversion(kMoebius, strategy, moebiusEquation);
    checkConversion(kCrossCap, strategy, crossCapEquation);
  }
}

TEST(Trig, HalfAngleParametersAndDenominators) {
  const TrigConversion c = toRationalParametrization(compileParametricEquations(kTorus), TrigStrategy::HalfAngle);
  ASSERT_EQ(c.parametrization.parameters.size(), 2u);
  EXPECT_EQ(c.parametrization.parameters[0], "$t_v");
  EXPECT_EQ(c.parametrization.parameters[1], "$t_u");
  EXPECT_TRUE(c.parametrization.relations.empty());
  const auto ring = algebra::Ring::make(c.parametrization.parameters);
  const auto tv = ring->var("$t_v"), tu = ring->var("$t_u");
  // z = sin(v)/2 = t/(1 + t^2); x and y share the lcm (1 + tu^2)(1 + tv^2).
  EXPECT_EQ(c.parametrization.numerators[2].inRing(ring), tv);
  EXPECT_EQ(c.parametrization.denominators[2].inRing(ring), 1 + tv * tv);
  EXPECT_EQ(c.parametrization.denominators[0].inRing(ring), (1 + tu * tu) * (1 + tv * tv));
}

TEST(Trig, RationalMultiplesAreRescaled) {
  const TrigConversion c = toRationalParametrization(compileParametricEquations(kMoebius), TrigStrategy::CosSinRelation);
  ASSERT_EQ(c.angles.size(), 1u);
  EXPECT_EQ(c.angles[0].parameter, "u");
  EXPECT_EQ(c.angles[0].scale, Rational(2));  // u = 2 psi: cos(u/2) = cos psi, cos(u) = cos 2psi
  EXPECT_EQ(c.parametrization.parameters, (std::vector<std::string>{"v", "$c_u", "$s_u"}));  // in order of first use
  ASSERT_EQ(c.parametrization.relations.size(), 1u);
  EXPECT_EQ(c.parametrization.relations[0].toString(), "$c_u^2 + $s_u^2 - 1");
  // Only the gcd of the multiples matters: cos(2v) and sin(4v) use psi = 2v, v = psi/2.
  const TrigConversion d = toRationalParametrization(compileParametricEquations("x = cos(2*v); y = sin(4*v)"),
                                                     TrigStrategy::CosSinRelation);
  EXPECT_EQ(d.angles[0].scale, Rational(1, 2));
  EXPECT_EQ(d.parametrization.numerators[0].toString(), "$c_v");
  EXPECT_EQ(d.parametrization.numerators[1].toString(), "2*$c_v*$s_v");
}

TEST(Trig, SumsTangentsAndPlainParameters) {
  const TrigConversion sum = toRationalParametrization(compileParametricEquations("x = cos(u - v)"),
                                                       TrigStrategy::CosSinRelation);
  EXPECT_EQ(sum.parametrization.numerators[0].toString(), "$c_u*$c_v + $s_u*$s_v");
  const TrigConversion tangent = toRationalParametrization(compileParametricEquations("x = tan(u)"),
                                                           TrigStrategy::HalfAngle);
  EXPECT_EQ(tangent.parametrization.numerators[0].toString(), "-2*$t_u");
  EXPECT_EQ(tangent.parametrization.denominators[0].toString(), "$t_u^2 - 1");
  const TrigConversion plain = toRationalParametrization(compileParametricEquations("x = u*v; y = v; z = u^2"),
                                                         TrigStrategy::HalfAngle);
  EXPECT_EQ(plain.parametrization.parameters, (std::vector<std::string>{"u", "v"}));
  EXPECT_EQ(plain.parametrization.numerators[2].toString(), "u^2");
  EXPECT_EQ(plain.parametrization.denominators[0].toString(), "1");
}

TEST(Trig, InternalNamesAvoidUserNames) {
  // A user parameter may be called t_u; the new one is "$t_u", which it cannot be.
  const TrigConversion c = toRationalParametrization(compileParametricEquations("x = cos(u); y = t_u"),
                                                     TrigStrategy::HalfAngle);
  EXPECT_EQ(c.parametrization.parameters, (std::vector<std::string>{"$t_u", "t_u"}));
}

std::string trigError(std::string_view source) {
  return testing::errorOf(
      [](std::string_view s) { return toRationalParametrization(compileParametricEquations(s), TrigStrategy::HalfAngle); },
      source);
}

TEST(Trig, Errors) {
  EXPECT_EQ(trigError("x = cos(u^2)"), "column 5: the argument of 'cos' must be a rational multiple of parameters, such as 2*v or v/2");
  EXPECT_EQ(trigError("x = sin(u + 1)"), "column 5: the argument of 'sin' must be a rational multiple of parameters, such as 2*v or v/2");
  EXPECT_EQ(trigError("x = u*cos(u)"), "column 6: 'u' is used both inside and outside sin/cos/tan, so the parametrization is not rational");
  EXPECT_EQ(trigError("x = u; y = cos(u)"), "column 1: 'u' is used both inside and outside sin/cos/tan, so the parametrization is not rational");
  EXPECT_EQ(trigError("x = sqrt(u)"), "column 5: 'sqrt' is not a polynomial or rational function");
  EXPECT_EQ(trigError("x = cos(u) + cos(u/101)"), "column 5: the multiples of 'u' are too far apart for an exact conversion (at most 100 times the smallest)");
}

// End to end with algebra::implicitize: the textbook equations come out.
void expectImplicitEquation(std::string_view source, TrigStrategy strategy, std::string_view expected) {
  SCOPED_TRACE(std::string(source));
  const TrigConversion c = parseParametrization(source, strategy);
  algebra::ImplicitizationOptions options;
  options.groebner.budget.timeLimitSeconds = 30;  // milliseconds expected; never hang the suite
  const algebra::ImplicitizationResult r = algebra::implicitize(c.parametrization, options);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.generators.size(), 1u);
  EXPECT_EQ(r.generators[0], parsePolynomials(expected, r.ring)[0].primitive());
  EXPECT_TRUE(algebra::substituteParametrization(r.generators[0], c.parametrization).isZero());
}

TEST(Trig, ImplicitizesClassicSurfaces) {
  for (TrigStrategy strategy : {TrigStrategy::HalfAngle, TrigStrategy::CosSinRelation}) {
    expectImplicitEquation(kTorus, strategy, "(x^2 + y^2 + z^2 + 4 - 1/4)^2 - 16*(x^2 + y^2)");
  }
  // The default strategy; half-angle takes minutes on these two (see trig.h).
  expectImplicitEquation(kMoebius, TrigStrategy::CosSinRelation,
                         "-y + x^2*y + y^3 - 2*x*z - 2*x^2*z - 2*y^2*z + y*z^2");
  expectImplicitEquation(kCrossCap, TrigStrategy::CosSinRelation, "4*x^2*(x^2 + y^2 + z^2 + z) + y^2*(y^2 + z^2 - 1)");
  expectImplicitEquation("x = u*v; y = v; z = u^2", TrigStrategy::CosSinRelation, "y^2*z - x^2");
}

}  // namespace
}  // namespace sdfwb::expr
