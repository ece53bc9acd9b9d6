// The symbolic derivative: against central finite differences, at singular
// points, and the size of what it builds.

#include <gtest/gtest.h>

#include <random>

#include "formula_eval.h"

namespace sdfwb::expr {
namespace {

// Value and gradient of a formula over space, from one tape.
struct Sampler {
  explicit Sampler(std::string_view source) : formula(compileSdf(source)) {
    const auto g = gradient(formula.graph, formula.value);
    const NodeId outputs[] = {formula.value, g[0], g[1], g[2]};
    tape.emplace(formula.graph, outputs);
  }
  std::array<double, 4> operator()(glm::dvec3 p) const {
    Evaluator<double> evaluate(*tape);
    const double xyz[] = {p.x, p.y, p.z};
    const auto out = evaluate(xyz);
    return {out[0], out[1], out[2], out[3]};
  }
  SpaceFormula formula;
  std::optional<Tape> tape;
};

void expectGradientMatchesFiniteDifferences(std::string_view source, double lo, double hi) {
  const Sampler f(source);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(lo, hi);
  const double h = 1e-6;
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
    const auto exact = f(p);
    for (int axis = 0; axis < 3; ++axis) {
      glm::dvec3 step(0);
      step[axis] = h;
      const double numeric = (f(p + step)[0] - f(p - step)[0]) / (2 * h);
      EXPECT_NEAR(exact[1 + axis], numeric, 1e-5 * (1 + std::abs(numeric)))
          << source << " at (" << p.x << ", " << p.y << ", " << p.z << "), axis " << axis;
    }
  }
}

TEST(Derivative, MatchesFiniteDifferences) {
  expectGradientMatchesFiniteDifferences("length(p) - 1.5", -3, 3);
  expectGradientMatchesFiniteDifferences("length(vec2(length(p.xz) - 1.0, p.y)) - 0.25", -3, 3);
  expectGradientMatchesFiniteDifferences(
      "let q = abs(p) - vec3(1, 0.5, 2); length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0)", -3, 3);
  expectGradientMatchesFiniteDifferences("sin(x*y) + exp(z/3) + log(x*x + 1) + tan(z/4) - cos(2*x)", -2, 2);
  expectGradientMatchesFiniteDifferences("pow(x*x + 1, 1.5) + (y + 3)^-2 + x/(y*y + 1) - z^3", -2, 2);
  expectGradientMatchesFiniteDifferences("pow(y*y + 1, x) + sqrt(x*x + z*z + 1) * cos(z)", -2, 2);
  expectGradientMatchesFiniteDifferences("mix(x, y, 0.3) + smoothstep(-3, 3, z) + clamp(x*y, -1, 1)", -2, 2);
  expectGradientMatchesFiniteDifferences("mod(x*3, 2) + fract(y) + floor(z) + sign(x)*y", -2, 2);
  expectGradientMatchesFiniteDifferences("dot(normalize(p), vec3(1, 2, 3)) + length(cross(p, vec3(0, 1, 0)))", 0.5, 2);
  expectGradientMatchesFiniteDifferences("x^2*y + x*z/(1 + y^2)", -2, 2);  // a rational function
}

TEST(Derivative, FiniteAtSingularPoints) {
  const Sampler sphere("length(p) - 1");
  const auto atCenter = sphere({0, 0, 0});
  EXPECT_EQ(atCenter[1], 0);
  EXPECT_EQ(atCenter[2], 0);
  EXPECT_EQ(atCenter[3], 0);
  const Sampler roots("sqrt(x) + log(y) + pow(z, 0.5)");
  for (double v : roots({0, 0, 0})) EXPECT_TRUE(std::isfinite(v));
  for (double v : roots({-1, -1, -1})) EXPECT_TRUE(std::isfinite(v));
}

TEST(Derivative, SimplifiesZerosAndOnes) {
  SpaceFormula f = compileSdf("x*y + 3*z");
  Graph& g = f.graph;
  EXPECT_EQ(derivative(g, f.value, 0), g.variable(1));  // d/dx = y exactly
  EXPECT_TRUE(g.isConstant(derivative(g, f.value, 2), 3));
  SpaceFormula power = compileSdf("x^5");
  EXPECT_TRUE(power.graph.isConstant(derivative(power.graph, power.value, 2), 0));
}

TEST(Derivative, GradientOfASphereStaysSmall) {
  Sampler sphere("length(p) - 1");
  EXPECT_LE(sphere.tape->instructions().size(), 30u);
}

}  // namespace
}  // namespace sdfwb::expr
