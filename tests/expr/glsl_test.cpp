// GLSL generation: golden text for a few formulas and exact float literals.

#include <gtest/gtest.h>

#include <cfloat>
#include <cstdlib>
#include <random>

#include "expr/glsl.h"
#include "formula_eval.h"

namespace sdfwb::expr {
namespace {

std::string valueAndGradient(std::string_view source) {
  SpaceFormula f = compileSdf(source);
  const auto g = gradient(f.graph, f.value);
  const NodeId outputs[] = {f.value, g[0], g[1], g[2]};
  return emitGlslFunction(Tape(f.graph, outputs), {"sdUser", "vec3 p", {"p.x", "p.y", "p.z"}});
}

std::string valueOnly(std::string_view source) {
  SpaceFormula f = compileSdf(source);
  const NodeId outputs[] = {f.value};
  return emitGlslFunction(Tape(f.graph, outputs), {"sdUser", "vec3 p", {"p.x", "p.y", "p.z"}});
}

TEST(Glsl, SphereWithGradient) {
  EXPECT_EQ(valueAndGradient("length(p) - 1"), R"(vec4 sdUser(vec3 p) {
  float t0 = p.x * p.x;
  float t1 = p.y * p.y;
  float t2 = t0 + t1;
  float t3 = p.z * p.z;
  float t4 = t2 + t3;
  float t5 = max(t4, 0.0);
  float t6 = sqrt(t5);
  float t7 = t6 - 1.0;
  float t8 = p.x + p.x;
  float t9 = t4 < 0.0 ? 0.0 : t8;
  float t10 = max(t6, 1.17549435e-38);
  float t11 = 2.0 * t10;
  float t12 = t9 / t11;
  float t13 = p.y + p.y;
  float t14 = t4 < 0.0 ? 0.0 : t13;
  float t15 = t14 / t11;
  float t16 = p.z + p.z;
  float t17 = t4 < 0.0 ? 0.0 : t16;
  float t18 = t17 / t11;
  return vec4(t7, t12, t15, t18);
}
)");
}

TEST(Glsl, BoxValue) {
  EXPECT_EQ(valueOnly("let q = abs(p) - vec3(1, 0.5, 2); length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0)"),
            R"(float sdUser(vec3 p) {
  float t0 = abs(p.x);
  float t1 = abs(p.y);
  float t2 = abs(p.z);
  float t3 = t0 - 1.0;
  float t4 = t1 - 0.5;
  float t5 = t2 - 2.0;
  float t6 = max(t3, 0.0);
  float t7 = max(t4, 0.0);
  float t8 = max(t5, 0.0);
  float t9 = t6 * t6;
  float t10 = t7 * t7;
  float t11 = t9 + t10;
  float t12 = t8 * t8;
  float t13 = t11 + t12;
  float t14 = max(t13, 0.0);
  float t15 = sqrt(t14);
  float t16 = max(t4, t5);
  float t17 = max(t3, t16);
  float t18 = min(t17, 0.0);
  float t19 = t15 + t18;
  return t19;
}
)");
}

TEST(Glsl, GuardsAndPowers) {
  EXPECT_EQ(valueOnly("sqrt(x) + log(y) + pow(z, 0.1) + mod(x, y) - y^3 + 0.1"), R"(float sdUser(vec3 p) {
  float t0 = max(p.x, 0.0);
  float t1 = sqrt(t0);
  float t2 = max(p.y, 1.17549435e-38);
  float t3 = formulaLog(t2);
  float t4 = t1 + t3;
  float t5 = max(p.z, 1.17549435e-38);
  float t6 = formulaPow(t5, 0.100000001);
  float t7 = t4 + t6;
  float t8 = p.x / p.y;
  float t9 = floor(t8);
  float t10 = p.y * t9;
  float t11 = p.x - t10;
  float t12 = p.y == 0.0 ? p.x : t11;
  float t13 = t7 + t12;
  float t14 = p.y * p.y;
  float t15 = t14 * p.y;
  float t16 = t13 - t15;
  float t17 = t16 + 0.100000001;
  return t17;
}
)");
}

TEST(Glsl, FloatLiterals) {
  EXPECT_EQ(glslFloatLiteral(1), "1.0");
  EXPECT_EQ(glslFloatLiteral(-2), "(-2.0)");
  EXPECT_EQ(glslFloatLiteral(0.1), "0.100000001");
  EXPECT_EQ(glslFloatLiteral(1e20), "1.00000002e+20");
  EXPECT_EQ(glslFloatLiteral(FLT_MIN), "1.17549435e-38");
  EXPECT_EQ(glslFloatLiteral(1e300), "uintBitsToFloat(0x7f800000u)");
  // Every literal reads back as the float the C++ evaluator uses.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> mantissa(-10, 10);
  for (int i = 0; i < 10000; ++i) {
    const double v = std::ldexp(mantissa(rng), static_cast<int>(rng() % 200) - 100);
    std::string text = glslFloatLiteral(v);
    if (text.front() == '(') text = text.substr(1, text.size() - 2);
    EXPECT_EQ(std::strtof(text.c_str(), nullptr), static_cast<float>(v)) << text;
  }
}

}  // namespace
}  // namespace sdfwb::expr
