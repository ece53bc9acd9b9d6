#include "glcontext/fragment_evaluator.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <vector>

#include "gl_test_support.h"
#include "glcontext/gl_error.h"

using sdfwb::glcontext::EvaluatorInput;
using sdfwb::glcontext::FragmentEvaluator;
using sdfwb::glcontext::GlError;
using sdfwb::glcontext::InputLayout;
using ::testing::HasSubstr;

namespace {

using FragmentEvaluatorTest = sdfwb::test::GlTest;

std::string evaluationError(const FragmentEvaluator& evaluator, const sdfwb::glcontext::GlFunctions& gl,
                            int width, int height, const std::vector<EvaluatorInput>& inputs) {
  try {
    evaluator.evaluate(gl, width, height, inputs);
  } catch (const GlError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST_F(FragmentEvaluatorTest, EachPixelSeesItsCoordinatesAndIndex) {
  FragmentEvaluator evaluator(gl(), "void main() { evalResult = vec4(evalPixel(), evalIndex(), 0.25); }\n");
  const int width = 7, height = 5;
  std::vector<float> out = evaluator.evaluate(gl(), width, height);
  ASSERT_EQ(out.size(), std::size_t{width * height * 4});
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float* pixel = &out[static_cast<std::size_t>((y * width + x) * 4)];
      EXPECT_EQ(pixel[0], x);
      EXPECT_EQ(pixel[1], y);
      EXPECT_EQ(pixel[2], y * width + x);
      EXPECT_EQ(pixel[3], 0.25f);
    }
  }
}

TEST_F(FragmentEvaluatorTest, BufferInputOfEveryWidthReachesTheShader) {
  FragmentEvaluator evaluator(gl(),
                              "uniform samplerBuffer scalars;\n"
                              "uniform samplerBuffer pairs;\n"
                              "uniform samplerBuffer quads;\n"
                              "void main() {\n"
                              "  int i = evalIndex();\n"
                              "  evalResult = vec4(texelFetch(scalars, i).x, texelFetch(pairs, i).xy,\n"
                              "                    dot(texelFetch(quads, i), vec4(1.0)));\n"
                              "}\n");
  const int count = 12;
  EvaluatorInput scalars{"scalars", 1, InputLayout::Buffer, {}};
  EvaluatorInput pairs{"pairs", 2, InputLayout::Buffer, {}};
  EvaluatorInput quads{"quads", 4, InputLayout::Buffer, {}};
  for (int i = 0; i < count; ++i) {
    scalars.values.push_back(0.5f * i);
    pairs.values.insert(pairs.values.end(), {-1.0f * i, 100.0f + i});
    quads.values.insert(quads.values.end(), {1.0f, 2.0f, 4.0f, 8.0f * i});
  }
  std::vector<float> out = evaluator.evaluate(gl(), count, 1, std::vector{scalars, pairs, quads});
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(out[i * 4 + 0], 0.5f * i);
    EXPECT_EQ(out[i * 4 + 1], -1.0f * i);
    EXPECT_EQ(out[i * 4 + 2], 100.0f + i);
    EXPECT_EQ(out[i * 4 + 3], 7.0f + 8.0f * i);
  }
}

TEST_F(FragmentEvaluatorTest, PerPixelInputMatchesOutputPixels) {
  FragmentEvaluator evaluator(gl(),
                              "uniform sampler2D image;\n"
                              "void main() { evalResult = texelFetch(image, evalPixel(), 0) * 2.0; }\n");
  const int width = 3, height = 4;
  EvaluatorInput image{"image", 4, InputLayout::PerPixel, {}};
  for (int i = 0; i < width * height * 4; ++i) image.values.push_back(static_cast<float>(i));
  std::vector<float> out = evaluator.evaluate(gl(), width, height, std::vector{image});
  for (int i = 0; i < width * height * 4; ++i) EXPECT_EQ(out[i], 2.0f * i) << i;
}

TEST_F(FragmentEvaluatorTest, OddWidthSingleComponentPerPixelInputIsNotSkewed) {
  FragmentEvaluator evaluator(gl(),
                              "uniform sampler2D image;\n"
                              "void main() { evalResult = vec4(texelFetch(image, evalPixel(), 0).x); }\n");
  const int width = 5, height = 3;
  gl().PixelStorei(GL_UNPACK_ALIGNMENT, 8);  // a hostile leftover from other code
  EvaluatorInput image{"image", 1, InputLayout::PerPixel, {}};
  for (int i = 0; i < width * height; ++i) image.values.push_back(static_cast<float>(i));
  std::vector<float> out = evaluator.evaluate(gl(), width, height, std::vector{image});
  for (int i = 0; i < width * height; ++i) EXPECT_EQ(out[i * 4], static_cast<float>(i)) << i;
}

