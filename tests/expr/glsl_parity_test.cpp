// The emitted GLSL against the CPU float evaluator on llvmpipe, on the same
// points: bit-identical for formulas using any built-in (sin, cos, tan, exp,
// log and pow come from the shared library's sdf/glsl/transcendental.glsl in
// both, the rest are built-ins llvmpipe computes exactly). The output is
// declared invariant, as glsl.h requires for bit-exact results: otherwise
// Mesa refactors x*y + x*x into x*(y + x) and rounds differently.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "expr/glsl.h"
#include "formula_eval.h"
#include "gl_test_support.h"
#include "glcontext/fragment_evaluator.h"
#include "expr/builtins.h"
#include "sdf/glsl_sources.h"

namespace sdfwb::expr {
namespace {

using GlslParity = sdfwb::test::GlTest;

struct Comparison {
  int mismatches = 0;      // results that differ at all
  double worstRelative = 0;  // max |gpu - cpu| / max(1, |cpu|)
};

Comparison compare(const glcontext::GlFunctions& gl, std::string_view source, const std::vector<float>& xyzw) {
  SpaceFormula f = compileSdf(source);
  const auto g = gradient(f.graph, f.value);
  const NodeId outputs[] = {f.value, g[0], g[1], g[2]};
  const Tape tape(f.graph, outputs);
  const std::string shader = std::string(sdf::glslPrelude()) + std::string(sdf::glslLibrary()) +
                             "invariant evalResult;\nuniform samplerBuffer points;\n" +
                             emitGlslFunction(tape, {"sdUser", "vec3 p", {"p.x", "p.y", "p.z"}}) +
                             "void main() { evalResult = sdUser(texelFetch(points, evalIndex()).xyz); }\n";
  const glcontext::FragmentEvaluator evaluator(gl, shader);

  const int count = static_cast<int>(xyzw.size() / 4);
  glcontext::EvaluatorInput points{"points", 4, glcontext::InputLayout::Buffer, xyzw};
  const std::vector<float> gpu = evaluator.evaluate(gl, count, 1, std::vector{points});

  Comparison result;
  Evaluator<float> cpu(tape);
  for (int i = 0; i < count; ++i) {
    const auto expected = cpu(std::span<const float>(&points.values[static_cast<std::size_t>(i) * 4], 3));
    for (int k = 0; k < 4; ++k) {
      const float actual = gpu[static_cast<std::size_t>(i) * 4 + k];
      if (actual == expected[k] || (std::isnan(actual) && std::isnan(expected[k]))) continue;
      ++result.mismatches;
      result.worstRelative = std::max(result.worstRelative, std::abs(double(actual) - expected[k]) / std::max(1.0, std::abs(double(expected[k]))));
    }
  }
  return result;
}

std::vector<float> randomPoints(int count) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> coordinate(-3, 3);
  std::vector<float> xyzw;
  for (int i = 0; i < count; ++i) xyzw.insert(xyzw.end(), {coordinate(rng), coordinate(rng), coordinate(rng), 0});
  return xyzw;
}

Comparison compare(const glcontext::GlFunctions& gl, std::string_view source, int count) {
  return compare(gl, source, randomPoints(count));
}

TEST_F(GlslParity, ExactBuiltinsAgreeBitForBit) {
  for (const char* source : {
           "length(p) - 1.5",
           "let q = abs(p) - vec3(1, 0.5, 2); length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0)",
           "length(vec2(length(p.xz) - 1.0, p.y)) - 0.25",
           "x^3 - 0.1*y^2*z + x/(y*y + 1) - 2",
           "x*y + x*x - z*(x + z)",
           "mod(x, 0.7) + fract(y*3) + clamp(z, -0.5, 0.5) + sign(x*y) + step(0.2, z)",
           "let d = normalize(p); dot(d, vec3(0.3, 0.5, 0.1)) + mix(x, y, 0.25) + smoothstep(-1, 2, z)",
       }) {
    const Comparison c = compare(gl(), source, 2048);
    EXPECT_EQ(c.mismatches, 0) << source << " (worst relative difference " << c.worstRelative << ")";
  }
}

// One formula per built-in of builtins(), each bit for bit; a built-in added
// to the language without a case here fails.
TEST_F(GlslParity, EveryBuiltinAgreesBitForBit) {
  const std::map<std::string_view, const char*> uses = {
      {"sin", "sin(x*7) * y + sin(z*100)"},
      {"cos", "cos(y*5 - 1) + cos(x*300)*z"},
      {"tan", "tan(x*0.5) + tan(z)*0.01"},
      {"exp", "exp(x*y) - exp(-z*z*20)"},
      {"log", "log(x*x + 0.001) + log(abs(y*z))"},
      {"sqrt", "sqrt(abs(x)) - sqrt(y)"},
      {"abs", "abs(x) - abs(y*z)"},
      {"sign", "sign(x) * y + sign(z)"},
      {"floor", "floor(x*3) + floor(-y)"},
      {"fract", "fract(x*3) + fract(-y)"},
      {"min", "min(x, y) + min(z, 0.1)"},
      {"max", "max(x, y) + max(z, 0.1)"},
      {"clamp", "clamp(x, -0.5, 0.5) + clamp(y, z, 1)"},
      {"mix", "mix(x, y, z)"},
      {"step", "step(0.2, x) + step(y, z)"},
      {"smoothstep", "smoothstep(-1, 1, x) + smoothstep(y, z, 0.5)"},
      {"pow", "pow(abs(x), y) + pow(abs(z) + 1, 1.5)"},
      {"mod", "mod(x, 0.7) + mod(y, z)"},
      {"length", "length(p) - 1 + length(p.xz)"},
      {"distance", "distance(p, vec3(1, 0, 0.5)) - 1"},
      {"dot", "dot(p, vec3(0.3, -0.5, 0.1))"},
      {"cross", "dot(cross(p, vec3(0, 1, 0)), vec3(1, 2, 3))"},
      {"normalize", "dot(normalize(p), vec3(0.6, 0.8, 0))"},
      {"vec2", "length(vec2(x, z)) - y"},
      {"vec3", "length(vec3(x, y*2, z)) - 1"},
  };
  for (const Builtin& builtin : builtins()) {
    EXPECT_TRUE(uses.count(builtin.name)) << builtin.name << " has no parity case";
  }
  for (const auto& [name, source] : uses) {
    const Comparison c = compare(gl(), source, 2048);
    EXPECT_EQ(c.mismatches, 0) << name << ": " << source << " (worst relative difference " << c.worstRelative << ")";
  }
}

// A NaN (0/0 in a formula, say) reaching min, max or clamp: GLSL leaves the
// result undefined; both evaluators give the same one.
TEST_F(GlslParity, NanOperandsOfMinMaxAgree) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> points = {nan, 1, -2, 0, 1, nan, 2, 0, nan, nan, 0.5f, 0};
  for (const char* source : {"min(x, y)", "min(y, x)", "max(x, y)", "max(y, x)", "clamp(x, -1, 1)",
                             "clamp(z, x, y)", "min(x, z) + max(z, y)", "step(x, z) + step(z, x)", "abs(x) + sign(y)"}) {
    const Comparison c = compare(gl(), source, points);
    EXPECT_EQ(c.mismatches, 0) << source;
  }
}

}  // namespace
}  // namespace sdfwb::expr
