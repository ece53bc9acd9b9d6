// CPU evaluation: known SDFs written as formulas against closed forms, in
// float and double; integer powers; the guards for GLSL-undefined cases.

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

#include "formula_eval.h"

namespace sdfwb::expr {
namespace {

using testing::sdfAt;

constexpr const char* kSphere = "length(p) - 1.5";
constexpr const char* kBox =
    "let q = abs(p) - vec3(1, 0.5, 2); length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0)";
constexpr const char* kTorus = "length(vec2(length(p.xz) - 1.0, p.y)) - 0.25";

template <class T>
T sphere(glm::vec<3, T> p) {
  return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z) - T(1.5);
}

template <class T>
T box(glm::vec<3, T> p) {
  const glm::vec<3, T> q = glm::abs(p) - glm::vec<3, T>(1, 0.5, 2);
  const glm::vec<3, T> m = glm::max(q, T(0));
  return std::sqrt(m.x * m.x + m.y * m.y + m.z * m.z) + std::min(std::max(q.x, std::max(q.y, q.z)), T(0));
}

template <class T>
T torus(glm::vec<3, T> p) {
  const T a = std::sqrt(p.x * p.x + p.z * p.z) - T(1);
  return std::sqrt(a * a + p.y * p.y) - T(0.25);
}

template <class T>
class EvaluateTyped : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(EvaluateTyped, Scalars);

TYPED_TEST(EvaluateTyped, KnownPointsOfClassicSdfs) {
  using T = TypeParam;
  using V = glm::vec<3, T>;
  EXPECT_EQ(sdfAt<T>(kSphere, V(3, 4, 0)), T(3.5));
  EXPECT_EQ(sdfAt<T>(kSphere, V(0, 0, 0)), T(-1.5));
  EXPECT_EQ(sdfAt<T>(kBox, V(3, 0, 0)), T(2));
  EXPECT_EQ(sdfAt<T>(kBox, V(0, 0, 0)), T(-0.5));
  EXPECT_EQ(sdfAt<T>(kBox, V(4, 4.5, 0)), T(5));
  EXPECT_EQ(sdfAt<T>(kTorus, V(1, 0, 0)), T(-0.25));
  EXPECT_EQ(sdfAt<T>(kTorus, V(0, 0, 3)), T(1.75));
  EXPECT_EQ(sdfAt<T>(kTorus, V(0, 0, 0)), T(0.75));
}

TYPED_TEST(EvaluateTyped, MatchesClosedFormsEverywhere) {
  using T = TypeParam;
  using V = glm::vec<3, T>;
  const SpaceFormula s = compileSdf(kSphere), b = compileSdf(kBox), t = compileSdf(kTorus);
  std::mt19937 rng(7);
  std::uniform_real_distribution<T> coordinate(-3, 3);
  for (int i = 0; i < 500; ++i) {
    const V p(coordinate(rng), coordinate(rng), coordinate(rng));
    // Same operations in the same order: the results are identical.
    EXPECT_EQ(testing::evaluateAt(s, p), sphere(p));
    EXPECT_EQ(testing::evaluateAt(b, p), box(p));
    EXPECT_EQ(testing::evaluateAt(t, p), torus(p));
  }
}

TYPED_TEST(EvaluateTyped, GuardsForUndefinedGlslCases) {
  using T = TypeParam;
  const glm::vec<3, T> o(0, 0, 0);
  const T tiny = T(FLT_MIN);
  EXPECT_EQ(sdfAt<T>("sqrt(-1)", o), T(0));
  EXPECT_EQ(sdfAt<T>("log(-1)", o), std::log(tiny));
  EXPECT_EQ(sdfAt<T>("log(x)", o), std::log(tiny));
  // in float, pow is the shared library's exp(y log x) (sdf/glsl/transcendental.glsl), here 1.5e-6 off
  EXPECT_NEAR(sdfAt<T>("pow(-2, 0.5)", o), std::pow(tiny, T(0.5)), 1e-5 * std::pow(tiny, T(0.5)));
  EXPECT_EQ(sdfAt<T>("x ^ 0.5", glm::vec<3, T>(4, 0, 0)), T(2));
  EXPECT_EQ(sdfAt<T>("mod(5, x)", o), T(5));
  EXPECT_EQ(sdfAt<T>("mod(-1, 3)", o), T(2));
  EXPECT_EQ(sdfAt<T>("mod(7, -3)", o), T(-2));
  EXPECT_EQ(sdfAt<T>("normalize(p).x", o), T(0));
  EXPECT_EQ(sdfAt<T>("normalize(vec3(3, 0, 4)).z", o), T(0.8));
  EXPECT_EQ(sdfAt<T>("smoothstep(1, 1, 0.5)", o), T(0));
  EXPECT_EQ(sdfAt<T>("smoothstep(1, 1, 1)", o), T(1));
  EXPECT_EQ(sdfAt<T>("smoothstep(x, x, 1)", o), T(1));
  EXPECT_EQ(sdfAt<T>("smoothstep(0, 2, 1)", o), T(0.5));
  EXPECT_EQ(sdfAt<T>("smoothstep(0, 2, 5)", o), T(1));
  EXPECT_EQ(sdfAt<T>("clamp(5, 2, 1)", o), T(1));  // reversed bounds: min(max(x, low), high)
  EXPECT_EQ(sdfAt<T>("clamp(-5, 2, 3)", o), T(2));
}

TYPED_TEST(EvaluateTyped, GlslFunctions) {
  using T = TypeParam;
  const glm::vec<3, T> p(-0.25, 2, 3);
  EXPECT_EQ(sdfAt<T>("fract(x)", p), T(0.75));
  EXPECT_EQ(sdfAt<T>("floor(x)", p), T(-1));
  EXPECT_EQ(sdfAt<T>("sign(x) + 10 * sign(0)", p), T(-1));
  EXPECT_EQ(sdfAt<T>("mix(1, 3, 0.25)", p), T(1.5));
  EXPECT_EQ(sdfAt<T>("step(1, 0.5) + step(1, 1)", p), T(1));
  EXPECT_EQ(sdfAt<T>("distance(p, vec3(-0.25, 5, 7))", p), T(5));
  EXPECT_EQ(sdfAt<T>("exp(0) + cos(0) + sin(0) + tan(0)", p), T(2));
  EXPECT_EQ(sdfAt<T>("abs(x) * 4", p), T(1));
  EXPECT_EQ(sdfAt<T>("max(y, z) - min(y, z)", p), T(1));
  EXPECT_NEAR(sdfAt<T>("sin(z) + cos(y) + tan(x) + exp(x) + log(z)", p),
              std::sin(T(3)) + std::cos(T(2)) + std::tan(T(-0.25)) + std::exp(T(-0.25)) + std::log(T(3)),
              T(1e-5));
}

TYPED_TEST(EvaluateTyped, IntegerPowersExpandToMultiplications) {
  using T = TypeParam;
  const glm::vec<3, T> p(-2, 3, 0);
  EXPECT_EQ(sdfAt<T>("x ^ 3", p), T(-8));  // GLSL pow would be undefined here
  EXPECT_EQ(sdfAt<T>("pow(x, 3.0)", p), T(-8));
  EXPECT_EQ(sdfAt<T>("x ^ -2", p), T(0.25));
  EXPECT_EQ(sdfAt<T>("x ^ 0", p), T(1));
  EXPECT_EQ(sdfAt<T>("y ^ 5", p), T(243));
}

TEST(Evaluate, PowerExpansionShape) {
  // x^3 = (x*x)*x and x^4 = (x*x)*(x*x): the order both backends evaluate in.
  const SpaceFormula cube = compileSdf("x ^ 3");
  const Node& outer = cube.graph.node(cube.value);
  ASSERT_EQ(outer.op, Op::Mul);
  EXPECT_EQ(cube.graph.node(outer.args[0]).op, Op::Mul);
  EXPECT_EQ(cube.graph.node(outer.args[1]).op, Op::Variable);
  const SpaceFormula fourth = compileSdf("x ^ 4");
  const Node& square = fourth.graph.node(fourth.value);
  ASSERT_EQ(square.op, Op::Mul);
  EXPECT_EQ(square.args[0], square.args[1]);
}

TEST(Evaluate, ConstantsAreCorrectlyRounded) {
  // mpq_get_d truncates; the graph rounds to nearest.
  const std::vector<std::pair<const char*, double>> cases = {
      {"0.1", 0.1}, {"0.7", 0.7}, {"1e-300", 1e-300}, {"2.2250738585072014e-308", 2.2250738585072014e-308},
      {"1.7976931348623157e308", 1.7976931348623157e308}, {"-3.14159265358979323846", -3.14159265358979323846},
      {"1/3", 1.0 / 3.0}, {"9007199254740993", 9007199254740992.0}, {"9007199254740995", 9007199254740996.0}};
  for (const auto& [text, expected] : cases) {
    EXPECT_EQ(sdfAt<double>(text, {0, 0, 0}), expected) << text;
  }
  // Random decimals with up to 19 significant digits against strtod, which rounds correctly.
  std::mt19937_64 rng(3);
  for (int i = 0; i < 2000; ++i) {
    char text[64];
    std::snprintf(text, sizeof text, "%llu.%llue%d", static_cast<unsigned long long>(rng() % 100000000000ull),
                  static_cast<unsigned long long>(rng() % 100000000ull), static_cast<int>(rng() % 600) - 300);
    EXPECT_EQ(nearestDouble(testing::constantValue(text)), std::strtod(text, nullptr)) << text;
  }
}

}  // namespace
}  // namespace sdfwb::expr
