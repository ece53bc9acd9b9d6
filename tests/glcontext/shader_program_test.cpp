// Shader build failures come back with the line of the offending source.
#include "glcontext/shader_program.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <regex>

#include "gl_test_support.h"
#include "glcontext/fragment_evaluator.h"
#include "glcontext/gl_error.h"

using sdfwb::glcontext::buildProgram;
using sdfwb::glcontext::FragmentEvaluator;
using sdfwb::glcontext::GlError;
using sdfwb::glcontext::ProgramBuild;
using sdfwb::glcontext::ShaderSource;
using ::testing::HasSubstr;

namespace {

using ShaderProgramTest = sdfwb::test::GlTest;

constexpr const char* kVertex =
    "#version 330 core\n"
    "void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n";

ProgramBuild build(const sdfwb::glcontext::GlFunctions& gl, const char* fragment) {
  const std::array<ShaderSource, 2> stages = {{{GL_VERTEX_SHADER, kVertex}, {GL_FRAGMENT_SHADER, fragment}}};
  return buildProgram(gl, stages, "test");
}

TEST_F(ShaderProgramTest, CompileErrorNamesTheLineAndEchoesIt) {
  ProgramBuild result = build(gl(),
                              "#version 330 core\n"
                              "out vec4 color;\n"
                              "float twice(float x) { return 2.0 * x; }\n"
                              "void main() {\n"
                              "    color = vec4(twice(undefinedThing));\n"
                              "}\n");
  std::cout << result.report;
  EXPECT_FALSE(result.ok());
  ASSERT_FALSE(result.diagnostics.empty());
  EXPECT_EQ(result.diagnostics[0].line, 5);
  EXPECT_EQ(result.diagnostics[0].stage, static_cast<GLenum>(GL_FRAGMENT_SHADER));
  EXPECT_THAT(result.report, HasSubstr("test fragment shader:5:"));
  EXPECT_THAT(result.report, HasSubstr("undefinedThing' undeclared"));
  EXPECT_THAT(result.report, HasSubstr("    5 |     color = vec4(twice(undefinedThing));\n"));
  EXPECT_THAT(result.report, HasSubstr("test: the fragment shader did not compile"));
}

TEST_F(ShaderProgramTest, LinkErrorIsReportedWithoutALine) {
  // Declared, called, never defined: only the linker can tell.
  ProgramBuild result = build(gl(),
                              "#version 330 core\n"
                              "out vec4 color;\n"
                              "float helper(float x);\n"
                              "void main() { color = vec4(helper(1.0)); }\n");
  std::cout << result.report;
  EXPECT_FALSE(result.ok());
  EXPECT_THAT(result.report, HasSubstr("test link: "));
  EXPECT_THAT(result.report, HasSubstr("test: the program did not link"));
}

TEST_F(ShaderProgramTest, WarningsOfASuccessfulBuildAreKept) {
  ProgramBuild result = build(gl(),
                              "#version 330 core\n"
                              "out vec4 color;\n"
                              "void main() {\n"
                              "  float unset;\n"
                              "  color = vec4(unset);\n"
                              "}\n");
  EXPECT_TRUE(result.ok());
  EXPECT_THAT(result.report, HasSubstr("warning"));
  EXPECT_THAT(result.report, HasSubstr("    5 |   color = vec4(unset);"));
}

TEST_F(ShaderProgramTest, EvaluatorErrorLinesCountLinesOfItsGeneratedSource) {
  const char* source =
      "void main() {\n"
      "  evalResult = vec4(notDeclaredHere);\n"
      "}\n";
  try {
    FragmentEvaluator evaluator(gl(), source);
    FAIL() << "bad shader accepted";
  } catch (const GlError& error) {
    std::string report = error.what();
    std::smatch match;
    ASSERT_TRUE(std::regex_search(report, match, std::regex("fragment shader:([0-9]+):")));
    int line = std::stoi(match[1]);
    // The prelude comes first, so the line is the user's second line shifted by its length.
    std::string prelude(FragmentEvaluator::prelude());
    int preludeLines = static_cast<int>(std::count(prelude.begin(), prelude.end(), '\n'));
    EXPECT_EQ(line, preludeLines + 2);
    EXPECT_THAT(report, HasSubstr("|   evalResult = vec4(notDeclaredHere);"));
  }
}

}  // namespace