TEST_F(FragmentEvaluatorTest, FloatsPassThroughBitForBitExceptDenormals) {
  // Read and write back, and once through arithmetic (a uniform 1.0, so the
  // compiler cannot fold it): the target keeps every bit of a normal float.
  FragmentEvaluator evaluator(gl(),
                              "uniform samplerBuffer values;\n"
                              "uniform float one;\n"
                              "void main() {\n"
                              "  float v = texelFetch(values, evalIndex()).x;\n"
                              "  evalResult = vec4(v, v * one, 0.0, 0.0);\n"
                              "}\n");
  gl().UseProgram(evaluator.program());
  gl().Uniform1f(gl().GetUniformLocation(evaluator.program(), "one"), 1.0f);
  const float denormal = std::numeric_limits<float>::denorm_min() * 1000.0f;
  const std::vector<float> normals = {0.0f, -0.0f, 1.0f, -2.5f, 3.14159274f, 1e30f, -1e-30f,
                                      std::numeric_limits<float>::min(), std::numeric_limits<float>::max(),
                                      16777217.0f, std::nextafter(1.0f, 2.0f)};
  EvaluatorInput input{"values", 1, InputLayout::Buffer, {}};
  input.values.reserve(normals.size() + 1);
  input.values.assign(normals.begin(), normals.end());
  input.values.push_back(denormal);
  std::vector<float> out = evaluator.evaluate(gl(), static_cast<int>(input.values.size()), 1, std::vector{input});
  for (std::size_t i = 0; i < normals.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(out[i * 4 + 0]), std::bit_cast<std::uint32_t>(normals[i])) << normals[i];
    EXPECT_EQ(std::bit_cast<std::uint32_t>(out[i * 4 + 1]), std::bit_cast<std::uint32_t>(normals[i])) << normals[i];
  }
  // llvmpipe flushes denormals to zero in arithmetic (TOOLCHAIN.md).
  const std::size_t last = normals.size() * 4;
  std::cout << "denormal " << denormal << " read back as " << out[last] << ", times 1.0: " << out[last + 1] << "\n";
  EXPECT_EQ(out[last + 1], 0.0f);
}

TEST_F(FragmentEvaluatorTest, UniformsSetOnTheProgramPersist) {
  FragmentEvaluator evaluator(gl(), "uniform vec4 value;\nvoid main() { evalResult = value; }\n");
  gl().UseProgram(evaluator.program());
  gl().Uniform4f(gl().GetUniformLocation(evaluator.program(), "value"), 1.0f, 2.0f, 3.0f, 4.0f);
  gl().UseProgram(0);
  std::vector<float> out = evaluator.evaluate(gl(), 2, 2);
  for (int i = 0; i < 4; ++i) EXPECT_THAT(std::vector<float>(out.begin() + i * 4, out.begin() + i * 4 + 4),
                                          ::testing::ElementsAre(1.0f, 2.0f, 3.0f, 4.0f));
}

TEST_F(FragmentEvaluatorTest, LeavesBindingsAtZero) {
  FragmentEvaluator evaluator(gl(),
                              "uniform samplerBuffer values;\n"
                              "void main() { evalResult = texelFetch(values, evalIndex()); }\n");
  evaluator.evaluate(gl(), 1, 1, std::vector{EvaluatorInput{"values", 4, InputLayout::Buffer, {1, 2, 3, 4}}});
  for (GLenum binding : {GL_FRAMEBUFFER_BINDING, GL_CURRENT_PROGRAM, GL_VERTEX_ARRAY_BINDING,
                         GL_TEXTURE_BINDING_BUFFER, GL_TEXTURE_BINDING_2D}) {
    GLint value = -1;
    gl().GetIntegerv(binding, &value);
    EXPECT_EQ(value, 0) << std::hex << binding;
  }
}

TEST_F(FragmentEvaluatorTest, InputMistakesAreNamed) {
  FragmentEvaluator evaluator(gl(),
                              "uniform samplerBuffer points;\n"
                              "void main() { evalResult = texelFetch(points, evalIndex()); }\n");
  EXPECT_THAT(evaluationError(evaluator, gl(), 1, 1, {{"pionts", 4, InputLayout::Buffer, {1, 2, 3, 4}}}),
              HasSubstr("input 'pionts': the shader has no active uniform of that name"));
  EXPECT_THAT(evaluationError(evaluator, gl(), 1, 1, {{"points", 4, InputLayout::PerPixel, {1, 2, 3, 4}}}),
              HasSubstr("a PerPixel input needs `uniform sampler2D points;`"));
  EXPECT_THAT(evaluationError(evaluator, gl(), 1, 1, {{"points", 3, InputLayout::Buffer, {1, 2, 3}}}),
              HasSubstr("3 components per texel; use 1, 2 or 4"));
  EXPECT_THAT(evaluationError(evaluator, gl(), 1, 1, {{"points", 4, InputLayout::Buffer, {1, 2, 3}}}),
              HasSubstr("3 values is not a positive multiple of 4 components"));
  EXPECT_THAT(evaluationError(evaluator, gl(), 0, 5, {}), HasSubstr("output size 0x5 is outside 1.."));
  // After all those refusals the context is clean and still works.
  std::vector<float> out =
      evaluator.evaluate(gl(), 1, 1, std::vector{EvaluatorInput{"points", 4, InputLayout::Buffer, {1, 2, 3, 4}}});
  EXPECT_THAT(out, ::testing::ElementsAre(1.0f, 2.0f, 3.0f, 4.0f));
}

TEST_F(FragmentEvaluatorTest, PerPixelInputOfTheWrongSizeIsNamed) {
  FragmentEvaluator evaluator(gl(),
                              "uniform sampler2D image;\n"
                              "void main() { evalResult = texelFetch(image, evalPixel(), 0); }\n");
  EXPECT_THAT(evaluationError(evaluator, gl(), 2, 2, {{"image", 1, InputLayout::PerPixel, {1, 2, 3}}}),
              HasSubstr("a PerPixel input needs 2x2 texels, got 3"));
}

}  // namespace
