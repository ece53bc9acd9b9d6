// The emitted GLSL against the CPU float evaluator on llvmpipe, on the same
// points: bit-identical for formulas made of + - * / sqrt abs floor min max
// and selects (the built-ins llvmpipe computes exactly), within a few ulps
// where llvmpipe approximates (sin, cos, exp, log, pow). The output is
// declared invariant, as glsl.h requires for bit-exact results: otherwise
// Mesa refactors x*y + x*x into x*(y + x) and rounds differently.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "expr/glsl.h"
#include "formula_eval.h"
#include "gl_test_support.h"
#include "glcontext/fragment_evaluator.h"

namespace sdfwb::expr {
namespace {

using GlslParity = sdfwb::test::GlTest;

struct Comparison {
  int mismatches = 0;      // results that differ at all
  double worstRelative = 0;  // max |gpu - cpu| / max(1, |cpu|)
};

Comparison compare(const glcontext::GlFunctions& gl, std::string_view source, int count) {
  SpaceFormula f = compileSdf(source);
  const auto g = gradient(f.graph, f.value);
  const NodeId outputs[] = {f.value, g[0], g[1], g[2]};
  const Tape tape(f.graph, outputs);
  const std::string shader = "invariant evalResult;\nuniform samplerBuffer points;\n" +
                             emitGlslFunction(tape, {"sdUser", "vec3 p", {"p.x", "p.y", "p.z"}}) +
                             "void main() { evalResult = sdUser(texelFetch(points, evalIndex()).xyz); }\n";
  const glcontext::FragmentEvaluator evaluator(gl, shader);

  std::mt19937 rng(23);
  std::uniform_real_distribution<float> coordinate(-3, 3);
  glcontext::EvaluatorInput points{"points", 4, glcontext::InputLayout::Buffer, {}};
  for (int i = 0; i < count; ++i) points.values.insert(points.values.end(), {coordinate(rng), coordinate(rng), coordinate(rng), 0});
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

TEST_F(GlslParity, ApproximateBuiltinsAgreeClosely) {
  for (const char* source : {
           "sin(x*2) * cos(y) + exp(z/4) - log(x*x + 1)",
           "pow(abs(x) + 0.5, 1.5) + tan(y/3) + sqrt(abs(z))",
       }) {
    const Comparison c = compare(gl(), source, 2048);
    EXPECT_LT(c.worstRelative, 1e-5) << source << " (" << c.mismatches << " results differ)";
  }
}

}  // namespace
}  // namespace sdfwb::expr
